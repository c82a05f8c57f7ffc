// Media and `hollow`: the camera inside a hollow sphere of thin scattering media, media in a non-hollow object
// (which rays inside it never see), media seen through a refracting hollow glass shell, and a transparent object
// casting a shadow dimmed by its media.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -8> look_at <0, 1, 0> angle 55 }
light_source { <-4, 9, -6> color rgb 1.2 }
plane { y, 0 pigment { checker rgb 0.8, rgb 0.35 } }
sphere { 0, 12 pigment { rgbt 1 } hollow
  interior { media { scattering { 1, rgb 0.004 } absorption 0.002 samples 2 } }
}
sphere { <-2.6, 1, 0>, 1 pigment { rgbt 1 } interior { media { emission <1, 0.4, 0.2> } } }
sphere { <-2.6, 1, 0>, 1.001 pigment { rgbt 1 } hollow no }
sphere { <0, 1.1, 0.5>, 1.1
  pigment { rgbf <0.9, 1, 0.95, 0.9> } finish { phong 0.8 } hollow
  interior { ior 1.3 }
}
sphere { <0, 1.1, 0.5>, 0.8 pigment { rgbt 1 } hollow
  interior { media { emission <0.2, 0.6, 1> absorption 0.6 density { spherical } } }
}
box { <1.8, 0, -0.8>, <3.4, 2, 0.8> pigment { rgbt 1 } hollow
  interior { media { absorption <0.2, 0.6, 1.2> density { gradient y color_map { [0 rgb 1] [1 rgb 0.2] } } } }
}
