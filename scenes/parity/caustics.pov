// Parity scene: POV-Ray's fake caustics (interior caustics): shadows of clear glass brighter where its surface
// faces the light, with bumped normals and a texture map in the shadow's way, and POV-Ray 3.1's caustics in a finish.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }

camera { location <0, 4, -8> look_at <0, 0.3, 0> angle 50 }
light_source { <-3, 10, -4> color rgb 1 }
light_source { <6, 5, -2> color rgb <0.3, 0.3, 0.35> }
background { rgb <0.1, 0.12, 0.2> }

plane { y, -0.5 pigment { checker rgb 0.8, rgb <0.55, 0.6, 0.7> } finish { diffuse 0.8 } }

// A smooth glass sphere: the shadow's centre brightens with caustics 1.
sphere { <-2, 0.6, 0>, 1.1
  pigment { rgbf <0.97, 1, 0.97, 0.92> } finish { phong 0.8 phong_size 90 reflection 0.05 }
  interior { ior 1.5 caustics 1 }
}
// Bumpy water-like glass: the caustic term follows the perturbed normal.
box { <-0.2, -0.5, -0.8>, <1.4, 0.9, 0.8>
  pigment { rgbt <0.8, 0.9, 1, 0.85> } normal { bumps 0.6 scale 0.25 }
  interior { ior 1.33 caustics 0.6 }
}
// A texture map over clear glass, caustics 2.
sphere { <2.6, 0.3, 0.4>, 0.8
  texture { gradient y texture_map { [0.3 pigment { rgbf <1, 0.7, 0.5, 0.9> }]
                                     [0.7 pigment { rgbt <0.6, 0.8, 1, 0.9> } normal { dents 0.5 scale 0.2 }] } }
  interior { ior 1.45 caustics 2 }
}
// POV-Ray 3.1's caustics in a finish, promoted to the interior unscaled.
cylinder { <-0.5, -0.5, 2>, <-0.5, 1.4, 2>, 0.5
  pigment { rgbf <1, 1, 0.9, 0.9> } finish { caustics 20 }
  interior { ior 1.2 }
}
