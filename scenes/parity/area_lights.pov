// Area lights: soft shadows from a full grid, an adaptive grid, a circular and an oriented light, and a spotlight
// with an area, all without jitter so both renderers sample the same points.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 6, -9> look_at <0, 0.5, 0> angle 55 }
light_source { <-4, 7, -3> color rgb 0.5 area_light 3*x, 3*z, 5, 5 }
light_source { <5, 5, -2> color rgb <0.4, 0.35, 0.3> area_light 2*x, 2*y, 9, 9 adaptive 1 }
light_source { <0, 8, 4> color rgb <0.2, 0.25, 0.35> area_light 4*x, 4*z, 6, 6 circular orient }
light_source {
  <3, 9, 3> color rgb 0.4
  spotlight point_at <0, 0, 0> radius 20 falloff 35
  area_light 2*x, 2*z, 4, 4 adaptive 0
}
plane { y, 0 pigment { rgb 0.8 } }
sphere { <-1.5, 1, 0>, 1 pigment { rgb <0.9, 0.4, 0.3> } }
box { <0.5, 0, -0.8>, <2.3, 1.6, 0.8> rotate y*25 pigment { rgb <0.3, 0.6, 0.9> } }
cylinder { <-0.3, 0, 2>, <-0.3, 2.5, 2>, 0.3 pigment { rgb 0.9 } }
