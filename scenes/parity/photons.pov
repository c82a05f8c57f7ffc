// parity switches: -A
// Parity scene: POV-Ray's photon mapping, compared at a dense spacing: a glass sphere's refracted caustic and a
// metal ring's reflected one on a diffuse floor, the shadows through the targets black but for the photons.
#version 3.7;
global_settings {
  assumed_gamma 1.0
  max_trace_level 10
  photons { spacing 0.006 jitter 0 autostop 0 }
}

camera { location <0, 5, -6> look_at <0, 0.2, 0.3> angle 48 }
light_source { <-2, 9, -3> color rgb 1 photons { refraction on reflection on } }
light_source { <5, 6, -6> color rgb 0.25 photons { refraction off reflection off } }
background { rgb <0.05, 0.05, 0.1> }

plane { y, 0 pigment { rgb 0.75 } finish { diffuse 0.8 } }

sphere { <-1.1, 0.9, 0>, 0.9
  pigment { rgbf <1, 1, 1, 0.95> } finish { phong 0.6 phong_size 80 reflection 0.04 }
  interior { ior 1.5 }
  photons { target refraction on reflection on collect off }
}
torus { 0.8, 0.08 rotate 90 * x translate <1.3, 0.8, 0.6>
  pigment { rgb <1, 0.8, 0.4> } finish { diffuse 0.1 reflection { 0.9 metallic } }
  photons { target reflection on }
}
