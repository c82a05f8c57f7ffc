// Parity scene: every warp (turbulence, repeat, black_hole, cylindrical, spherical, toroidal, planar, cubic) with
// orientation and dist_exp, mixed with transforms before and after.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 0, -9.5> look_at <0, 0, 0> angle 50 }
light_source { <-20, 30, -40> color rgb 1 }

#declare Fin = finish { ambient 0.15 diffuse 0.85 }
#declare Map = color_map { [0 rgb <0.1, 0.2, 0.6>] [0.5 rgb <0.9, 0.8, 0.3>] [1 rgb <0.7, 0.1, 0.1>] }
plane { z, 2 pigment { checker rgb <0.2, 0.2, 0.25>, rgb <0.35, 0.35, 0.3> scale 0.75 } finish { Fin } }

#macro Ball(X, Y) sphere { <X * 1.6 - 3.2, 1.6 - Y * 1.6, 0>, 0.7 #end

Ball(0, 0) pigment { gradient x color_map { Map } warp { turbulence 0.5 octaves 3 omega 0.7 lambda 2.5 } scale 0.5 } finish { Fin } }
Ball(1, 0) pigment { bozo color_map { Map } scale 0.2 warp { repeat x * 0.3 offset <0, 0.1, 0> flip x } } finish { Fin } }
Ball(2, 0) pigment { checker rgb 1, rgb <0.2, 0.3, 0.8> scale 0.15 warp { black_hole <0, 0, 0>, 0.6 falloff 1.5 strength 1.5 } } finish { Fin } }
Ball(3, 0) pigment { checker rgb 1, rgb <0.8, 0.2, 0.2> scale 0.1 warp { black_hole <0.05, 0.05, 0.05>, 0.08 inverse repeat <0.2, 0.2, 0.2> turbulence <0.02, 0.02, 0> } } finish { Fin } }
Ball(4, 0) pigment { checker rgb 1, rgb <0.2, 0.6, 0.2> warp { cylindrical orientation y dist_exp 0.5 } scale <0.1, 0.2, 0.1> } finish { Fin } }
Ball(0, 1) pigment { checker rgb 1, rgb <0.6, 0.2, 0.6> scale <0.1, 0.1, 1> warp { spherical } rotate y * 20 } finish { Fin } }
Ball(1, 1) pigment { checker rgb 1, rgb <0.2, 0.2, 0.2> scale 0.1 warp { spherical orientation <0, 1, 1> dist_exp 1 } } finish { Fin } }
Ball(2, 1) pigment { gradient x color_map { Map } scale 0.2 warp { toroidal major_radius 0.4 orientation x dist_exp 0.5 } } finish { Fin } }
Ball(3, 1) pigment { checker rgb 1, rgb <0.9, 0.5, 0.1> scale 0.2 warp { planar y, 0.3 } rotate x * 30 } finish { Fin } }
Ball(4, 1) pigment { checker rgb 1, rgb <0.1, 0.5, 0.9> scale <0.125, 0.167, 1> warp { cubic } } finish { Fin } }
Ball(0, 2) pigment { marble color_map { Map } turbulence 0.5 warp { turbulence 0.3 } scale 0.5 } finish { Fin } }
Ball(1, 2) pigment { agate color_map { Map } scale 0.6 warp { repeat y * 0.25 flip y } rotate z * 20 warp { turbulence 0.2 } } finish { Fin } }
Ball(2, 2) pigment { rgb 0.8 } normal { bumps 0.8 scale 0.1 warp { black_hole 0, 0.5 strength 2 } } finish { Fin } }
Ball(3, 2) pigment { rgb 0.8 } normal { gradient x 0.8 scale 0.2 warp { cylindrical } rotate x * 90 } finish { Fin } }
Ball(4, 2) texture { checker texture { pigment { rgb 1 } finish { Fin } } texture { pigment { rgb <0.8, 0.3, 0.1> } finish { Fin } } scale 0.15 warp { repeat z * 0.3 } warp { black_hole 0, 0.5 } } }
