// Parity scene: sphere sweeps of every spline type (linear, b_spline, cubic_spline) with varying radii, one
// transformed, one cut by a box (its inside test), on a floor under a point light.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 4, -9> look_at <0, 0.9, 0> angle 50 }

light_source { <-5, 10, -6> color rgb 1 }

plane { y, 0 pigment { rgb <0.8, 0.8, 0.7> } finish { ambient 0.1 diffuse 0.7 } }

// A zigzag of straight segments: spheres joined by cones.
sphere_sweep { linear_spline 5,
  <-4.5, 0.3, 1>, 0.3, <-3.8, 1.8, 1.4>, 0.15, <-3.1, 0.4, 1.0>, 0.35, <-2.4, 1.9, 0.6>, 0.2, <-2.0, 0.5, 0>, 0.1
  pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.5 } }

// A B-spline loop (approximating its control spheres), tilted.
sphere_sweep { b_spline 8,
  <1, 0, 0>, 0.25, <0, 0, 1>, 0.15, <-1, 0, 0>, 0.3, <0, 0, -1>, 0.2,
  <1, 0, 0>, 0.25, <0, 0, 1>, 0.15, <-1, 0, 0>, 0.3, <0, 0, -1>, 0.2
  tolerance 1e-4
  scale <1.2, 1, 0.9> rotate <-35, 20, 0> translate <-0.3, 1.2, 2.2>
  pigment { rgb <0.2, 0.5, 0.9> } finish { phong 0.4 } }

// A Catmull-Rom spline through its inner control spheres, rising like a spring.
sphere_sweep { cubic_spline 9,
  <0.0, -0.3, -0.8>, 0.1, <0.8, 0.0, 0>, 0.12, <0, 0.35, 0.8>, 0.16, <-0.8, 0.7, 0>, 0.2, <0, 1.05, -0.8>, 0.24,
  <0.8, 1.4, 0>, 0.2, <0, 1.75, 0.8>, 0.16, <-0.8, 2.1, 0>, 0.12, <-1.2, 2.3, -0.5>, 0.1
  translate <3.2, 0, 0.8> pigment { rgb <0.3, 0.8, 0.3> } finish { phong 0.6 } }

// A box with a swept groove carved out of it.
difference {
  box { <-1, 0, -0.6>, <1, 0.8, 0.6> }
  sphere_sweep { cubic_spline 5, <-2, 0.8, -1>, 0.2, <-1.2, 0.8, 0>, 0.3, <0, 0.7, 0.1>, 0.35, <1.2, 0.8, 0>, 0.3,
    <2, 0.8, 1>, 0.2 }
  rotate <0, 15, 0> translate <0.6, 0, -2.2> pigment { rgb <0.9, 0.8, 0.3> } finish { phong 0.3 }
}
