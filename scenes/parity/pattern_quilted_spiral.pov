// Parity scene: the quilted (pigment and normal, control0/control1), spiral1 and spiral2 patterns.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 0, -9.5> look_at <0, 0, 0> angle 50 }
light_source { <-20, 30, -40> color rgb 1 }

#declare Fin = finish { ambient 0.15 diffuse 0.85 phong 0.5 }
#declare Map = color_map { [0 rgb <0.1, 0.2, 0.6>] [0.5 rgb <0.9, 0.8, 0.3>] [1 rgb <0.7, 0.1, 0.1>] }
plane { z, 2 pigment { checker rgb <0.2, 0.2, 0.25>, rgb <0.35, 0.35, 0.3> scale 0.75 } finish { Fin } }

#macro Ball(X, Y) sphere { <X * 2.2 - 3.3, 1.2 - Y * 2.4, 0>, 0.95 #end

Ball(0, 0) pigment { quilted color_map { Map } scale 0.3 } finish { Fin } }
Ball(1, 0) pigment { quilted control0 0 control1 1 frequency 2 color_map { Map } scale 0.4 } finish { Fin } }
Ball(2, 0) pigment { rgb <0.8, 0.7, 0.6> } normal { quilted 0.8 scale 0.3 } finish { Fin } }
Ball(3, 0) pigment { rgb <0.6, 0.7, 0.9> } normal { quilted 1.2 control0 0.5 control1 -0.5 scale 0.4 rotate y * 30 } finish { Fin } }
Ball(0, 1) pigment { spiral1 3 color_map { Map } scale 0.5 } finish { Fin } }
Ball(1, 1) pigment { spiral2 4 sine_wave color_map { Map } scale 0.4 rotate x * 40 } finish { Fin } }
Ball(2, 1) pigment { spiral1 5 turbulence 0.3 color_map { Map } scale 0.5 } finish { Fin } }
Ball(3, 1) pigment { rgb 0.8 } normal { spiral2 6 0.7 scale 0.5 } finish { Fin } }
