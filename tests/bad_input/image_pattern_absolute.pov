// An image_pattern file by an absolute path outside the permitted folders.
#version 3.7;
plane { z, 1 pigment { image_pattern { png "/etc/passwd" } color_map { [0 rgb 0] [1 rgb 1] } } }
