// Parity scene: slope (simple, ranges, altitude, point_at, in a texture_map, after a perturbed normal) and aoi.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 0, -9.5> look_at <0, 0, 0> angle 50 }
light_source { <-20, 30, -40> color rgb 1 }

#declare Fin = finish { ambient 0.15 diffuse 0.85 }
#declare Ramp = color_map { [0 rgb <0.1, 0.1, 0.6>] [0.5 rgb <0.2, 0.9, 0.3>] [1 rgb <1, 0.8, 0.2>] }
plane { z, 2 pigment { aoi color_map { Ramp } } finish { Fin } }

#macro Ball(X, Y) sphere { <X * 2.2 - 3.3, 1.2 - Y * 2.4, 0>, 0.95 #end

Ball(0, 0) pigment { slope y color_map { Ramp } } finish { Fin } }
Ball(1, 0) pigment { slope { -x*2, 0.3, 0.8 } color_map { Ramp } } finish { Fin } }
Ball(2, 0) pigment { slope { y*0.8, 0.5, 1.0 altitude <0, 1, 0.5>, -0.2, 1.8 } color_map { Ramp } } finish { Fin } }
Ball(3, 0) pigment { slope { point_at <3, 5, -6> } color_map { Ramp } } finish { Fin } }
Ball(0, 1) texture { slope { -z*0.8 altitude y } texture_map {
    [0.3 pigment { rgb <0.2, 0.6, 0.2> } finish { Fin }]
    [0.5 pigment { rgb <0.8, 0.7, 0.5> } finish { Fin }]
    [0.7 pigment { rgb 0.6 } finish { Fin }] } scale 1.5 rotate z * 20 } }
Ball(1, 1) pigment { slope <1, 1, 0> color_map { Ramp } frequency 3 } normal { bumps 0.8 scale 0.2 } finish { Fin } }
Ball(2, 1) pigment { aoi color_map { Ramp } } normal { slope { y altitude x } 1.5 scale 0.3 } finish { Fin } }
Ball(3, 1) pigment { aoi pigment_map { [0 slope y color_map { Ramp }] [1 rgb 1] } } finish { Fin } scale <1, 0.6, 1> }
