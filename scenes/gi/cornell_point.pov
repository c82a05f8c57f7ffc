// GI scene: a Cornell-like box (red and green side walls) lit by one point light under the ceiling.
// Most of what the walls receive is indirect, so the colour bleeding shows the cache's error directly.
#version 3.7;
global_settings {
  assumed_gamma 1.0
  radiosity {
    pretrace_start 0.08
    pretrace_end 0.02
    count 100
    nearest_count 10
    error_bound 0.4
    recursion_limit 2
  }
}

camera { location <0, 1, -3.4> look_at <0, 1, 0> angle 48 }
light_source { <0, 1.85, 0> color rgb 1.2 }

#declare Wall = finish { ambient 0 diffuse 0.75 }
#declare White = texture { pigment { rgb 0.8 } finish { Wall } }

box { <-1, -0.01, -1>, <1, 0, 1> texture { White } }                           // floor
box { <-1, 2, -1>, <1, 2.01, 1> texture { White } }                            // ceiling
box { <-1, 0, 1>, <1, 2, 1.01> texture { White } }                             // back wall
box { <-1.01, 0, -1>, <-1, 2, 1> pigment { rgb <0.75, 0.1, 0.1> } finish { Wall } }  // left: red
box { <1, 0, -1>, <1.01, 2, 1> pigment { rgb <0.1, 0.7, 0.1> } finish { Wall } }     // right: green

box { <-0.3, 0, -0.3>, <0.3, 1.2, 0.3> rotate y * 20 translate <-0.35, 0, 0.3> texture { White } }
sphere { <0.45, 0.35, -0.3>, 0.35 texture { White } }
