// GI scene: a closed box lit only by an emissive ceiling panel; there is no light_source at all.
// Direct light from the panel reaches the walls only through radiosity, so the whole image is the GI estimate.
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

camera { location <0, 1, -2.9> look_at <0, 0.9, 0> angle 55 }

#declare Wall = finish { ambient 0 diffuse 0.8 }

box { <-1.5, -0.1, -3>, <1.5, 0, 1.5> pigment { rgb 0.7 } finish { Wall } }        // floor
box { <-1.5, 2, -3>, <1.5, 2.1, 1.5> pigment { rgb 0.7 } finish { Wall } }         // ceiling
box { <-1.5, 0, 1.5>, <1.5, 2, 1.6> pigment { rgb <0.6, 0.65, 0.75> } finish { Wall } }  // back wall
box { <-1.6, 0, -3>, <-1.5, 2, 1.5> pigment { rgb <0.8, 0.6, 0.3> } finish { Wall } }    // left wall
box { <1.5, 0, -3>, <1.6, 2, 1.5> pigment { rgb 0.7 } finish { Wall } }            // right wall
box { <-1.5, 0, -3.1>, <1.5, 2, -3> pigment { rgb 0.7 } finish { Wall } }          // front wall, behind the camera

// The panel: a thin slab just under the ceiling, emitting and reflecting nothing.
box { <-0.5, 1.97, -0.2>, <0.5, 1.99, 0.6> pigment { rgb 1 } finish { ambient 0 diffuse 0 emission 6 } }

box { <-0.9, 0, 0.3>, <-0.2, 0.9, 1.0> rotate y * -15 pigment { rgb 0.75 } finish { Wall } }
sphere { <0.6, 0.3, 0.2>, 0.3 pigment { rgb <0.2, 0.6, 0.8> } finish { Wall } }
