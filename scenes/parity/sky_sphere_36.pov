// Parity scene: a sky_sphere in a #version 3.6 scene, whose layered pigments POV-Ray 3.7 combines by 3.6's rule
// (not as a layered texture), with filter and transmit in both layers and emission.
#version 3.6;
global_settings { assumed_gamma 1.0 }

camera { location <0, 1, -5> look_at <0, 2, 0> angle 90 }
light_source { <3, 6, -4> color rgb 1 }
background { color rgb <0.2, 0.5, 0.1> }

sky_sphere {
  pigment { gradient y color_map { [0 rgbt <1, 0.5, 0.2, 0.6>] [1 rgbf <0.2, 0.3, 1, 0.5>] } }
  pigment { wood scale 0.2 color_map { [0 rgbft <1, 1, 1, 0.2, 0.6>] [1 rgbft <0.9, 0.2, 0.2, 0.7, 0.1>] } }
  emission rgb 0.8
  scale <1, 0.5, 1>
}

box { <-1, 0, -1>, <1, 1, 1> pigment { rgb <0.8, 0.7, 0.5> } }
