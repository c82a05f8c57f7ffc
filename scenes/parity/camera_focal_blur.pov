// Focal blur, compared converged against converged: both renderers draw random points on the aperture, so every
// pixel takes blur_samples' maximum (variance 0 never lets the confidence test stop early) and the noise of the two
// estimates of the same lens integral stays below the parity tolerance (two wardray seeds differ by 0.44 %; the same
// scene without blur differs from this one by 7.6 %). Objects in front of, at and behind the focal point, with sharp
// edges and a checker that the blur turns to grey; a low-contrast checker and a grey background keep the noise low.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera {
  location <0, 2, -7>
  look_at <0, 1, 0>
  angle 50
  aperture 0.4
  focal_point <0, 1, 0>
  blur_samples 400, 400
  confidence 0.999
  variance 0
}
light_source { <-5, 8, -6> color rgb 1 }
background { rgb <0.35, 0.4, 0.5> }
plane { y, 0 pigment { checker rgb 0.75, rgb 0.45 } }
sphere { <0, 1, 0>, 1 pigment { rgb <0.9, 0.4, 0.2> } }
box { <-3.2, 0, -2.5>, <-2.2, 1.6, -1.5> pigment { rgb <0.3, 0.5, 0.9> } }
cylinder { <2.6, 0, 4>, <2.6, 3, 4>, 0.6 pigment { rgb <0.3, 0.8, 0.3> } }
