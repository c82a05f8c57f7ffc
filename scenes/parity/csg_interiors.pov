// Parity scene: the interiors of CSG children, as POV-Ray's Post_Process shares them. A child refracts with its own
// interior and inherits its CSG's only when it has none (merge and union alike); children that inherit one interior
// count as one in the ray's interior list, so an overlapping union with one interior bends where its spheres
// overlap; a merge's face lying in a clipping plane is inside it (POV-Ray's plane inside test with its epsilon).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }

camera { location <0, 5, -10> look_at <0, 0.2, 0> angle 52 }
light_source { <-5, 10, -6> color rgb 1 }
light_source { <6, 4, -8> color rgb 0.4 }

plane { y, -1.2 pigment { checker rgb <0.9, 0.85, 0.7> rgb <0.15, 0.3, 0.6> scale 0.6 } }
plane { z, 3 pigment { checker rgb <0.9, 0.3, 0.2> rgb <0.95, 0.95, 0.9> scale 0.5 } }

#declare Glass = texture { pigment { rgbf <0.95, 0.97, 1, 0.92> } finish { phong 0.8 reflection 0.05 } }

// A merge of one cylinder that has its own interior and one that takes the merge's.
merge {
  cylinder { <0, -1, 0>, <0, 1, 0>, 0.7 interior { ior 1.9 } }
  cylinder { <0.6, -0.9, 0>, <0.6, 0.85, 0>, 0.5 }
  texture { Glass }
  interior { ior 1.3 fade_distance 2 fade_power 1 }
  translate <-3, 0, 0>
}

// The same children in a union: the union's interior goes only to the child without one.
union {
  cylinder { <0, -1, 0>, <0, 1, 0>, 0.7 interior { ior 1.9 } }
  cylinder { <0.6, -0.9, 0>, <0.6, 0.85, 0>, 0.5 }
  texture { Glass }
  interior { ior 1.3 }
  translate <-1, 0, 0>
}

// Overlapping spheres that share their union's interior: POV-Ray's ray leaves it at the inner surfaces.
union {
  sphere { <-0.35, 0, 0>, 0.75 }
  sphere { <0.35, 0, 0>, 0.75 }
  texture { Glass }
  interior { ior 1.5 }
  translate <1.2, 0, -0.5>
}

// A merge whose second part's face lies in the first part's clipping plane (the wine glass's rim on its bowl),
// with interiors of its own, under a merge that gives the rest.
merge {
  torus { 0.8, 0.2 clipped_by { plane { -y, 0 } } interior { ior 1.6 } }
  difference {
    cylinder { <0, -1, 0>, <0, 0, 0>, 1 }
    cylinder { <0, -0.8, 0>, <0, 0.1, 0>, 0.7 }
  }
  texture { Glass }
  interior { ior 1.4 }
  rotate <-20, 0, 0>
  translate <3.3, 0.2, 0>
}
