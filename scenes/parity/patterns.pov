// Parity scene: POV-Ray's common patterns with colour maps, pigment maps, turbulence, wave types and transforms.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 0, -9.5> look_at <0, 0, 0> angle 50 }
light_source { <-20, 30, -40> color rgb 1 }

#declare Fin = finish { ambient 0.15 diffuse 0.85 }
#macro Ramp() color_map { [0 rgb <0.1, 0.2, 0.6>] [0.5 rgb <0.9, 0.8, 0.3>] [1 rgb <0.7, 0.1, 0.1>] } #end

// Back wall: checker in two colours.
plane { z, 2 pigment { checker rgb <0.2, 0.2, 0.25>, rgb <0.35, 0.35, 0.3> scale 0.75 } finish { Fin } }

#macro Ball(X, Y) sphere { <X * 1.3 - 3.25, 1.95 - Y * 1.3, 0>, 0.6 #end

// Row 0
Ball(0, 0) pigment { gradient x color_map { [0 rgb <1, 0, 0>] [0.5 rgb <0, 1, 0>] [1 rgb <0, 0, 1>] } scale 0.5 } finish { Fin } }
Ball(1, 0) pigment { hexagon rgb <0.9, 0.2, 0.1>, rgb <0.1, 0.7, 0.2>, rgb <0.2, 0.3, 0.9> scale 0.15 rotate x * 90 } finish { Fin } }
Ball(2, 0) pigment { brick rgb 0.8, rgb <0.6, 0.2, 0.1> scale 0.04 } finish { Fin } }
Ball(3, 0) pigment { bozo Ramp() scale 0.3 } finish { Fin } }
Ball(4, 0) pigment { spotted color_map { [0.3 rgb 0.1] [0.7 rgb <1, 0.8, 0.4>] } scale 0.25 } finish { Fin } }
Ball(5, 0) pigment { granite Ramp() scale 0.8 } finish { Fin } }

// Row 1
Ball(0, 1) pigment { marble turbulence 0.8 color_map { [0 rgb 0.9] [0.8 rgb <0.5, 0.2, 0.2>] [1 rgb 0.1] } scale 0.4 } finish { Fin } }
Ball(1, 1) pigment { wood turbulence 0.1 color_map { [0 rgb <0.8, 0.5, 0.2>] [1 rgb <0.4, 0.2, 0.05>] } scale 0.1 rotate x * 70 } finish { Fin } }
Ball(2, 1) pigment { agate agate_turb 0.6 Ramp() scale 0.5 } finish { Fin } }
Ball(3, 1) pigment { radial frequency 6 color_map { [0 rgb 1] [0.5 rgb <0.2, 0.4, 0.9>] [1 rgb 1] } rotate x * -60 } finish { Fin } }
Ball(4, 1) pigment { onion sine_wave Ramp() scale 0.2 translate <0.1, 0.2, 0> } finish { Fin } }
Ball(5, 1) pigment { leopard color_map { [0 rgb 0.9] [0.5 rgb <0.8, 0.6, 0.2>] [1 rgb 0.05] } scale 0.05 } finish { Fin } }

// Row 2
Ball(0, 2) pigment { ripples frequency 2 Ramp() scale 0.3 } finish { Fin } }
Ball(1, 2) pigment { waves phase 0.3 Ramp() scale 0.2 } finish { Fin } }
Ball(2, 2) pigment { wrinkles Ramp() scale 0.4 } finish { Fin } }
Ball(3, 2) pigment { bumps triangle_wave frequency 2 Ramp() scale 0.2 } finish { Fin } }
Ball(4, 2) pigment { dents cubic_wave color_map { [0 rgb 1] [0.3 rgb <0.3, 0.5, 0.2>] [1 rgb 0] } scale 0.3 } finish { Fin } }
Ball(5, 2) pigment { crackle color_map { [0 rgb 0] [0.05 rgb 0] [0.1 rgb <0.9, 0.9, 0.7>] [1 rgb <0.5, 0.6, 0.9>] } scale 0.25 } finish { Fin } }

// Row 3
Ball(0, 3) pigment { cells Ramp() scale 0.2 } finish { Fin } }
Ball(1, 3) pigment { bozo turbulence 0.5 octaves 4 omega 0.6 lambda 2.5 scallop_wave Ramp() scale 0.4 } finish { Fin } }
Ball(2, 3) pigment { gradient y pigment_map { [0.3 checker rgb 1, rgb 0 scale 0.1] [0.7 granite Ramp()] } } finish { Fin } }
Ball(3, 3) pigment { checker color rgb <1, 0.5, 0>, color rgb <0.2, 0.2, 0.5> scale 0.3 } finish { Fin } scale 0.7 rotate y * 30 translate <-0.5, 0, 0> }
Ball(4, 3) pigment { spotted poly_wave 3 color_map { [0, 0.5 color rgb 0 color rgb <0.5, 1, 0.5>] [0.5, 1 color rgb 1 color rgb <0.2, 0.2, 1>] } scale 0.2 } finish { Fin } }
Ball(5, 3) pigment { marble turbulence <0.5, 0.2, 0.1> frequency 2 phase 0.25 Ramp() rotate z * 45 } finish { Fin } }
