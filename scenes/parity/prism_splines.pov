// Parity scene: prisms with quadratic, cubic and Bézier outlines (one with a hole), linear and conic sweeps,
// open and closed, on a floor under two point lights.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 5, -9> look_at <0, 0.5, 0> angle 50 }

light_source { <-5, 10, -6> color rgb 1 }
light_source { <6, 4, -3> color rgb 0.4 }

plane { y, 0 pigment { rgb <0.8, 0.8, 0.7> } finish { ambient 0.1 diffuse 0.7 } }

// A quadratic blob: a control point before the first curve point, closing on it.
prism { quadratic_spline linear_sweep 0, 1, 7,
  <0.8, -0.8>, <1, 0>, <0, 1>, <-1, 0>, <0, -1>, <1, 0>, <0, 1>
  translate <-3, 0, 1> pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.5 } }

// A cubic four-pointed star with a small cubic hole.
prism { cubic_spline 0, 0.6, 18,
  <0, -1.4>, <1.2, 0>, <0.4, 0.4>, <0, 1.2>, <-0.4, 0.4>, <-1.2, 0>, <-0.4, -0.4>, <0, -1.2>, <0.4, -0.4>, <1.2, 0>, <0.4, 0.4>,
  <0.3, 0.3>, <0.3, 0>, <0, -0.3>, <-0.3, 0>, <0, 0.3>, <0.3, 0>, <0, -0.3>
  translate <-0.6, 0, 2> pigment { rgb <0.2, 0.5, 0.9> } finish { phong 0.4 } }

// A Bézier heart, turned on its side.
prism { bezier_spline 0, 0.4, 8,
  <0, -1>, <0.8, -0.4>, <1.2, 0.8>, <0, 0.4>,
  <0, 0.4>, <-1.2, 0.8>, <-0.8, -0.4>, <0, -1>
  rotate <-90, 0, 0> translate <1.6, 1.1, 0.2> pigment { rgb <0.9, 0.2, 0.5> } finish { phong 0.6 } }

// A conic cubic cup, open.
prism { conic_sweep cubic_spline 0.4, 1, 8,
  <-1, -1>, <1, 0>, <0, 1>, <-1, 0>, <0, -1>, <1, 0>, <0, 1>, <-1, 0>
  open rotate <180, 0, 0> translate <3.4, 1, 1.2> pigment { rgb <0.3, 0.8, 0.3> } }

// A Bézier disc of four quarter arcs lying on the floor.
prism { bezier_spline 0, 0.3, 16,
  <1, 0>, <1, 0.55>, <0.55, 1>, <0, 1>,
  <0, 1>, <-0.55, 1>, <-1, 0.55>, <-1, 0>,
  <-1, 0>, <-1, -0.55>, <-0.55, -1>, <0, -1>,
  <0, -1>, <0.55, -1>, <1, -0.55>, <1, 0>
  scale 0.8 translate <-1.8, 0, -1.6> pigment { rgb <0.9, 0.8, 0.2> } finish { phong 0.3 } }
