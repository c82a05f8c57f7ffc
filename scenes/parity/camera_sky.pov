// A perspective camera with a tilted sky, a wide non-square right vector, an explicit direction and angle, then
// transformed: POV-Ray's order of applying them decides every pixel.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera {
  location <3, 4, -6>
  direction 1.5*z
  right 1.6*x
  up 0.9*y
  sky <0.3, 1, 0>
  angle 70
  look_at <0, 0.5, 0>
  rotate y*10
  translate <0.2, 0, 0>
}
light_source { <-5, 8, -4> color rgb 1 }
plane { y, 0 pigment { checker rgb 0.9, rgb 0.3 } }
sphere { <0, 1, 0>, 1 pigment { rgb <0.9, 0.4, 0.2> } }
box { <1.5, 0, -1>, <2.5, 2, 0> pigment { rgb <0.3, 0.5, 0.9> } }
