// A bump_map image by an absolute path outside the permitted folders.
#version 3.7;
plane { z, 1 pigment { rgb 1 } normal { bump_map { png "/etc/passwd" } } }
