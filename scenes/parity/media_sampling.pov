// Media sampling: method 2 (stratified, without jitter), method 3's adaptive refinement (aa_level, aa_threshold)
// with several intervals shared out by `ratio` between the stretches a spotlight lights and those it does not.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -10> look_at <0, 1.5, 0> angle 50 }
light_source { <-6, 8, -6> color rgb 1 }
light_source { <0, 9, 0> color rgb <1, 0.8, 0.5> * 3 spotlight point_at <0, 0, 0> radius 5 falloff 9 }
plane { y, 0 pigment { checker rgb 0.8, rgb 0.4 } }
#declare Cloud = density { spherical color_map { [0 rgb 0] [0.5 rgb 0.6] [1 rgb 1] } }
sphere { 0, 0.9
  pigment { rgbt 1 } hollow
  interior { media { method 2 intervals 4 samples 3 emission <1, 0.6, 0.3> absorption 0.5 density { Cloud } } }
  translate <-3, 1.6, 0>
}
sphere { 0, 0.9
  pigment { rgbt 1 } hollow
  interior {
    media { method 1 intervals 3 samples 5 emission <0.3, 0.6, 1> }  // constant emission: any position gives the same
    media { method 3 intervals 5 samples 4 aa_level 3 aa_threshold 0.05 scattering { 1, rgb 0.5 } ratio 0.7
            density { Cloud } }
  }
  translate <0, 1.6, 0>
}
sphere { 0, 0.9
  pigment { rgbt 1 } hollow
  interior {
    media { intervals 3 samples 7 aa_level 2 scattering { 1, rgb 0.8 } ratio 0.3 density { Cloud scale <1, 0.5, 1> } }
  }
  translate <3, 1.6, 0>
}
