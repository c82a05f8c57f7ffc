// A relative name that climbs out of the scene folder into the source tree.
#version 3.7;
#include "../../CMakeLists.txt"
