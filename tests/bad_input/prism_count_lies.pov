// A prism that claims two billion points and gives four.
#version 3.7;
prism { linear_spline 0, 1, 2000000000, <0, 0>, <1, 0>, <1, 1>, <0, 0> }
