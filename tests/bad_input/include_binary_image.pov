// A PNG of the system include folder is readable but is not text: an error with a short escaped excerpt.
#version 3.7;
#include "Mount1.png"
