// Parity scene: each light type over a floor: point with fade, spotlight with tightness, parallel, shadowless.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 5, -9> look_at <0, 0.5, 0> angle 55 }

light_source { <-3, 4, -2> color rgb <0.9, 0.6, 0.4> fade_distance 3 fade_power 2 }
light_source { <2, 6, -1> color rgb <0.4, 0.7, 1.0>
  spotlight point_at <1.5, 0, 1> radius 14 falloff 26 tightness 5 }
light_source { <0, 10, -10> color rgb 0.25 parallel point_at <0, 0, 0> }
light_source { <5, 1, -5> color rgb <0.1, 0.2, 0.1> shadowless }

plane { y, 0 pigment { rgb 0.8 } finish { ambient 0.05 diffuse 0.9 } }
sphere { <-1.5, 0.8, 0>, 0.8 pigment { rgb <0.9, 0.9, 0.6> } finish { ambient 0.05 diffuse 0.8 specular 0.4 roughness 0.02 } }
box { <0.8, 0, 0.2>, <2.2, 1.2, 1.6> pigment { rgb <0.6, 0.9, 0.6> } finish { diffuse 0.7 brilliance 2 } }
