// An orthographic camera looking down at an angle: parallel rays, the image plane sized by right and up.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <4, 6, -5> look_at <0, 0, 0> right 8*x up 6*y }
light_source { <-5, 8, -4> color rgb 1 }
plane { y, 0 pigment { checker rgb 0.9, rgb 0.3 } }
sphere { <0, 1, 0>, 1 pigment { rgb <0.9, 0.4, 0.2> } }
cone { <2, 0, 1>, 1, <2, 2, 1>, 0 pigment { rgb <0.3, 0.8, 0.4> } }
