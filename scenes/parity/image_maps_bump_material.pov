// bump_map (grey heights with interpolate 2 and once; palette indices with use_index), material_map (index
// picks, wrapping past the count), image_map filter and transmit per palette entry, and tiles.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -9> look_at <0, 1.2, 0> angle 50 }
light_source { <-5, 8, -6> color rgb 1 }
plane { y, 0 texture { tiles { texture { pigment { rgb 0.8 } } tile2 texture { pigment { rgb <0.3, 0.4, 0.5> } finish { phong 0.5 } } } scale 0.7 } }
box { <0, 0, 0>, <1, 1, 0.1>
      pigment { rgb 0.8 } finish { phong 0.6 phong_size 30 }
      normal { bump_map { png "bumpmap_.png" bump_size 4 interpolate 2 once } }
      scale <2.4, 1.5, 1> translate <-3.6, 1.8, 0.5> }
sphere { <0, 0, 0>, 1
         pigment { rgb <0.9, 0.8, 0.5> } finish { specular 0.5 }
         normal { bump_map { png "test.png" map_type 1 bump_size 0.3 use_index } }
         rotate y*30 translate <-2.2, 1, -1> }
box { <0, 0, 0>, <1, 1, 0.1>
      texture { material_map { png "povmap.png"
                  texture { pigment { rgb <0.2, 0.1, 0.9> } finish { phong 0.8 } }
                  texture { pigment { rgb <0.9, 0.9, 0.1> } normal { bumps 0.5 scale 0.05 } }
                  texture { pigment { gradient x color_map { [0 rgb <1, 0, 0>] [1 rgb <0, 1, 0>] } scale 0.2 } }
                } scale <2.2, 1.6, 1> }
      rotate y*-20 translate <-0.3, 0.2, 0.5> }
box { <0.01, 0.01, 0>, <0.99, 0.99, 0.1>
      pigment { image_map { png "test.png" filter 1, 0.8 transmit 3, 0.7 transmit all 0.1 transmit 5, 1 once } }
      scale <2, 1.4, 1> translate <1.6, 1.5, -0.5> }
sphere { <2.6, 0.6, -2.2>, 0.6 pigment { rgb <0.2, 0.9, 0.3> } }
