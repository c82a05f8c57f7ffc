// height_field from a POT file (a GIF whose two halves' palette indices are each height's high and low bytes):
// POV-Ray's mtmand.pot, plain and smooth.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -9> look_at <0, 0.4, 0> angle 52 }
light_source { <-6, 10, -5> color rgb 1 }
light_source { <5, 6, -8> color rgb 0.4 }
plane { y, -0.01 pigment { checker rgb 0.7, rgb 0.35 } }
height_field { pot "mtmand.pot" water_level 0.05
               pigment { rgb <0.9, 0.6, 0.3> } finish { phong 0.4 }
               translate <-0.5, 0, -0.5> scale <4, 1.5, 3> translate <-2.1, 0, 0.5> }
height_field { pot "mtmand.pot" smooth
               pigment { rgb <0.6, 0.8, 0.9> } finish { specular 0.5 }
               translate <-0.5, 0, -0.5> rotate y * 40 scale <3, 2, 3> translate <2.1, 0, -0.5> }
