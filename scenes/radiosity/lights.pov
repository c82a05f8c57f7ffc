// box.pov's room lit by five lights of different kinds: a coloured point light, a faded one, a spotlight, a jittered
// area light and a shadowless fill. On gather paths a few of them are picked per hit (lighting/light_choice.h), so
// this scene checks that the picks repeat for any thread count and turn with --seed.
#version 3.7;
global_settings {
  assumed_gamma 1.0
  max_trace_level 5
  radiosity { count 100 error_bound 0.5 pretrace_start 0.08 pretrace_end 0.04 nearest_count 5 recursion_limit 2 }
}
camera { location <0, 1, -3.2> look_at <0, 1, 0> angle 50 }
light_source { <0, 1.9, 0> color rgb <1.0, 0.7, 0.5> }
light_source { <-0.7, 1.5, -0.6> color rgb <0.3, 0.5, 1.0> fade_distance 1 fade_power 2 }
light_source { <0.6, 1.8, 0.6> color rgb 1.2 spotlight point_at <0.3, 0, 0> radius 25 falloff 40 }
light_source { <0, 1.95, -0.5> color rgb 0.5 area_light 0.4*x, 0.4*z, 3, 3 jitter adaptive 1 }
light_source { <0, 1, -3> color rgb 0.1 shadowless }
#declare Wall = finish { diffuse 0.8 ambient 0 }
box { <-1.02, -0.02, -1>, <1.02, 0, 1.02> pigment { rgb 0.8 } finish { Wall } }
box { <-1.02, 2, -1>, <1.02, 2.02, 1.02> pigment { rgb 0.8 } finish { Wall } }
box { <-1.02, 0, 1>, <1.02, 2, 1.02> pigment { rgb 0.8 } finish { Wall } }
box { <-1.02, 0, -1>, <-1, 2, 1> pigment { rgb <0.8, 0.1, 0.1> } finish { Wall } }
box { <1, 0, -1>, <1.02, 2, 1> pigment { rgb <0.1, 0.8, 0.1> } finish { Wall } }
box { <-0.3, 0, -0.3>, <0.3, 0.6, 0.3> rotate y*20 translate <0.35, 0, -0.2> pigment { rgb 0.8 } finish { Wall } }
box { <-0.3, 0, -0.3>, <0.3, 1.2, 0.3> rotate -y*15 translate <-0.4, 0, 0.4> pigment { rgb 0.8 } finish { Wall } }
