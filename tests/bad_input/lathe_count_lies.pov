// A lathe that claims two billion points and gives three.
#version 3.7;
lathe { linear_spline 2000000000, <0, 0>, <1, 0>, <1, 1> }
