// A font file named outside the permitted folders is refused before it is opened.
// Run with --strict-reads: the source tree may lie below $HOME or /tmp, which Debian's povray.conf lets a scene read.
#version 3.7;
text { ttf "../../CMakeLists.txt" "abc" 1, 0 pigment { rgb 1 } }
