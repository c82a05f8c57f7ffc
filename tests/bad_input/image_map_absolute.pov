// image_map by an absolute path outside the permitted folders.
#version 3.7;
plane { z, 1 pigment { image_map { png "/etc/hostname" } } }
