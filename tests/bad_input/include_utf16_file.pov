// An included file in UTF-16 is not text the parser reads: an error at the #include, with a short excerpt.
#version 3.7;
#include "inc/utf16.inc"
