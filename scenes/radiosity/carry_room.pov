#version 3.7;
// A small radiosity animation: a closed room, a small ball rolling along the left wall; the right half is still.
global_settings { assumed_gamma 1.0 radiosity { count 100 error_bound 0.5 recursion_limit 1 nearest_count 5 pretrace_start 0.08 pretrace_end 0.02 } }
camera { location <0, 2.5, -9> look_at <0, 2, 0> }
light_source { <0, 4.5, 0> color rgb 1 }
box { <-5, 0, -10>, <5, 5, 5> pigment { rgb 0.8 } inverse }
box { <2.5, 0, 1>, <4, 2, 2.5> pigment { rgb <0.9, 0.3, 0.2> } }
sphere { <-3.5, 0.6, -2 + 4 * clock>, 0.6 pigment { rgb <0.2, 0.9, 0.3> } }
