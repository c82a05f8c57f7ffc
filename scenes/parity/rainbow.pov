// Parity scene: two rainbows (no jitter, so both renderers agree pixel for pixel), one cut by arc_angle and faded
// by falloff_angle about a tilted up vector, over a sky_sphere and a floor at finite distance.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 2, -10> look_at <0, 6, 0> angle 100 }
light_source { <0, 20, -30> color rgb 1 }

sky_sphere { pigment { gradient y color_map { [0 rgb <0.6, 0.7, 0.9>] [1 rgb <0.1, 0.2, 0.5>] } } }

#declare Bow = color_map {
  [0.0 rgbf <1, 0.5, 1, 1>] [0.1 rgbf <1, 0.5, 1, 0.8>] [0.3 rgbf <0.2, 0.2, 1, 0.8>]
  [0.5 rgbf <0.2, 1, 0.2, 0.8>] [0.7 rgbf <1, 1, 0.2, 0.8>] [0.9 rgbft <1, 0.2, 0.2, 0.8, 0.1>]
}
rainbow { angle 42 width 6 distance 200 direction <-0.2, -0.2, 1> color_map { Bow } }
rainbow {
  angle 30 width 5 distance 1e7 direction <0.1, -0.3, 1> up <0.3, 1, 0>
  arc_angle 140 falloff_angle 60
  color_map { Bow }
}

plane { y, 0 pigment { rgb <0.4, 0.5, 0.3> } }
sphere { <4, 2, 30>, 4 pigment { rgb 0.7 } }
