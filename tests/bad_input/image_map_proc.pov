// A /proc file as an image.
#version 3.7;
plane { z, 1 pigment { image_map { png "/proc/self/maps" } } }
