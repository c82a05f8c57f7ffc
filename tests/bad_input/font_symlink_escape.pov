// A font reached through a symbolic link in the scene folder that leads outside.
#version 3.7;
text { ttf "inc/escape.inc" "abc" 1, 0 pigment { rgb 1 } }
