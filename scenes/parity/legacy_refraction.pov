// Parity scene: POV-Ray 3.1's `refraction R` amount, which 3.7 still reads: in a plain texture's finish it scales
// the light refracted through each surface of the object (both of a sphere's), and an interior's own `refraction`
// is overridden by that finish (1 when not given). Photons landing through the glass are scaled too.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 photons { spacing 0.02 } }

camera { location <0, 3, -7> look_at <0, 0.5, 0> angle 50 }
light_source { <-2, 8, -3> color rgb 1 photons { refraction on } }
background { rgb <0.1, 0.12, 0.2> }

plane { y, -0.5 pigment { checker rgb 0.8, rgb <0.45, 0.5, 0.7> } finish { diffuse 0.8 } }
plane { z, 4 pigment { gradient x color_map { [0 rgb <0.9, 0.3, 0.2>] [1 rgb <0.2, 0.4, 0.9>] } } }

// Half of the refracted light through each surface.
sphere { <-2, 0.6, 0>, 1
  pigment { rgbf <1, 1, 1, 0.9> } finish { refraction 0.5 phong 0.6 } interior { ior 1.5 }
  photons { target refraction on }
}
// An interior's own refraction, overridden by the plain texture's finish (POV-Ray draws it as refraction 1).
sphere { <0.3, 0.6, 0>, 1
  pigment { rgbf <1, 1, 1, 0.9> } interior { ior 1.3 refraction 0.3 }
}
// A declared finish with refraction, on a CSG whose parts inherit the texture.
#declare Half = finish { refraction 0.7 ior 1.4 }
union {
  box { <1.6, -0.45, -0.6>, <2.8, 1.2, 0.6> }
  sphere { <2.2, 1.5, 0>, 0.5 }
  pigment { rgbf <0.9, 1, 0.9, 0.8> } finish { Half }
}
