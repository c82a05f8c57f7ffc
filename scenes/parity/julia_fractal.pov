// Parity scene: julia_fractal in both algebras (quaternion sqr and cube, hypercomplex sqr, reciprocal and pwr),
// max_iteration, precision, a slice, transforms, one cut by a box in CSG, casting shadows on a floor.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 4, -11> look_at <0, 0.4, 0> angle 48 }

light_source { <-8, 14, -10> color rgb 1 }
light_source { <9, 6, -6> color rgb 0.35 }

plane { y, -1.6 pigment { rgb <0.8, 0.8, 0.7> } finish { ambient 0.1 diffuse 0.7 } }

#declare Fin = finish { ambient 0.1 diffuse 0.7 phong 0.5 phong_size 60 }

// Quaternion z² + c.
julia_fractal { <-0.083, 0.0, -0.83, -0.025> quaternion sqr max_iteration 8 precision 20
  pigment { rgb <0.9, 0.5, 0.3> } finish { Fin } translate <-3.6, 1.8, 0> }

// Quaternion z³ + c, scaled and turned.
julia_fractal { <-0.03, 0.5, -0.2, -0.5> quaternion cube max_iteration 8 precision 30
  pigment { rgb <0.4, 0.7, 0.9> } finish { Fin } rotate y*40 scale 1.2 translate <0, 1.8, 0> }

// Hypercomplex z² + c.
julia_fractal { <0.2, 0.1, 0.59, -0.2> hypercomplex sqr max_iteration 7 precision 20
  pigment { rgb <0.8, 0.65, 0.85> } finish { Fin } scale 0.6 translate <3.6, 1.8, 0> }

// Hypercomplex 1/z + c, with a slice through the fourth dimension.
julia_fractal { <-0.2, 0.3, 0.1, 0.0> hypercomplex reciprocal max_iteration 6 precision 30 slice <0, 0, 0.3, 1>, 0.1
  pigment { rgb <0.6, 0.9, 0.5> } finish { Fin } scale 0.25 translate <-3.4, -0.6, -1> }

// A quaternion cut in half by a box: the cut face lies where the fractal is inside.
intersection {
  julia_fractal { <-0.08, 0.0, -0.83, -0.025> quaternion sqr max_iteration 8 precision 25 }
  box { <-2, -2, -2>, <2, 2, 0> }
  pigment { rgb <0.5, 0.5, 0.9> } finish { Fin } rotate y*-30 scale 0.8 translate <-1.8, -0.5, -2.5>
}

// Hypercomplex pwr.
julia_fractal { <0.3, 0.2, 0.0, 0.1> hypercomplex pwr(2.5, 0) max_iteration 6 precision 30
  pigment { rgb <0.9, 0.4, 0.6> } finish { Fin } scale 0.5 translate <3.6, -0.4, -1> }
