// GI scene: a room without light sources, lit only through a window by a sky_sphere.
// Everything seen inside is indirect light gathered from the sky, one or more bounces deep.
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

camera { location <-1.6, 1.1, -1.6> look_at <0.6, 0.8, 1> angle 70 }

sky_sphere {
  pigment { gradient y color_map { [0 rgb <2.5, 2.4, 2.1>] [0.5 rgb <1.1, 1.5, 2.5>] [1 rgb <0.5, 0.9, 2.2>] } }
}

#declare Wall = texture { pigment { rgb 0.75 } finish { ambient 0 diffuse 0.8 } }

box { <-2, -0.1, -2>, <2, 0, 2> texture { Wall } }                   // floor
box { <-2, 2.5, -2>, <2, 2.6, 2> texture { Wall } }                  // ceiling
box { <-2.1, 0, -2>, <-2, 2.5, 2> texture { Wall } }                 // left wall
box { <-2, 0, -2.1>, <2, 2.5, -2> texture { Wall } }                 // front wall (behind the camera)
box { <-2, 0, 2>, <2, 2.5, 2.1> texture { Wall } }                   // back wall
// Right wall with a window: four boxes around the opening z in [-0.8, 0.8], y in [0.8, 2.0].
box { <2, 0, -2>, <2.1, 0.8, 2> texture { Wall } }
box { <2, 2.0, -2>, <2.1, 2.5, 2> texture { Wall } }
box { <2, 0.8, -2>, <2.1, 2.0, -0.8> texture { Wall } }
box { <2, 0.8, 0.8>, <2.1, 2.0, 2> texture { Wall } }

box { <-0.4, 0, 0.6>, <0.6, 0.7, 1.4> pigment { rgb <0.8, 0.55, 0.3> } finish { ambient 0 diffuse 0.8 } }
sphere { <-0.9, 0.4, 0.2>, 0.4 pigment { rgb <0.3, 0.45, 0.8> } finish { ambient 0 diffuse 0.8 } }
