// Parity scene: isosurfaces in box and sphere containers, closed and open, with threshold, max_trace and
// all_intersections, internal functions of functions.inc (noise among them), transformed and in CSG.
#version 3.7;
#include "functions.inc"
global_settings { assumed_gamma 1.0 }

camera { location <0, 5, -10> look_at <0, 0.6, 0> angle 52 }

light_source { <-6, 12, -8> color rgb 1 }
light_source { <7, 5, -4> color rgb 0.35 }

plane { y, -1 pigment { rgb <0.8, 0.8, 0.7> } finish { ambient 0.1 diffuse 0.7 } }

#declare Fin = finish { ambient 0.1 diffuse 0.7 phong 0.4 }

// A sphere cut by its box container: the closed caps show.
isosurface { function { sqrt(x*x + y*y + z*z) - 1.2 } contained_by { box { -1, 1 } }
  pigment { rgb <0.9, 0.3, 0.2> } finish { Fin } translate <-4, 0, 2> }

// A torus from functions.inc with a threshold, stretched and turned.
isosurface { function { f_torus(x, y, z, 0.8, 0.1) } threshold 0.15 contained_by { box { <-1.1, -0.3, -1.1>, <1.1, 0.3, 1.1> } }
  pigment { rgb <0.2, 0.5, 0.9> } finish { Fin } scale <1, 1.5, 0.8> rotate <-50, 20, 0> translate <-1.3, 0.2, 2> }

// Noise displacement in a sphere container, with a higher max_gradient.
isosurface { function { sqrt(x*x + y*y + z*z) - 0.85 + f_noise3d(x*4, y*4, z*4)*0.3 } max_gradient 3
  contained_by { sphere { 0, 1.1 } } pigment { rgb <0.3, 0.8, 0.3> } finish { Fin } translate <1.4, 0.2, 2> }

// An open wave sheet: the container leaves no caps.
isosurface { function { y - sin(x*3)*cos(z*3)*0.3 } open max_gradient 2 contained_by { box { <-1, -0.5, -1>, <1, 0.5, 1> } }
  pigment { rgb <0.9, 0.8, 0.2> } finish { Fin } rotate <0, 30, 0> translate <4, 0, 2> }

// A heart, a rounded box and a superellipsoid of functions.inc in front.
isosurface { function { -f_heart(x, y, z, 1) } contained_by { box { -1.5, 1.5 } } max_gradient 30
  pigment { rgb <0.9, 0.2, 0.5> } finish { Fin } rotate <90, 0, 0> scale 0.8 translate <-3.6, 0.2, -1.5> }
isosurface { function { f_rounded_box(x, y, z, 0.2, 0.8, 0.5, 0.6) } contained_by { box { -1, 1 } }
  pigment { rgb <0.6, 0.4, 0.9> } finish { Fin } rotate <0, 35, 0> translate <-1.2, -0.4, -1.5> }

// all_intersections in CSG: a hollow shell cut open by a box.
difference {
  isosurface { function { abs(sqrt(x*x + y*y + z*z) - 0.8) - 0.08 } all_intersections contained_by { sphere { 0, 1 } } }
  box { <-1, 0, -1>, <1, 1.2, 0> }
  pigment { rgb <0.9, 0.5, 0.1> } finish { Fin } rotate <0, -30, 0> translate <1.2, 0, -1.5> }

// max_trace 2 and an intersection with a sphere: the inside test of the isosurface.
intersection {
  isosurface { function { f_helix1(x, y, z, 2, 3, 0.15, 0.6, 1, 1, 0) } max_trace 2 max_gradient 3.5
    contained_by { box { <-1, -1, -1>, <1, 1, 1> } } }
  sphere { 0, 0.95 }
  pigment { rgb <0.2, 0.8, 0.8> } finish { Fin } translate <3.8, 0, -1.5> }
