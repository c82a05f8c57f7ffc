// A font file named outside the permitted folders is refused before it is opened.
#version 3.7;
text { ttf "../../CMakeLists.txt" "abc" 1, 0 pigment { rgb 1 } }
