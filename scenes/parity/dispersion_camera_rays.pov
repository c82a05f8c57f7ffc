// parity switches: -A
// Parity scene: dispersion seen by camera rays, no photons: a dispersive glass sphere, and a dispersive sphere of 5
// samples inside a plain glass one (the relative index and dispersion of nested interiors), before a checker wall.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
camera { location <0, 1, -5> look_at <0, 1, 0> angle 40 }
light_source { <3, 6, -6> color rgb 1 }
plane { z, 3 pigment { checker rgb 1 rgb 0.1 scale 0.25 } finish { ambient 0 diffuse 1 } }
plane { y, 0 pigment { rgb 0.8 } finish { ambient 0 diffuse 1 } }
sphere { <-0.7, 1, 0>, 0.6 pigment { rgbf 1 } finish { ambient 0 diffuse 0 }
  interior { ior 1.5 dispersion 1.15 } }
sphere { <0.7, 1, 0>, 0.6 pigment { rgbf 1 } finish { ambient 0 diffuse 0 }
  interior { ior 1.5 } }
sphere { <0.7, 1, 0>, 0.3 pigment { rgbf 1 } finish { ambient 0 diffuse 0 }
  interior { ior 1.3 dispersion 1.3 dispersion_samples 5 } }
