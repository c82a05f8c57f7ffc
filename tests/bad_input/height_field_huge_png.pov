// A height_field PNG whose header claims 60000 x 60000 pixels in a 254-byte file.
#version 3.7;
height_field { png "inc/huge.png" }
