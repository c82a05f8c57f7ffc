// Parity scene: square, triangular, cubic and pigment_pattern in pigments and normals, and slope_map on normals.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 0, -9.5> look_at <0, 0, 0> angle 50 }
light_source { <-20, 30, -40> color rgb 1 }

#declare Fin = finish { ambient 0.15 diffuse 0.85 phong 0.5 }
plane { z, 2 pigment { square rgb <0.2, 0.2, 0.25>, rgb <0.35, 0.35, 0.3>, rgb 0.3, rgb 0.25 scale 0.75 } finish { Fin } }

#macro Ball(X, Y) sphere { <X * 2.2 - 3.3, 1.2 - Y * 2.4, 0>, 0.95 #end

Ball(0, 0) pigment { square rgb <1, 0.2, 0.2>, rgb <0.2, 1, 0.2>, rgb <0.2, 0.2, 1>, rgb 1 scale 0.3 rotate x * -70 } finish { Fin } }
Ball(1, 0) pigment { triangular scale 0.35 rotate x * -60 } finish { Fin } }
Ball(2, 0) pigment { cubic rgb 0, rgb 0.2, rgb 0.4, rgb 0.6, rgb 0.8, rgb 1 rotate <30, 40, 0> } finish { Fin } }
Ball(3, 0) pigment { pigment_pattern { checker rgb 1, rgb 0.3 scale 0.3 } color_map { [0 rgb <0.1, 0.1, 0.5>] [1 rgb <1, 0.9, 0.3>] } turbulence 0.3 } finish { Fin } }
Ball(0, 1) pigment { rgb 0.8 } normal { gradient x 1 slope_map { [0 <0, 1>] [0.5 <1, 1>] [0.5 <1, -1>] [1 <0, -1>] } scale 0.3 } finish { Fin } }
Ball(1, 1) pigment { rgb <0.7, 0.8, 0.9> } normal { onion 0.8 slope_map { [0 <0.5, 1>] [0.25 <1, 0>] [0.5 <0.5, -1>] [0.75 <0, 0>] [1 <0.5, 1>] } scale 0.4 } finish { Fin } }
Ball(2, 1) pigment { rgb 0.8 } normal { pigment_pattern { bozo color_map { [0 rgb 0] [1 rgb 1] } scale 0.2 } 0.8 } finish { Fin } }
Ball(3, 1) pigment { rgb <0.9, 0.7, 0.6> } normal { triangular 0.8 scale 0.3 rotate x * -60 } finish { Fin } }
