// A sor that claims two billion points and gives four.
#version 3.7;
sor { 2000000000, <0, 0>, <1, 0>, <1, 1>, <0, 2> }
