// height_field: a palette PNG (index * 256) flat with water_level, a float function smooth, a pigment function
// (16-bit RGB, POV-Ray's grey weights) clipped by a sphere, and a non-uniformly scaled smooth one.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -9> look_at <0, 0.4, 0> angle 52 }
light_source { <-6, 10, -5> color rgb 1 }
light_source { <5, 6, -8> color rgb 0.4 }
plane { y, -0.01 pigment { checker rgb 0.7, rgb 0.35 } }
height_field { png "plasma2.png" water_level 0.3
               pigment { rgb <0.9, 0.6, 0.3> } finish { phong 0.4 }
               translate <-0.5, 0, -0.5> scale <3, 1.2, 3> translate <-2, 0, 1.6> }
height_field { function 40, 30 { 0.5 + 0.4 * sin(x * 9) * cos(y * 7) } smooth
               pigment { rgb <0.4, 0.8, 0.5> } finish { specular 0.5 }
               translate <-0.5, 0, -0.5> scale <3, 1, 3> translate <2, 0, 1.6> }
height_field { function 60, 60 { pigment { bozo color_map { [0 rgb <0, 0.2, 1>] [1 rgb <1, 0.9, 0.2>] } scale 0.2 } }
               pigment { rgb <0.7, 0.7, 0.9> }
               clipped_by { sphere { <0.5, 0, 0.5>, 0.5 } }
               translate <-0.5, 0, -0.5> scale <3, 0.8, 3> translate <-1.7, 0, -1.8> }
height_field { function 25, 25 { 0.5 + 0.5 * sin(x * 6 + y * 3) } smooth water_level 0.2 hierarchy off
               pigment { rgb <0.9, 0.9, 0.9> } finish { phong 0.6 }
               translate <-0.5, 0, -0.5> rotate y * 30 scale <3.5, 0.6, 2> translate <1.8, 0, -1.6> }
