// inc/escape.inc is a symbolic link to /etc/passwd: its real location is outside, so it is refused.
#version 3.7;
#include "inc/escape.inc"
