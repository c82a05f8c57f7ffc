// Parity scene: mirrors, refraction through glass (ior, fade), filter and transmit with their coloured shadows.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }

camera { location <0, 3, -9> look_at <0, 0.5, 0> angle 55 }
light_source { <-6, 12, -8> color rgb 1 }
light_source { <8, 6, -4> color rgb <0.35, 0.3, 0.25> }
background { rgb <0.15, 0.2, 0.3> }

plane { y, -0.5 pigment { checker rgb <0.8, 0.8, 0.75>, rgb <0.2, 0.3, 0.5> } finish { diffuse 0.8 } }
plane { z, 4 pigment { gradient x color_map { [0 rgb <0.9, 0.4, 0.2>] [1 rgb <0.2, 0.7, 0.4>] } scale 2 } }

// A mirror and a glass sphere with a solid inside it.
box { <-4.5, -0.5, 2>, <-1.5, 2.5, 2.2> pigment { rgb 0.1 } finish { reflection 0.85 ambient 0 diffuse 0.1 } rotate y * 25 }
sphere { <-1.6, 0.6, -0.5>, 1.1
  pigment { rgbf <0.95, 1, 0.95, 0.9> } finish { phong 0.9 phong_size 120 reflection { 0.02, 0.6 fresnel } }
  interior { ior 1.5 }
}
sphere { <-1.6, 0.6, -0.5>, 0.35 pigment { rgb <1, 0.3, 0.1> } }

// Filtered and transmitting boxes casting coloured shadows.
box { <0.2, -0.5, -1>, <1.4, 1.5, 0.2> pigment { rgbf <0.3, 0.6, 1, 0.8> } finish { reflection 0.1 } }
box { <1.8, -0.5, 0.4>, <3, 0.8, 1.6> pigment { rgbt <1, 0.4, 0.2, 0.6> } }

// A faded, low-index glass cylinder-like stack and a total-internal-reflection prism.
sphere { <2.6, 0.4, -1.6>, 0.9
  pigment { rgbt <1, 1, 1, 1> }
  interior { ior 1.33 fade_distance 0.8 fade_power 2 fade_color rgb <0.2, 0.5, 1> }
  finish { reflection 0.05 }
}
box { <-0.9, -0.5, -3.2>, <0.1, 0.5, -2.2>
  pigment { rgbf <1, 1, 1, 1> } interior { ior 2.4 } finish { specular 0.6 }
  rotate <0, 45, 0>
}
