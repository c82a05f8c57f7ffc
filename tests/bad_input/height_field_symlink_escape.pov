// A height_field image through a link in the scene folder that leads outside it.
#version 3.7;
height_field { png "inc/escape.inc" }
