// parity switches: -A
// parity tolerance: 0.03 0.005
// Parity scene: photons in media (`media` in the photons block): a spotlight's beam through a scattering medium and
// a weak glass sphere that converges it (its focus lies beyond the medium: at a focus no photon estimate is stable).
// The medium's box lets photons pass (pass_through): before the sphere the beam is direct light lighting the medium;
// behind it the sphere's shadow is black for the light (a photon target), and the beam is the photons kept in the
// medium along their paths. Both renderers converged at the same photon spacing, jitter random in each.
#version 3.7;
global_settings {
  assumed_gamma 1.0
  max_trace_level 10
  photons { spacing 0.01 media 100, 1 autostop 0 }
}

camera { location <-0.5, 4, -9.5> look_at <-0.5, 1, 0> angle 45 }
light_source { <-9, 1.2, 0> color rgb 1.2
  spotlight radius 3 falloff 4 point_at <0, 1.2, 0>
  photons { refraction on reflection on }
}
light_source { <4, 8, -6> color rgb 0.3 photons { refraction off reflection off } media_interaction off }
background { rgb <0.02, 0.02, 0.04> }

plane { y, 0 pigment { rgb 0.6 } finish { diffuse 0.7 } }

box { <-3.5, 0.01, -2>, <4.5, 2.6, 2> hollow
  pigment { rgbf 1 }
  interior { media { scattering { 1, rgb 0.12 } method 3 intervals 1 samples 8 } }
  photons { pass_through }
}
sphere { <-2, 1.2, 0>, 0.8
  pigment { rgbf <1, 1, 1, 0.97> } finish { phong 0.5 phong_size 60 reflection 0.03 }
  interior { ior 1.05 }
  photons { target refraction on reflection on collect off }
}
