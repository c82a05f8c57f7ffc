// Parity scene: the mandel, julia and magnet patterns with exponents, exterior and interior types, in pigments
// and normals.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 0, -9.5> look_at <0, 0, 0> angle 50 }
light_source { <-20, 30, -40> color rgb 1 }

#declare Fin = finish { ambient 0.2 diffuse 0.8 }
#declare Map = color_map { [0 rgb <0, 0, 0.3>] [0.2 rgb <0.2, 0.6, 1>] [0.5 rgb <1, 1, 0.5>] [1 rgb <0.8, 0.1, 0>] }
#macro Tile(X, Y) box { <-0.95, -0.95, 0>, <0.95, 0.95, 0.1> translate <X * 2 - 3, 2 - Y * 2, 0> #end

Tile(0, 0) pigment { mandel 40 color_map { Map } scale 0.6 translate <0.3, 0, 0> } finish { Fin } }
Tile(1, 0) pigment { mandel 30 exponent 3 color_map { Map } scale 0.7 } finish { Fin } }
Tile(2, 0) pigment { mandel 25 exponent 4 exterior 6, 0.3 interior 1, 1 color_map { Map } scale 0.7 } finish { Fin } }
Tile(3, 0) pigment { mandel 20 exponent 7 exterior 7, 5 interior 2, 0.5 color_map { Map } scale 0.7 } finish { Fin } }
Tile(0, 1) pigment { julia <0.353, 0.288>, 50 color_map { Map } scale 0.8 } finish { Fin } }
Tile(1, 1) pigment { julia <-0.2, 0.6>, 30 exponent 3 interior 6, 0.5 color_map { Map } scale 0.7 } finish { Fin } }
Tile(2, 1) pigment { julia <0.4, 0.1>, 30 exponent 4 exterior 2, 0.5 interior 3, 1 color_map { Map } scale 0.7 } finish { Fin } }
Tile(3, 1) pigment { julia <0.5, 0.2>, 20 exponent 5 exterior 8, 4 interior 4, 2 color_map { Map } scale 0.7 } finish { Fin } }
Tile(0, 2) pigment { magnet 1 mandel 40 color_map { Map } scale 0.4 translate <0.4, 0, 0> } finish { Fin } }
Tile(1, 2) pigment { magnet 2 mandel 30 exterior 3, 0.3 color_map { Map } scale 0.4 } finish { Fin } }
Tile(2, 2) pigment { magnet 1 julia <1.3, 0.6>, 30 interior 5, 0.5 color_map { Map } scale 0.3 } finish { Fin } }
Tile(3, 2) pigment { rgb 0.8 } normal { mandel 30, 0.8 scale 0.7 } finish { Fin } }
