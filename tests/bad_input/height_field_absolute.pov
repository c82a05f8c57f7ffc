// A height_field image by an absolute path outside the permitted folders.
#version 3.7;
height_field { png "/etc/passwd" }
