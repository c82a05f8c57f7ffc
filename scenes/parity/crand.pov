// parity switches: +A0.0 +R9 -J
// Parity scene: finish { crand }, POV-Ray's random graininess of the diffuse light, compared converged against
// converged (81 samples a pixel), on a plain plane, a checkered sphere and a layered box with two lights.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 2.5, -8> look_at <0, 0.8, 0> angle 50 }
light_source { <-10, 15, -12> color rgb 1 }
light_source { <8, 6, -10> color rgb 0.4 }

plane { y, 0 pigment { rgb <0.9, 0.85, 0.7> } finish { diffuse 0.8 crand 0.06 } }
sphere { <-1.3, 1, 0>, 1
  pigment { checker rgb <0.9, 0.3, 0.2> rgb <0.9, 0.9, 0.9> scale 0.5 }
  finish { diffuse 0.7 crand 0.05 phong 0.3 }
}
box { <0.4, 0, -0.8>, <2.4, 1.6, 0.8> rotate y*20
  texture { pigment { rgb <0.3, 0.5, 0.9> } finish { crand 0.05 } }
  texture { pigment { gradient x color_map { [0.5 rgbt 1] [0.5 rgb 1] } scale 0.5 } finish { diffuse 0.9 crand 0.04 } }
}
