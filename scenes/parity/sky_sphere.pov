// Parity scene: a declared sky_sphere with two layered pigments (the top one partly filtering and transmitting),
// emission, a rotation and a declared copy extended with a translation, over a background, seen directly and
// in a mirror.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 1.5, -6> look_at <0, 2.2, 0> angle 80 }
light_source { <-4, 8, -6> color rgb 1 }
background { color rgb <0.3, 0.1, 0.05> }

#declare Sky = sky_sphere {
  pigment { gradient y color_map { [0 rgb <0.9, 0.6, 0.3>] [0.5 rgb <0.2, 0.4, 0.9>] [1 rgb <0.05, 0.1, 0.4>] } }
  pigment { bozo turbulence 0.6 scale <0.3, 0.08, 0.3>
    color_map { [0.4 rgbft <1, 1, 1, 0, 1>] [0.6 rgbft <1, 0.9, 0.8, 0.3, 0.2>] [1 rgbf <0.8, 0.8, 0.9, 0.5>] } }
  emission rgb <1.2, 1.1, 1.0>
  rotate <10, 20, 0>
}
sky_sphere { Sky translate <0, -0.15, 0> }

plane { y, 0 pigment { checker rgb 0.6 rgb 0.3 } finish { reflection 0.3 } }
sphere { <0, 1, 1>, 1 pigment { rgb 0.1 } finish { reflection 0.8 } }
