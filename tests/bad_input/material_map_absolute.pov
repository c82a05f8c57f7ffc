// A material_map image by an absolute path outside the permitted folders.
#version 3.7;
plane { z, 1 texture { material_map { png "/etc/passwd" texture { pigment { rgb 1 } } } } }
