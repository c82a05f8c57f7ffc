// An image reached through a symbolic link that leads outside.
#version 3.7;
plane { z, 1 pigment { image_map { png "inc/escape.inc" } } }
