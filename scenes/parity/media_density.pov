// Media: absorption and emission in interiors, density patterns with colour maps, density maps, several densities
// multiplied, several media in one object, transformed with the object; method 3's defaults.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -9> look_at <0, 1, 0> angle 50 }
light_source { <-5, 10, -8> color rgb 1 }
plane { y, 0 pigment { checker rgb 0.9, rgb 0.3 } }
plane { -z, -6 pigment { checker rgb <0.9, 0.8, 0.6>, rgb <0.2, 0.3, 0.5> } }
#declare Glow = density {
  spherical
  color_map { [0 rgb 0] [0.3 rgb <1, 0.3, 0.1>] [1 rgb <1, 1, 0.2>] }
}
// Emission with a declared density, moved and scaled with the sphere.
sphere { 0, 1
  pigment { rgbt 1 } hollow
  interior { media { emission 0.9 density { Glow } } }
  scale 1.2 translate <-2.6, 1.3, 0>
}
// Absorption by a gradient through a density_map of two densities.
box { -1, 1
  pigment { rgbt 1 } hollow
  interior {
    media {
      absorption <0.6, 1.2, 1.6>
      intervals 2 samples 6
      density {
        gradient x
        density_map { [0.3 Glow scale 0.5] [0.7 rgb 1] }
      }
    }
  }
  rotate 30*y translate <0, 1.1, 0.5>
}
// Two media in one object, and two densities multiplied in one of them.
sphere { 0, 1
  pigment { rgbt 1 } hollow
  interior {
    media { emission <0.2, 0.5, 1> density { Glow translate 0.3*y } density { bozo scale 0.4 } }
    media { absorption 0.8 aa_level 4 aa_threshold 0.05 density { gradient y color_map { [0 rgb 0] [1 rgb 1] } } }
  }
  scale 1.2 translate <2.6, 1.3, 0>
}
