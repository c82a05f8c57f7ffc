// Parity scene: bicubic patches as POV-Ray tessellates them: a saddle subdivided to its steps (type 1), a wave
// stopped early by its flatness after scaling (type 0), a flat patch, and a patch in a transformed union.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 5, -10> look_at <0, 0.5, 0> angle 50 }

light_source { <-5, 10, -6> color rgb 1 }
light_source { <6, 4, -3> color rgb 0.4 }

plane { y, -1 pigment { rgb <0.8, 0.8, 0.7> } finish { ambient 0.1 diffuse 0.7 } }

// objects/bezier.pov's saddle.
bicubic_patch { type 1 flatness 0.1 u_steps 8 v_steps 8
  <0, 0, 2>, <1, 0, 0>, <2, 0, 0>, <3, 0, -2>,
  <0, 1, 0>, <1, 1, 0>, <2, 1, 0>, <3, 1, 0>,
  <0, 2, 0>, <1, 2, 0>, <2, 2, 0>, <3, 2, 0>,
  <0, 3, 2>, <1, 3, 0>, <2, 3, 0>, <3, 3, -2>
  pigment { checker color rgb <0.9, 0.1, 0.1> color rgb 1 rotate 90*x }
  finish { ambient 0.1 diffuse 0.9 phong 1 }
  translate <-1.5, -1.5, 0> scale 0.8 rotate <60, -30, 0> translate <-2.6, 1.5, 1>
}

// A wave with coarse flatness: the facets show on its outline and in its shading.
bicubic_patch { type 0 flatness 0.05 u_steps 3 v_steps 4
  <0, 0, 0>, <1, 1, 0>, <2, -1, 0>, <3, 0, 0>,
  <0, 0.5, 1>, <1, 1.5, 1>, <2, -0.5, 1>, <3, 0.5, 1>,
  <0, 0, 2>, <1, 1, 2>, <2, -1, 2>, <3, 0, 2>,
  <0, 0.5, 3>, <1, 1.5, 3>, <2, -0.5, 3>, <3, 0.5, 3>
  pigment { rgb <0.2, 0.5, 0.9> } finish { phong 0.6 }
  scale 0.9 rotate 20*y translate <0.4, 0.2, 0.5>
}

// A flat patch (two triangles) and a bump, both in a union that is scaled and turned as a whole.
union {
  bicubic_patch { type 1 u_steps 3 v_steps 3
    <0, 0, 0>, <1, 0, 0>, <2, 0, 0>, <3, 0, 0>,
    <0, 0, 1>, <1, 0, 1>, <2, 0, 1>, <3, 0, 1>,
    <0, 0, 2>, <1, 0, 2>, <2, 0, 2>, <3, 0, 2>,
    <0, 0, 3>, <1, 0, 3>, <2, 0, 3>, <3, 0, 3>
    pigment { rgb <0.9, 0.8, 0.2> } }
  bicubic_patch { type 1 flatness 0.01 u_steps 4 v_steps 4
    <0, 0, 0>, <1, 0, 0>, <2, 0, 0>, <3, 0, 0>,
    <0, 0, 1>, <1, 2, 1>, <2, 2, 1>, <3, 0, 1>,
    <0, 0, 2>, <1, 2, 2>, <2, 2, 2>, <3, 0, 2>,
    <0, 0, 3>, <1, 0, 3>, <2, 0, 3>, <3, 0, 3>
    pigment { rgb <0.3, 0.8, 0.3> } finish { phong 0.5 } translate 3.2*x }
  scale 0.6 rotate -15*y translate <1.2, -0.5, -2.5>
}
