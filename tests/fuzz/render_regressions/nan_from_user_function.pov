// A user function that is NaN everywhere drives a pigment; a light of 1e300: the image must stay finite.
#version 3.7;
global_settings { assumed_gamma 1 radiosity { count 20 recursion_limit 1 } }
#declare F = function(x, y, z) { sqrt(-1 - x * x) }
camera { location <0, 1, -4> look_at 0 }
light_source { <3, 5, -4> color rgb 1e300 }
sphere { 0, 1 pigment { function { F(x, y, z) } color_map { [0 rgb 0] [1 rgb 1] } } finish { reflection 0.5 } }
plane { y, -1 pigment { rgb <1e300, 0, 1> } }
