// Parity scene: every analytic primitive (cylinder, open cylinder, cone, torus, disc with hole, quadric,
// quartic, superellipsoid, triangle, smooth_triangle, polygon with a hole) on a floor under two point lights.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 4, -9> look_at <0, 0.3, 0> angle 50 }

light_source { <-5, 10, -6> color rgb 1 }
light_source { <6, 4, -3> color rgb 0.4 }

plane { y, -1 pigment { rgb <0.8, 0.8, 0.7> } finish { ambient 0.1 diffuse 0.7 } }

cylinder { <-3.5, -1, 0>, <-3.5, 1, 0>, 0.6 pigment { rgb <0.9, 0.2, 0.2> } finish { phong 0.6 } }
cylinder { <-3, 0, -2.5>, <-2, 0.5, -2.5>, 0.4 open pigment { rgb <0.9, 0.5, 0.1> } }
cone { <-1.5, -1, 0>, 0.8, <-1.5, 1.2, 0>, 0.2 pigment { rgb <0.2, 0.8, 0.2> } finish { phong 0.3 phong_size 20 } }
torus { 0.8, 0.3 sturm rotate <-60, 0, 0> translate <0.8, 0.2, 0> pigment { rgb <0.2, 0.4, 0.9> } finish { phong 0.5 } }
disc { <3.2, 0.2, 0>, <0, 0.5, -1>, 0.9, 0.3 pigment { rgb <0.9, 0.8, 0.1> } }
superellipsoid { <0.3, 0.6> scale 0.6 translate <-0.5, -0.4, -2.5> pigment { rgb <0.6, 0.3, 0.8> } }
// An infinite cylinder (quadric) bounded by a box through CSG.
intersection {
  quadric { <1, 0, 1>, <0, 0, 0>, <0, 0, 0>, -0.16 }
  box { <-1, -1, -1>, <1, 0.3, 1> }
  translate <1.5, 0, -2.5>
  pigment { rgb <0.3, 0.8, 0.8> }
}
triangle { <2.5, -1, 2>, <4, -1, 2>, <3.5, 1.5, 2.5> pigment { rgb <1, 0.4, 0.4> } }
smooth_triangle { <-4, -1, 2>, <-0.5, 0, -1>, <-2.5, -1, 2>, <0.5, 0, -1>, <-3.2, 1.5, 2.5>, <0, 0.5, -1>
  pigment { rgb <0.4, 1, 0.4> } }
polygon { 10, <0, 0>, <2, 0>, <2, 2>, <0, 2>, <0, 0>, <0.5, 0.5>, <1.5, 0.5>, <1.5, 1.5>, <0.5, 1.5>, <0.5, 0.5>
  translate <-1, -0.5, 2.5> pigment { rgb <0.9, 0.9, 0.3> } }
// A torus of major radius 0.6 and minor radius 0.2 as a general quartic:
// (x² + y² + z² + R² - r²)² - 4R²(x² + z²), bounded by itself.
quartic {
  < 1, 0, 0, 0,  2, 0, 0,  2, 0, -0.8,
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    1, 0, 0,  2, 0,  0.64,  0, 0, 0, 0,
    1, 0, -0.8, 0, 0.1024 >
  sturm
  rotate <-50, 0, 0>
  translate <2.7, -0.5, -1.4>
  pigment { rgb <0.95, 0.6, 0.7> } finish { phong 0.4 }
}
