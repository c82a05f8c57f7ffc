// Parity scene: triangle meshes traced as native Embree triangles: mesh (flat and smooth triangles), mesh2 with
// normals and indices, a closed mesh with inside_vector inside CSG, polygons with holes, and linear-spline prisms
// (linear and conic sweep, one with a hole).
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 5, -9> look_at <0, 0.1, 0.5> angle 55 }

light_source { <-5, 10, -6> color rgb 1 }
light_source { <6, 4, -3> color rgb 0.4 }

plane { y, -1 pigment { rgb <0.8, 0.8, 0.7> } finish { ambient 0.1 diffuse 0.7 } }

// An octahedron as a flat mesh.
#declare Octahedron = mesh {
  triangle { <1, 0, 0>, <0, 1, 0>, <0, 0, 1> }
  triangle { <0, 0, 1>, <0, 1, 0>, <-1, 0, 0> }
  triangle { <-1, 0, 0>, <0, 1, 0>, <0, 0, -1> }
  triangle { <0, 0, -1>, <0, 1, 0>, <1, 0, 0> }
  triangle { <1, 0, 0>, <0, 0, 1>, <0, -1, 0> }
  triangle { <0, 0, 1>, <-1, 0, 0>, <0, -1, 0> }
  triangle { <-1, 0, 0>, <0, 0, -1>, <0, -1, 0> }
  triangle { <0, 0, -1>, <1, 0, 0>, <0, -1, 0> }
  inside_vector <0.2, 0.7, 0.1>
}
object { Octahedron rotate <0, 25, 0> translate <-2.8, 0, 0> pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.5 } }

// The same octahedron with smooth triangles (normals along the vertex directions).
mesh {
  smooth_triangle { <1, 0, 0>, <1, 0, 0>, <0, 1, 0>, <0, 1, 0>, <0, 0, 1>, <0, 0, 1> }
  smooth_triangle { <0, 0, 1>, <0, 0, 1>, <0, 1, 0>, <0, 1, 0>, <-1, 0, 0>, <-1, 0, 0> }
  smooth_triangle { <-1, 0, 0>, <-1, 0, 0>, <0, 1, 0>, <0, 1, 0>, <0, 0, -1>, <0, 0, -1> }
  smooth_triangle { <0, 0, -1>, <0, 0, -1>, <0, 1, 0>, <0, 1, 0>, <1, 0, 0>, <1, 0, 0> }
  smooth_triangle { <1, 0, 0>, <1, 0, 0>, <0, 0, 1>, <0, 0, 1>, <0, -1, 0>, <0, -1, 0> }
  smooth_triangle { <0, 0, 1>, <0, 0, 1>, <-1, 0, 0>, <-1, 0, 0>, <0, -1, 0>, <0, -1, 0> }
  smooth_triangle { <-1, 0, 0>, <-1, 0, 0>, <0, 0, -1>, <0, 0, -1>, <0, -1, 0>, <0, -1, 0> }
  smooth_triangle { <0, 0, -1>, <0, 0, -1>, <1, 0, 0>, <1, 0, 0>, <0, -1, 0>, <0, -1, 0> }
  rotate <0, 25, 0> translate <-0.5, 0, 0>
  pigment { rgb <0.3, 0.8, 0.3> } finish { phong 0.5 }
}

// A square pyramid as mesh2 with explicit normals for its smooth sides.
mesh2 {
  vertex_vectors { 5, <-1, 0, -1>, <1, 0, -1>, <1, 0, 1>, <-1, 0, 1>, <0, 1.5, 0> }
  normal_vectors { 5, <-1, 0.5, -1>, <1, 0.5, -1>, <1, 0.5, 1>, <-1, 0.5, 1>, <0, 1, 0> }
  face_indices { 6, <0, 1, 4>, <1, 2, 4>, <2, 3, 4>, <3, 0, 4>, <0, 2, 1>, <0, 3, 2> }
  normal_indices { 6, <0, 1, 4>, <1, 2, 4>, <2, 3, 4>, <3, 0, 4>, <0, 2, 1>, <0, 3, 2> }
  rotate <0, 20, 0> translate <2.2, -1, 0.3>
  pigment { rgb <0.3, 0.5, 0.9> } finish { phong 0.3 }
}

// A closed mesh in CSG: the octahedron with a spherical bite (its inside comes from inside_vector).
difference {
  object { Octahedron }
  sphere { <0, 0.5, -0.6>, 0.6 pigment { rgb <1, 1, 0.5> } }
  scale 0.9
  translate <-1.6, -0.1, -2.4>
  pigment { rgb <0.9, 0.6, 0.2> }
}

// Polygons: a frame with a hole, and a star-shaped outline.
polygon { 10, <0, 0>, <2, 0>, <2, 2>, <0, 2>, <0, 0>, <0.5, 0.5>, <1.5, 0.5>, <1.5, 1.5>, <0.5, 1.5>, <0.5, 0.5>
  scale 0.8 rotate <0, -25, 0> translate <-4.3, -0.9, -1.4> pigment { rgb <0.9, 0.9, 0.3> } }
polygon { 11, <0, 1>, <0.25, 0.3>, <1, 0.3>, <0.4, -0.1>, <0.6, -0.8>, <0, -0.35>, <-0.6, -0.8>, <-0.4, -0.1>,
  <-1, 0.3>, <-0.25, 0.3>, <0, 1>
  translate <3.5, 0.5, 2> pigment { rgb <0.8, 0.3, 0.8> } finish { phong 0.2 } }

// Prisms: a star with a square hole (linear sweep), and a conic sweep of a square cut by a box.
prism { linear_sweep linear_spline 0, 0.6, 14,
  <1, 0>, <0.3, 0.3>, <0, 1>, <-0.3, 0.3>, <-1, 0>, <-0.3, -0.3>, <0, -1>, <0.3, -0.3>, <1, 0>,
  <-0.15, -0.15>, <0.15, -0.15>, <0.15, 0.15>, <-0.15, 0.15>, <-0.15, -0.15>
  rotate <0, 15, 0> translate <2.6, -1, -2.3>
  pigment { rgb <0.4, 0.9, 0.7> } finish { phong 0.4 } }
difference {
  prism { conic_sweep linear_spline 0.3, 1, 5, <1, 1>, <-1, 1>, <-1, -1>, <1, -1>, <1, 1> }
  box { <0, 0.5, -2>, <2, 2, 0> }
  rotate <180, 0, 0> scale 1.2
  translate <-1.2, 0.4, 4>
  pigment { rgb <0.9, 0.7, 0.5> }
}
