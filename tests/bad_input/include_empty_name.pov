// An empty include name.
#version 3.7;
#include ""
