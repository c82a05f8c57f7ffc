// Parity scene: image_pattern in pigments, normals and texture maps (planar, spherical and cylindrical maps,
// interpolate, once, use_index, use_alpha with and without alpha) and a palette image_map with its alpha.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 0, -9.5> look_at <0, 0, 0> angle 50 }
light_source { <-20, 30, -40> color rgb 1 }

#declare Fin = finish { ambient 0.15 diffuse 0.85 }
#declare Ramp = color_map { [0 rgb <0.1, 0.1, 0.6>] [0.5 rgb <0.2, 0.9, 0.3>] [1 rgb <1, 0.8, 0.2>] }
plane { z, 2 pigment { image_pattern { png "plasma2.png" interpolate 2 } color_map { Ramp } scale 3 } finish { Fin } }

#macro Ball(X, Y) sphere { <X * 2.2 - 3.3, 1.2 - Y * 2.4, 0>, 0.95 #end

Ball(0, 0) pigment { image_pattern { png "mtmandj.png" map_type 1 } color_map { Ramp } } finish { Fin } }
Ball(1, 0) pigment { image_pattern { png "Mount1.png" map_type 2 interpolate 4 } color_map { Ramp } } finish { Fin } }
Ball(2, 0) pigment { image_pattern { png "fract003.png" once use_index } color_map { Ramp } scale 1.9 translate <0.15, 0.25, 0> } finish { Fin } }
Ball(3, 0) pigment { image_pattern { png "Mount1.png" use_alpha interpolate 2 } color_map { Ramp } scale 0.8 } finish { Fin } }
Ball(0, 1) pigment { rgb 0.8 } normal { image_pattern { png "plasma2.png" interpolate 2 } 1.5 scale 0.7 } finish { Fin } }
Ball(1, 1) texture { image_pattern { png "Mount1.png" map_type 1 interpolate 2 } texture_map {
    [0.3 pigment { rgb <0.2, 0.6, 0.2> } finish { Fin }]
    [0.6 pigment { rgb <0.8, 0.7, 0.5> } finish { Fin }] } } }
Ball(2, 1) pigment { image_pattern { png "test.png" } pigment_map { [0 rgb 0.2] [1 checker rgb 1, rgb <1, 0.3, 0.3> scale 0.1] } } finish { Fin } }
Ball(3, 1) pigment { image_map { png "fract003.png" map_type 1 } } finish { Fin } }
Ball(1.5, 0.5) pigment { image_pattern { png "plasma2.png" use_alpha } color_map { Ramp } } finish { Fin } scale 0.3 }
