// Parity scene: the facets normal pattern, by the normal (size, metric) and by the point (coords).
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 0, -9.5> look_at <0, 0, 0> angle 50 }
light_source { <-20, 30, -40> color rgb 1 }
light_source { <30, 10, -20> color rgb 0.5 }

#declare Fin = finish { ambient 0.1 diffuse 0.7 phong 0.8 phong_size 60 }
plane { z, 2 pigment { rgb <0.4, 0.45, 0.5> } normal { facets coords 0.4 scale 0.5 } finish { Fin } }

#macro Ball(X, Y) sphere { <X * 2.2 - 3.3, 1.2 - Y * 2.4, 0>, 0.95 #end

Ball(0, 0) pigment { rgb <1, 0.65, 0> } normal { facets } finish { Fin } }
Ball(1, 0) pigment { rgb <0.8, 0.8, 1> } normal { facets size 0.3 } finish { Fin } }
Ball(2, 0) pigment { rgb <0.6, 1, 0.6> } normal { facets size 0.05 metric 1 } finish { Fin } }
Ball(3, 0) pigment { rgb <1, 0.7, 0.8> } normal { facets size 0.2 metric 3 } finish { Fin } }
Ball(0, 1) pigment { rgb <1, 0.65, 0> } normal { facets coords 1.5 scale 0.3 } finish { Fin } }
Ball(1, 1) pigment { rgb <0.8, 0.8, 1> } normal { facets coords 0.5 size 0.5 scale 0.5 rotate <20, 30, 0> } finish { Fin } }
Ball(2, 1) pigment { rgb <0.6, 1, 0.6> } normal { facets size 0.15 rotate y * 40 } finish { Fin } }
Ball(3, 1) pigment { rgb <1, 0.7, 0.8> } normal { average normal_map { [1 facets coords 1 scale 0.4] [1 bumps 0.5 scale 0.2] } } finish { Fin } }
