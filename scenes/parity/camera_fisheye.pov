// A fisheye camera: the view inside a circle, the angle from the axis proportional to the radius.
#version 3.7;
camera { fisheye location <0, 1.5, -0.5> look_at <0, 1, 3> angle 200 }
global_settings { assumed_gamma 1.0 }
light_source { <-5, 8, -4> color rgb 1 }
plane { y, 0 pigment { checker rgb 0.9, rgb 0.3 } }
sphere { <0, 1, 3>, 1 pigment { rgb <0.9, 0.4, 0.2> } }
sphere { <3, 1, 0>, 1 pigment { rgb <0.2, 0.5, 0.9> } }
sphere { <-3, 1, 0>, 1 pigment { rgb <0.3, 0.8, 0.4> } }
sphere { <0, 1, -3>, 1 pigment { rgb <0.9, 0.9, 0.2> } }
cone { <2, 0, 2>, 1, <2, 2.5, 2>, 0 pigment { rgb <0.8, 0.3, 0.8> } }
box { <-2.5, 0, 1.5>, <-1.5, 3, 2.5> pigment { rgb <0.4, 0.9, 0.9> } }
sky_sphere { pigment { gradient y color_map { [0 rgb <0.6, 0.7, 1.0>] [1 rgb <0.1, 0.2, 0.6>] } } }
