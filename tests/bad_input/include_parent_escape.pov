// A relative name that climbs out of the scene folder into the source tree.
// Run with --strict-reads: the source tree may lie below $HOME or /tmp, which Debian's povray.conf lets a scene read.
#version 3.7;
#include "../../CMakeLists.txt"
