// An include of the corpus that itself names a system file: the refusal is at its #include, inside inc/.
#version 3.7;
#include "inc/reads_outside.inc"
