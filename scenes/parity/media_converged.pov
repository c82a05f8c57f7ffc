// Random media sampling, compared converged against converged: method 1 with min and max samples, confidence and
// variance (more samples where the estimate varies), and method 3 with jitter. Both renderers draw random positions,
// so the sample counts are high enough for their noise to stay well below the parity tolerance.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -10> look_at <0, 1.5, 0> angle 30 }
light_source { <-6, 8, -6> color rgb 1 }
plane { y, 0 pigment { checker rgb 0.8, rgb 0.4 } }
plane { -z, -3 pigment { rgb 0.5 } }
#declare Cloud = density { spherical color_map { [0 rgb 0] [0.5 rgb 0.6] [1 rgb 1] } }
sphere { 0, 0.6
  pigment { rgbt 1 } hollow
  interior {
    media { method 1 intervals 4 samples 200, 600 confidence 0.95 variance 1/1000 emission <0.3, 0.6, 1> * 2
            density { Cloud } }
  }
  translate <-1, 1.5, 0>
}
sphere { 0, 0.6
  pigment { rgbt 1 } hollow
  interior {
    media { method 3 intervals 2 samples 30 jitter 0.8 aa_level 3 emission <1, 0.6, 0.3> * 2 absorption 1
            density { Cloud } }
  }
  translate <1, 1.5, 0>
}
