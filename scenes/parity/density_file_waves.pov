// density_file (POV-Ray's spiral.df3) as a pigment without and with trilinear interpolation, as a normal, and
// as media density; ripples and waves with number_of_waves 3; #default normal.
#version 3.7;
global_settings { assumed_gamma 1.0 number_of_waves 3 }
#default { normal { bumps 0.2 scale 0.3 } }
camera { location <0, 2, -8> look_at <0, 1, 0> angle 50 }
light_source { <-5, 8, -6> color rgb 1 }
plane { y, 0 pigment { rgb 0.7 } normal { ripples 0.8 frequency 3 } }
box { <0, 0, 0.5>, <1, 1, 0.6>
      pigment { density_file df3 "spiral.df3" color_map { [0 rgb <0, 0, 0.3>] [1 rgb <1, 0.9, 0.4>] } }
      scale <2.4, 2.4, 1> translate <-3.4, 0.6, -0.5> }
box { <0, 0, 0.5>, <1, 1, 0.6>
      pigment { density_file df3 "spiral.df3" interpolate 1 color_map { [0 rgb 0] [1 rgb 1] } }
      scale <2.4, 2.4, 1> translate <-0.9, 0.6, -0.5> }
box { <0, 0, 0.5>, <1, 1, 0.6>
      pigment { rgb 0.9 } finish { phong 0.8 phong_size 60 }
      normal { density_file df3 "spiral.df3", 6 interpolate 1 }
      scale <2.4, 2.4, 1> translate <1.6, 0.6, -0.5> }
sphere { <0, 0, 0>, 0.8 pigment { rgb <0.8, 0.3, 0.2> } normal { waves 0.6 frequency 2 } translate <-1.5, 0.5, -3.2> }
sphere { <0, 0, 0>, 0.8 pigment { rgb <0.3, 0.5, 0.9> } translate <1.5, 0.5, -3.2> }
box { 0, 1 pigment { rgbt 1 } hollow
      interior { media { emission 4 intervals 1 samples 5 method 3
                 density { density_file df3 "spiral.df3" interpolate 1 color_map { [0 rgb 0] [1 rgb <1, 0.6, 0.3>] } } } }
      scale <2, 2, 0.4> translate <-1, 2.2, -1.5> }
