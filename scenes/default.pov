// wardray's default scene: what `wardray` renders with no scene argument.
// Spheres, boxes and a floor under two point lights with shadows; direct light only.
#version 3.7;

global_settings { assumed_gamma 1.0 }

#declare Matte = finish { ambient 0.08 diffuse 0.75 }

camera {
  location <0, 2.2, -6.5>
  look_at  <0, 0.8, 0>
  angle 50
}

light_source { <-4, 7, -5> color rgb <1.0, 0.95, 0.88> }
light_source { <5, 4, -2> color rgb <0.25, 0.3, 0.45> fade_distance 6 fade_power 2 }

background { color rgb <0.55, 0.65, 0.8> }

// Floor and back wall.
plane { y, 0 pigment { rgb <0.75, 0.72, 0.65> } finish { Matte } }
plane { z, 4 pigment { rgb <0.6, 0.62, 0.7> } finish { Matte } }

sphere { <-1.6, 1, 0.4>, 1 pigment { rgb <0.8, 0.18, 0.12> } finish { Matte phong 0.4 phong_size 60 } }
sphere { <1.5, 0.6, -0.8>, 0.6 pigment { rgb <0.15, 0.45, 0.8> } finish { Matte } }
sphere { <0.2, 0.35, -1.9>, 0.35 pigment { rgb <0.9, 0.8, 0.2> } finish { Matte } }

box { <-0.5, 0, -0.5>, <0.5, 1.6, 0.5>
  rotate y*30
  translate <0.4, 0, 1.2>
  pigment { rgb <0.3, 0.7, 0.35> }
  finish { Matte }
}
box { <-3.5, 0, 1.5>, <-2.4, 0.5, 3.2> pigment { rgb 0.9 } finish { Matte } }
