// Parity scene: parametric surfaces as POV-Ray solves them: a Moebius strip with precompute (as in
// portfolio/allobjects.pov), a flared vase, a wavy sheet, transformed and in a union.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 5, -10> look_at <0, 0.2, 0> angle 50 }

light_source { <-8, 14, -10> color rgb 1 }
light_source { <9, 6, -6> color rgb 0.35 }

plane { y, -2 pigment { checker rgb <0.8, 0.8, 0.7> rgb <0.6, 0.6, 0.55> } finish { ambient 0.1 diffuse 0.7 } }

#declare Fin = finish { ambient 0.1 diffuse 0.7 specular 0.4 }

// The Moebius strip of allobjects.pov.
parametric {
  function { cos(u) + v*cos(u/2)*cos(u) }
  function { sin(u) + v*cos(u/2)*sin(u) }
  function { v*sin(u/2) }
  <0, -0.3>, <2*pi, 0.3>
  contained_by { box { <-2, -2, -2>, <2, 2, 2> } }
  accuracy 0.001
  precompute 20, x, y, z
  rotate <0, 33, 0>
  translate <-2.6, 0, 0>
  pigment { rgb <0.95, 0.9, 0.8> }
  finish { Fin }
}

// A flared vase (a surface of revolution), tilted. (POV-Ray's sphere container is not matched yet.)
parametric {
  function { (0.35 + 0.3*v*v)*cos(u) }
  function { v }
  function { (0.35 + 0.3*v*v)*sin(u) }
  <0, -0.9>, <2*pi, 0.9>
  contained_by { box { -1.2, 1.2 } }
  max_gradient 1.2
  accuracy 0.002
  rotate <-35, 0, 20>
  translate <1.2, 0.3, 0.5>
  pigment { rgb <0.4, 0.7, 0.9> }
  finish { Fin }
}

// A wavy sheet without precompute, scaled, and a sphere in a union with it.
union {
  parametric {
    function { u }
    function { 0.25*sin(3*u)*cos(2*v) }
    function { v }
    <-1, -1>, <1, 1>
    contained_by { box { <-1.1, -0.5, -1.1>, <1.1, 0.5, 1.1> } }
    max_gradient 1
    accuracy 0.003
  }
  sphere { <0, 0.4, 0>, 0.3 }
  scale <1.2, 1, 0.9>
  rotate y*20
  translate <3.3, -1.2, -1.5>
  pigment { rgb <0.9, 0.5, 0.3> }
  finish { Fin }
}
