// The radiosity box with every length a multiple of S: the cache's radii, its behind test and the ray offsets
// must all scale, so the image should not depend on S. Render it with Declare=S=1e-6 ... Declare=S=1e6
// (tools/scale_report.py --scene scenes/stiff/scaled_radiosity.pov; tests/render/stiff_scene_test.cpp).
#version 3.7;
#ifndef (S)
  #declare S = 1;
#end
global_settings {
  assumed_gamma 1.0
  radiosity { count 100 error_bound 0.5 pretrace_start 0.08 pretrace_end 0.02 nearest_count 8 recursion_limit 2 }
}
camera { location <0, 1, -3.2> * S look_at <0, 1, 0> * S angle 50 }
light_source { <0, 1.9, 0> * S color rgb 1.5 fade_distance 2 * S fade_power 1 }
union {
  #declare Wall = finish { diffuse 0.8 ambient 0 }
  box { <-1.02, -0.02, -1>, <1.02, 0, 1.02> pigment { rgb 0.8 } finish { Wall } }
  box { <-1.02, 2, -1>, <1.02, 2.02, 1.02> pigment { rgb 0.8 } finish { Wall } }
  box { <-1.02, 0, 1>, <1.02, 2, 1.02> pigment { rgb 0.8 } finish { Wall } }
  box { <-1.02, 0, -1>, <-1, 2, 1> pigment { rgb <0.8, 0.1, 0.1> } finish { Wall } }
  box { <1, 0, -1>, <1.02, 2, 1> pigment { rgb <0.1, 0.8, 0.1> } finish { Wall } }
  sphere { <0.35, 0.35, -0.2>, 0.35 pigment { rgb 0.8 } finish { Wall } }
  box { <-0.3, 0, -0.3>, <0.3, 1.2, 0.3> rotate -y*15 translate <-0.4, 0, 0.4> pigment { rgb 0.8 } finish { Wall } }
  scale S
}
