// parity switches: -A
// parity tolerance: 0.03 0.005
// Parity scene: dispersion. A spotlight's beam through an upright glass prism (interior dispersion) spreads into a
// spectrum on a white floor, in photons; camera rays through the prism split into bands too.
#version 3.7;
global_settings {
  assumed_gamma 1.0
  max_trace_level 10
  photons { spacing 0.002 jitter 0 autostop 0 }
}

camera { location <1.2, 5.5, -4> look_at <1.2, 0.2, 0> angle 50 }
light_source { <-6, 2.6, -0.4> color rgb 3
  spotlight point_at <0, 0.75, 0> radius 1.6 falloff 2.6
  photons { refraction on reflection off } }
light_source { <3, 8, -5> color rgb 0.25 photons { refraction off reflection off } }
background { rgb <0.05, 0.05, 0.1> }

plane { y, 0 pigment { rgb 1 } finish { diffuse 0.8 } }

prism { linear_sweep linear_spline 0.25, 1.25, 4, <-0.5, -0.29>, <0.5, -0.29>, <0, 0.577>, <-0.5, -0.29>
  rotate 18 * y
  pigment { rgbf 1 } finish { diffuse 0 phong 0.5 phong_size 60 }
  interior { ior 1.5 dispersion 1.1 dispersion_samples 7 }
  photons { target refraction on reflection off collect off }
}
