// A name built from pieces is checked as the file it names.
#version 3.7;
#declare D = "/et";
#include concat(D, "c/pass", "wd")
