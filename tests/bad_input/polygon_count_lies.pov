// A polygon that claims two billion points and gives four.
#version 3.7;
polygon { 2000000000, <0, 0>, <1, 0>, <1, 1>, <0, 0> }
