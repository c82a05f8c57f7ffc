// A font given by an absolute path outside the include path.
#version 3.7;
text { ttf "/etc/hostname" "abc" 1, 0 pigment { rgb 1 } }
