// A /proc file as a font.
#version 3.7;
text { ttf "/proc/cpuinfo" "abc" 1, 0 pigment { rgb 1 } }
