// Parity scene: objects a light carries, looks_like (drawn at the light, casting no shadow, moved with it) and
// projected_through (the light reaches only what sees it through the object, which casts no shadow itself).
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 4, -10> look_at <0, 1, 0> angle 55 }
light_source { <-8, 12, -10> color rgb 0.4 }

plane { y, 0 pigment { rgb <0.85, 0.85, 0.8> } }
plane { z, 3 pigment { rgb <0.5, 0.6, 0.8> } }

// A bulb: its globe sits where the light is and lets the light out.
#declare Bulb = light_source { <0, 0, 0> color rgb <1, 0.9, 0.7>
  looks_like { sphere { 0, 0.3 pigment { rgb 1 } finish { ambient 1 diffuse 0 } } }
}
light_source { Bulb translate <-2.5, 2, -1> }

// A window: a ring and a box the light is projected through; the placed copy casts no shadow from this light.
#declare Window = union {
  torus { 0.6, 0.12 rotate x*90 }
  box { <-0.2, -0.2, -0.05>, <0.2, 0.2, 0.05> translate x*1.1 }
  translate <1.5, 3.5, -1.5>
}
object { Window pigment { rgb <0.9, 0.8, 0.2> } }
light_source { <2, 6, -3> color rgb 1.5 projected_through { Window } }
sphere { <1.5, 0.6, 1>, 0.6 pigment { rgb <0.3, 0.8, 0.4> } }
