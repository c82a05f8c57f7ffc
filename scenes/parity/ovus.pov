// Parity scene: ovus with a bigger bottom, equal radii, a bigger top, a thin top, the top sphere substituted for
// top >= 2 bottom, transformed, cut by a box in CSG (its inside test), casting shadows on a floor.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 4, -11> look_at <0, 0.6, 0> angle 50 }

light_source { <-8, 14, -10> color rgb 1 }
light_source { <9, 6, -6> color rgb 0.35 }

plane { y, -1.2 pigment { checker rgb <0.8, 0.8, 0.7> rgb <0.6, 0.6, 0.55> } finish { ambient 0.1 diffuse 0.7 } }

#declare Fin = finish { ambient 0.1 diffuse 0.7 phong 0.6 phong_size 40 }

// The classic egg.
ovus { 1, 0.6 pigment { rgb <0.95, 0.85, 0.7> } finish { Fin } translate <-3.5, -0.2, 0> }

// Equal radii: a capsule-like egg.
ovus { 0.7, 0.7 pigment { rgb <0.4, 0.7, 0.9> } finish { Fin } rotate z*25 translate <-1.2, -0.5, 1> }

// A bigger top.
ovus { 0.5, 0.8 pigment { rgb <0.9, 0.5, 0.3> } finish { Fin } translate <1.2, -0.7, 0.5> }

// A thin top, stretched and tilted.
ovus { 0.8, 0.2 pigment { rgb <0.6, 0.9, 0.5> } finish { Fin } scale <1, 1.4, 0.8> rotate <-20, 30, 0>
  translate <3.6, -0.1, 0> }

// Top >= 2 bottom: POV-Ray draws the top sphere alone (with a warning).
ovus { 0.3, 0.7 pigment { rgb <0.8, 0.6, 0.9> } finish { Fin } translate <2.6, 1.9, 3> }

// An egg cut open by a box: the cut face shows where the ovus is inside.
difference {
  ovus { 1, 0.5 }
  box { <-2, 0.3, -2>, <0, 3, 0> }
  pigment { rgb <0.9, 0.9, 0.4> } finish { Fin } rotate y*-40 translate <-1.6, -0.2, -2.8>
}

// In a merge with a sphere, lying on its side.
merge {
  ovus { 0.6, 0.45 rotate z*90 }
  sphere { <0.9, 0, 0>, 0.35 }
  pigment { rgb <0.5, 0.5, 0.9> } finish { Fin } translate <1.6, -0.6, -3.2>
}
