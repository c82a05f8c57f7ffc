// A device that never ends is outside the permitted folders.
#version 3.7;
#include "/dev/zero"
