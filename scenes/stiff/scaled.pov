// A scene whose every length is a multiple of S (camera, lights and their fade distances, geometry, through
// explicit products and through `scale S`): its image should not depend on S. Render it with Declare=S=1e-6
// ... Declare=S=1e6 (tools/scale_report.py; tests/render/stiff_scene_test.cpp).
#version 3.7;
#ifndef (S)
  #declare S = 1;
#end
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.2, -6.5> * S look_at <0, 0.8, 0> * S angle 50 }
light_source { <-4, 7, -5> * S color rgb <1.0, 0.95, 0.88> }
light_source { <5, 4, -2> * S color rgb <0.3, 0.35, 0.5> fade_distance 6 * S fade_power 2 }
plane { y, 0 pigment { rgb <0.75, 0.72, 0.65> } finish { ambient 0.08 diffuse 0.75 } }
plane { z, 4 * S pigment { rgb <0.6, 0.62, 0.7> } finish { ambient 0.08 diffuse 0.75 } }
sphere { <-1.6, 1, 0.4> * S, S pigment { rgb <0.8, 0.18, 0.12> } finish { ambient 0.08 phong 0.4 } }
union {
  sphere { <1.5, 0.6, -0.8>, 0.6 pigment { rgb <0.15, 0.45, 0.8> } }
  box { <-0.5, 0, -0.5>, <0.5, 1.6, 0.5> rotate y * 30 translate <0.4, 0, 1.2> pigment { rgb 0.7 } }
  triangle { <-3, 0, 2>, <-2, 2.5, 3>, <-1, 0, 3> pigment { rgb <0.3, 0.8, 0.3> } }
  cylinder { <2.6, 0, 1>, <2.6, 1.8, 1>, 0.3 pigment { rgb <0.9, 0.8, 0.2> } }
  scale S
}
