// Parity scene: `no_bump_scale` (POV-Ray's DONT_SCALE_BUMPS_FLAG): the normal goes into and out of a scaled normal
// pattern's space unnormalized, so its bumps are shallower by the pattern's scale; given in a normal, in a texture
// (reaching its normal, read before or after the flag) and in a normal_map's parent (its entries inherit it).
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 3, -8> look_at <0, 0.6, 0> angle 50 }
light_source { <-4, 8, -6> color rgb 1 }
light_source { <5, 4, -3> color rgb <0.3, 0.3, 0.35> }
background { rgb <0.1, 0.12, 0.2> }

plane { y, -0.5 pigment { rgb 0.7 } normal { bumps 0.8 scale 0.4 no_bump_scale } }
// The same bumps scaled by 3, with and without the flag.
sphere { <-2.4, 0.8, 0>, 1 pigment { rgb <0.9, 0.5, 0.3> } normal { bumps 1 scale 3 } }
sphere { <0, 0.8, 0>, 1 pigment { rgb <0.9, 0.5, 0.3> } normal { bumps 1 scale 3 no_bump_scale } }
// In a texture, before its normal; a non-uniform scale.
box { <1.6, -0.4, -0.8>, <3.2, 1.6, 0.8>
  texture { no_bump_scale pigment { rgb <0.4, 0.6, 0.9> } normal { wrinkles 1.2 scale <0.5, 2, 0.5> } }
}
// A normal_map whose entries inherit the flag.
sphere { <-1.2, 2.6, 1.5>, 0.8
  pigment { rgb 0.9 }
  normal { gradient y normal_map { [0 dents 1 scale 0.2] [1 ripples 1 scale 0.3] } scale 2 no_bump_scale }
}
