// A system file outside every permitted folder: refused at the #include, never read or echoed.
#version 3.7;
#include "/etc/passwd"
