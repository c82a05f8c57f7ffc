// Parity scene: the `average` pattern in a pigment_map, a normal_map and a texture_map, with weights.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 0, -9.5> look_at <0, 0, 0> angle 50 }
light_source { <-20, 30, -40> color rgb 1 }

#declare Fin = finish { ambient 0.15 diffuse 0.85 phong 0.4 }
plane { z, 2 pigment { checker rgb <0.2, 0.2, 0.25>, rgb <0.35, 0.35, 0.3> scale 0.75 } finish { Fin } }

#macro Ball(X, Y) sphere { <X * 2.2 - 3.3, 1.2 - Y * 2.4, 0>, 0.95 #end

Ball(0, 0) pigment { average pigment_map {
    [1 gradient x color_map { [0 rgb <1, 0, 0>] [1 rgb <0, 0, 1>] } scale 0.5]
    [2 bozo color_map { [0 rgb 1] [1 rgb <0.1, 0.6, 0.1>] } scale 0.3]
    [0.5 rgb <0.9, 0.8, 0.2>] } } finish { Fin } }
Ball(1, 0) pigment { average pigment_map {
    [1 wood color_map { [0 rgb <0.8, 0.5, 0.2>] [1 rgb <0.4, 0.2, 0.05>] } turbulence 0.1 scale 0.1]
    [1 wood color_map { [0 rgb <0.7, 0.6, 0.4>] [1 rgb <0.3, 0.1, 0.0>] } scale 0.07 rotate y * 40] }
    rotate x * 30 } finish { Fin } }
Ball(2, 0) pigment { average pigment_map {
    [3 rgbf <1, 0.2, 0.2, 0.6>] [1 checker rgb 1, rgb 0 scale 0.25] } scale 0.7 } finish { Fin } }
Ball(3, 0) pigment { rgb <0.8, 0.7, 0.6> } normal { average normal_map {
    [1 bumps 0.8 scale 0.2] [1 gradient x 0.6 scale 0.3] [0.5 dents 1 scale 0.25] } } finish { Fin } }
Ball(0, 1) pigment { rgb <0.6, 0.8, 0.6> } normal { average normal_map {
    [2 ripples 0.7 scale 0.4] [1 wrinkles 0.6 scale 0.3] } rotate y * 30 } finish { Fin } }
Ball(1, 1) texture { average texture_map {
    [1 pigment { rgb <1, 0.3, 0.1> } finish { Fin }]
    [1 pigment { granite color_map { [0 rgb 0] [1 rgb 1] } } normal { bumps 0.5 scale 0.2 } finish { Fin }]
    [2 pigment { rgb <0.2, 0.3, 0.9> } finish { ambient 0.1 diffuse 0.5 specular 0.6 }] } } }
Ball(2, 1) texture { average texture_map {
    [1 pigment { checker rgb 1, rgb <0.3, 0.3, 0.6> scale 0.3 } finish { Fin }]
    [1 pigment { rgbt <0.9, 0.9, 0.2, 0.7> } finish { Fin }] } scale 1.3 } }
Ball(3, 1) texture { average texture_map {
    [1 pigment { radial frequency 8 color_map { [0 rgb 1] [1 rgb <0.9, 0.1, 0.1>] } } finish { Fin }]
    [3 pigment { onion color_map { [0 rgb <0.1, 0.5, 0.9>] [1 rgb 1] } scale 0.3 } finish { Fin }] }
    rotate x * -60 } }
