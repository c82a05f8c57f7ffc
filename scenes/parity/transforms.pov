// Parity scene: translate, rotate (POV-Ray's x-then-y-then-z order), non-uniform scale, matrix, inverse, union.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <1, 3, -7> look_at <0, 1, 0> right x*image_width/image_height }
light_source { <-5, 8, -6> color rgb 1 }
background { rgb <0.2, 0.25, 0.3> }

plane { y, 0 pigment { rgb <0.7, 0.7, 0.7> } }
box { <-0.5, -0.5, -0.5>, <0.5, 0.5, 0.5> scale <1, 2, 0.5> rotate <20, 35, 10> translate <-2, 1.3, 0>
  pigment { rgb <0.9, 0.3, 0.3> } }
sphere { 0, 1 scale <1.2, 0.5, 0.8> rotate z*30 translate <0.5, 1, 0.5> pigment { rgb <0.3, 0.6, 0.9> } }
sphere { 0, 0.6 matrix <1, 0, 0, 0.5, 1, 0, 0, 0, 1, 2.3, 0.7, -1> pigment { rgb <0.9, 0.8, 0.3> } }
union {
  sphere { <0, 0.3, 0>, 0.3 }
  box { <-0.2, 0, -0.2>, <0.2, 0.9, 0.2> pigment { rgb <0.5, 0.9, 0.5> } }
  pigment { rgb <0.9, 0.5, 0.9> }
  translate <-0.6, 0, -2>
}
