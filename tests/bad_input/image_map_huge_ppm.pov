// An image_map PPM whose header claims 60000 x 60000 pixels in a 31-byte file.
#version 3.7;
plane { z, 1 pigment { image_map { ppm "inc/huge.ppm" } } }
