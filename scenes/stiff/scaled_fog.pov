// scaled.pov's scene in fog whose every length is a multiple of S too: a tilted, turbulent ground fog (distance,
// fog_offset and fog_alt times S, the turbulence vector over S) and a thin constant fog, with a light dimmed by
// them. Its image should not depend on S (tests/render/stiff_scene_test.cpp).
#version 3.7;
#ifndef (S)
  #declare S = 1;
#end
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.2, -6.5> * S look_at <0, 1.4, 0> * S angle 60 }
light_source { <-4, 7, -5> * S color rgb <1.0, 0.95, 0.88> media_attenuation on }
light_source { <5, 4, -2> * S color rgb <0.3, 0.35, 0.5> fade_distance 6 * S fade_power 2 }
background { rgb <0.2, 0.3, 0.6> }
fog { fog_type 2 distance 6 * S color rgb <0.85, 0.8, 0.75> fog_offset 0.3 * S fog_alt 0.6 * S
      up <0.1, 1, 0> turbulence <2, 3, 2> / S turb_depth 1 }
fog { distance 40 * S color rgbft <0.5, 0.6, 0.9, 0.4, 0.1> }
plane { y, 0 pigment { rgb <0.75, 0.72, 0.65> } finish { ambient 0.08 diffuse 0.75 } }
sphere { <-1.6, 1, 0.4> * S, S pigment { rgb <0.8, 0.18, 0.12> } finish { ambient 0.08 phong 0.4 } }
union {
  sphere { <1.5, 0.6, -0.8>, 0.6 pigment { rgb <0.15, 0.45, 0.8> } }
  box { <-0.5, 0, -0.5>, <0.5, 1.6, 0.5> rotate y * 30 translate <0.4, 0, 1.2> pigment { rgb 0.7 } }
  cylinder { <2.6, 0, 1>, <2.6, 1.8, 1>, 0.3 pigment { rgb <0.9, 0.8, 0.2> } finish { reflection 0.3 } }
  scale S
}
