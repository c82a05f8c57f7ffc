// Parity scene: CSG with POV-Ray's inside/outside rules: difference, intersection, merge, nested CSG, inverse,
// clipped_by, bounded_by and texture inheritance (children without a texture take their CSG's).
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 6, -9> look_at <0, 0, 0.6> angle 55 }

light_source { <-5, 10, -6> color rgb 1 }
light_source { <6, 4, -3> color rgb 0.4 }

plane { y, -1 pigment { rgb <0.8, 0.8, 0.7> } finish { ambient 0.1 diffuse 0.7 } }

// A box with a spherical bite: the bite shows the sphere's own colour.
difference {
  box { -1, 1 pigment { rgb <0.9, 0.2, 0.2> } }
  sphere { 0, 1.3 pigment { rgb <0.2, 0.9, 0.2> } }
  rotate <0, 20, 0>
  translate <-2.6, 0, 0>
  finish { phong 0.5 }
}

// Rounded cube; the texture comes from the intersection.
intersection {
  box { -1, 1 }
  sphere { 0, 1.35 }
  pigment { rgb <0.2, 0.4, 0.9> }
  finish { phong 0.4 }
  rotate <0, 30, 0>
  translate <0, 0, 0.5>
}

// Merge removes the inner surfaces; one child keeps its own pigment.
merge {
  sphere { <-0.4, 0, 0>, 0.8 }
  sphere { <0.4, 0, 0>, 0.8 pigment { rgb <1, 1, 0> } }
  pigment { rgb <0.9, 0.5, 0.1> }
  translate <2.5, 0, 0>
}

// Nested CSG: a union used inside a difference, with a cylinder drilled through.
difference {
  union {
    sphere { <0, 0, 0>, 0.7 }
    box { <-0.5, -0.9, -0.5>, <0.5, 0, 0.5> }
  }
  cylinder { <0, 0, -2>, <0, 0, 2>, 0.3 pigment { rgb <0.95, 0.95, 0.95> } }
  pigment { rgb <0.6, 0.3, 0.8> }
  translate <-1.2, -0.1, -2.2>
}

// Inverse: an intersection with an inverted sphere is a difference.
intersection {
  cylinder { <0, -1, 0>, <0, 0.6, 0>, 0.7 }
  sphere { <0, 0.6, 0>, 0.5 inverse }
  pigment { rgb <0.3, 0.8, 0.8> }
  translate <1.3, 0, -2.3>
}

// clipped_by keeps only the surface inside the clip (no cap): the open sphere shows its inside.
sphere { 0, 0.8
  clipped_by { plane { <0, 1, -1>, 0.1 } }
  bounded_by { box { -1, 1 } }
  hollow
  pigment { rgb <0.9, 0.6, 0.6> }
  rotate <0, -30, 0>
  translate <3.8, -0.2, 2.2>
}

// Clipped union: a capsule cut in half along its length.
union {
  cylinder { <0, -0.8, 0>, <0, 0.8, 0>, 0.4 }
  sphere { <0, 0.8, 0>, 0.4 }
  sphere { <0, -0.8, 0>, 0.4 }
  clipped_by { plane { -z, 0 } }
  pigment { rgb <0.8, 0.8, 0.3> }
  rotate <0, 0, 60>
  translate <-2.2, 0, 3.2>
}
