// Cylinder lights: parallel beams limited to a cylinder around their axis, with radius, falloff and tightness,
// one of them faded with distance, over a floor and a few objects.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 7, -8> look_at <0, 0, 0.5> angle 60 }
light_source { <0, 10, -10> color rgb 0.15 }
light_source { <-2, 6, 0> color rgb <1, 0.6, 0.4> cylinder point_at <-2, 0, 0.5> radius 1 falloff 1.8 }
light_source {
  <2, 8, 1> color rgb <0.4, 0.7, 1> cylinder point_at <1.5, 0, 0> radius 0.5 falloff 2.5 tightness 3
  fade_distance 6 fade_power 2
}
light_source { <0, 3, -6> color rgb 0.8 cylinder point_at <0, 0.5, 3> }  // the defaults: radius 0.75, falloff 1
plane { y, 0 pigment { rgb 0.8 } }
sphere { <-2, 0.7, 0.5>, 0.7 pigment { rgb <0.9, 0.9, 0.5> } }
box { <1, 0, -0.5>, <2.2, 1.2, 0.7> pigment { rgb 0.9 } }
cylinder { <0, 0, 2>, <0, 1.5, 2>, 0.4 pigment { rgb <0.6, 0.9, 0.6> } }
