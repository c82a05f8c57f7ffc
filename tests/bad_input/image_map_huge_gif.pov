// An image_map GIF whose screen claims 65535 x 65535 pixels in a 35-byte file.
#version 3.7;
plane { z, 1 pigment { image_map { gif "inc/huge.gif" } } }
