// Parity scene: lathes of every spline type (linear, quadratic, cubic, Bézier), surfaces of revolution closed and
// open, and a lathe in CSG, on a floor under two point lights.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 4, -9> look_at <0, 0.8, 0> angle 50 }

light_source { <-5, 10, -6> color rgb 1 }
light_source { <6, 4, -3> color rgb 0.4 }

plane { y, 0 pigment { rgb <0.8, 0.8, 0.7> } finish { ambient 0.1 diffuse 0.7 } }

// A stepped linear profile (a turned chess-piece base).
lathe { linear_spline 8, <0, 0>, <0.9, 0>, <0.9, 0.3>, <0.5, 0.5>, <0.4, 1.5>, <0.7, 1.8>, <0.3, 2.2>, <0, 2.2>
  translate <-4.2, 0, 3> pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.5 } }

// A quadratic vase, open at the top so its inside shows.
lathe { quadratic_spline 7, <0, -0.2>, <0, 0>, <0.8, 0.1>, <0.5, 0.9>, <0.9, 1.6>, <0.85, 1.7>, <0.4, 1.4>
  sturm translate <-1.4, 0, 1.5> pigment { rgb <0.2, 0.5, 0.9> } finish { phong 0.4 } }

// A cubic (Catmull-Rom) bulb lying on its side.
lathe { cubic_spline 7, <-0.3, -0.3>, <0, 0>, <0.7, 0.3>, <0.4, 1.0>, <0.6, 1.5>, <0, 1.8>, <-0.3, 2.1>
  rotate <0, 0, 70> translate <1.3, 0.6, -0.2> pigment { rgb <0.3, 0.8, 0.3> } finish { phong 0.6 } }

// A Bézier torus-like ring (two segments closing a loop away from the axis).
lathe { bezier_spline 8,
  <1.0, 0>, <1.6, 0>, <1.6, 0.7>, <1.0, 0.7>,
  <1.0, 0.7>, <0.4, 0.7>, <0.4, 0>, <1.0, 0>
  scale 0.7 translate <3.2, 0, 1.6> pigment { rgb <0.9, 0.8, 0.2> } finish { phong 0.3 } }

// Surfaces of revolution: a closed goblet and an open tube.
sor { 8, <0, -0.1>, <0.6, 0>, <0.5, 0.1>, <0.1, 0.4>, <0.12, 1.0>, <0.6, 1.3>, <0.7, 1.8>, <0.75, 1.9>
  translate <0.8, 0, 2.4> pigment { rgb <0.7, 0.4, 0.9> } finish { phong 0.5 } }
sor { 6, <0.5, -0.5>, <0.4, 0>, <0.6, 0.6>, <0.3, 1.2>, <0.5, 1.6>, <0.6, 2> open
  rotate <-30, 0, 0> translate <-2.0, 0.6, -2.6> pigment { rgb <0.95, 0.6, 0.7> } }

// A lathe with a box cut out of it.
difference {
  lathe { linear_spline 5, <0, 0>, <0.8, 0>, <0.8, 0.9>, <0.3, 1.2>, <0, 1.2> }
  box { <0, 0.2, -1>, <1, 2, 0> }
  rotate <0, -30, 0> translate <3, 0, -1.8> pigment { rgb <0.4, 0.9, 0.9> }
}
