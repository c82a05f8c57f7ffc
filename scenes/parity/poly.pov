// Parity scene: cubic, poly (orders 2 and 5) and polynomial (order 6) surfaces, with and without sturm, bounded by
// CSG or clipped_by, transformed, casting shadows on a floor.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 5, -12> look_at <0, 0.3, 0> angle 50 }

light_source { <-8, 14, -10> color rgb 1 }
light_source { <9, 6, -6> color rgb 0.35 }

plane { y, -1.5 pigment { rgb <0.8, 0.8, 0.7> } finish { ambient 0.1 diffuse 0.7 } }

#declare Fin = finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 60 }

// The monkey saddle x³ - 3xy² - z = 0 written as a cubic, in a sphere.
intersection {
  cubic { <1, 0, 0, 0, -3, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, -1, 0> sturm }
  sphere { 0, 1.2 }
  pigment { rgb <0.9, 0.5, 0.3> } finish { Fin } rotate x*-90 translate <-3.5, 0.5, 0>
}

// A product of two spheres and a plane, order 5: the spheres, split by the plane.
intersection {
  poly { 5, <0, 1, 0, -0.2, 0, 0, -2.4, 0, 0, 0.48, 2, 0, -0.4, 2, 0, -0.05, 0, -0.4, 0, 0.01, 0, 0, -2.4, 0, 0,
             0.48, 0, -2.4, 0, 2.4, 0, 0, 0.48, 0, -0.48, 1, 0, -0.2, 2, 0, -0.05, 0, -0.4, 0, 0.01, 1, 0, -0.05,
             0, -0.95, 0, -0.2, 0, 0.01, 0, 0.19> }
  box { -2, 2 }
  pigment { rgb <0.9, 0.8, 0.3> } finish { Fin } scale 0.9 translate <1.5, -0.5, -3>
}

// Order 6: the rounded cube x⁶ + y⁶ + z⁶ = 1 from polynomial terms, clipped.
polynomial { 6, xyz(6, 0, 0): 1, xyz(0, 6, 0): 1, xyz(0, 0, 6): 1, xyz(0, 0, 0): -1
  sturm
  clipped_by { plane { z, 0.6 } }
  pigment { rgb <0.9, 0.3, 0.4> } finish { Fin } rotate <30, 40, 0> translate <3.5, 0.3, 0>
}

// The unit sphere as poly 2, a box taken out of it.
difference {
  poly { 2, <1, 0, 0, 0, 1, 0, 0, 1, 0, -1> }
  box { <0, 0, -2>, <2, 2, 0> }
  pigment { rgb <0.6, 0.9, 0.5> } finish { Fin } scale 0.8 translate <-1.5, -0.6, -2.5>
}
