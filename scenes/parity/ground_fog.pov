// Parity scene: two fogs at once: a tilted ground fog (fog_type 2, fog_offset, fog_alt, up, turbulence with
// turb_depth, octaves, omega, lambda) and a thin filtering constant fog with transmit; lights dimmed by it.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 2, -10> look_at <0, 1, 0> angle 60 }
light_source { <-5, 10, -5> color rgb 1 media_attenuation on }
background { color rgb <0.2, 0.3, 0.6> }

fog {
  fog_type 2
  distance 12
  color rgb <0.9, 0.85, 0.8>
  fog_offset 0.2
  fog_alt 0.5
  up <0, 1, 0.1>
  rotate <0, 0, 5>
  turbulence <0.4, 0.8, 0.4>
  turb_depth 0.6
  octaves 4
  omega 0.6
  lambda 2.5
}
fog {
  distance 60
  color rgbft <0.6, 0.7, 1.0, 0.5, 0.2>
}

plane { y, 0 pigment { checker rgb 0.8 rgb 0.2 scale 2 } }
sphere { <-2, 1, 3>, 1 pigment { rgb <0.9, 0.3, 0.2> } }
box { <1, 0, 0>, <3, 3, 2> pigment { rgb <0.3, 0.8, 0.4> } }
cylinder { <0, 0, 12>, <0, 6, 12>, 1 pigment { rgb 0.9 } }
