// The object pattern: inside a sphere, a box union and a transformed torus, as a pigment list, a pigment map
// entry, a normal list and a texture list under warps.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -9> look_at <0, 1, 0> angle 50 }
light_source { <-5, 8, -6> color rgb 1 }
#declare Ball = sphere { 0, 1.1 scale <1.2, 0.6, 1.2> }
#declare Bars = union { box { <-2, -0.1, -2>, <2, 0.1, 2> } box { <-0.1, -2, -2>, <0.1, 2, 2> } rotate 30*z }
plane { y, 0 pigment { object { Bars scale 1.5 color rgb <0.9, 0.9, 0.8>, color rgb <0.2, 0.3, 0.6> } } }
box { <-1, -1, -1>, <1, 1, 1>
      pigment { object { Ball pigment { rgb <0.9, 0.2, 0.1> }, pigment { checker rgb 1, rgb 0 scale 0.2 } } }
      rotate y*25 translate <-2.6, 1, 0> }
sphere { 0, 1
         pigment { rgb <0.8, 0.8, 0.3> } finish { phong 0.7 }
         normal { object { torus { 0.7, 0.2 rotate 90*x } normal { bumps 0.8 scale 0.1 }, normal { granite 0.3 } } }
         translate <0, 1, -1> }
box { <-1, -1, -1>, <1, 1, 1>
      texture { object { Bars texture { pigment { rgb 0.3 } finish { specular 0.6 } }
                                texture { pigment { rgb <0.2, 0.8, 0.3> } } }
                warp { cylindrical } scale 0.7 }
      rotate y*-30 translate <2.6, 1, 0.5> }
