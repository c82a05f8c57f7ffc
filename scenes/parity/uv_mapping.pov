// uv_mapping on meshes: mesh2 uv_vectors with and without uv_indices, a mesh's per-triangle uv_vectors and
// textures, mesh2 texture_list with one and three indices per face, texture and object uv_mapping, transformed.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -9> look_at <0, 0.6, 0> angle 50 }
light_source { <-5, 8, -6> color rgb 1 }
plane { y, -1 pigment { rgb 0.6 } }
#declare Check = texture { pigment { uv_mapping checker rgb <0.9, 0.2, 0.1>, rgb 0.9 scale 0.25 } }
#declare Red = texture { pigment { rgb <0.9, 0.1, 0.1> } }
#declare Green = texture { pigment { rgb <0.1, 0.8, 0.2> } }
#declare Blue = texture { pigment { rgb <0.1, 0.2, 0.9> } finish { phong 0.5 } }
// A quad: uv_vectors paired with the vertices, a pigment with uv_mapping, then moved.
mesh2 {
  vertex_vectors { 4, <-1, -1, 0>, <1, -1, 0>, <1, 1, 0>, <-1, 1, 0> }
  uv_vectors { 4, <0, 0>, <1, 0>, <1, 1>, <0, 1> }
  face_indices { 2, <0, 1, 2>, <0, 2, 3> }
  texture { Check }
  rotate <20, 30, 0> translate <-3, 1, 0>
}
// uv_indices and a normal with uv_mapping; spiral2 as in POV-Ray's mesh2 example.
mesh2 {
  vertex_vectors { 4, <-1, -1, 0>, <1, -1, 0>, <1, 1, 0>, <-1, 1, 0> }
  uv_vectors { 3, <0, 0>, <1, 1>, <1, -1> }
  face_indices { 2, <0, 1, 2>, <0, 2, 3> }
  uv_indices { 2, <0, 1, 2>, <1, 0, 2> }
  texture {
    pigment { uv_mapping spiral2 8 color_map { [0.5 rgb <0.2, 0, 0>] [0.5 rgb 1] } scale 0.8 }
    normal { uv_mapping bumps 0.6 scale 0.1 }
  }
  rotate -20*y translate <0, 1, 0>
}
// A mesh: per-triangle uv_vectors, a texture on one triangle, a texture_list of three on another; object
// uv_mapping keeps the texture in uv space as the mesh moves.
mesh {
  triangle { <-1, -1, 0>, <1, -1, 0>, <1, 1, 0> uv_vectors <0, 0>, <1, 0>, <1, 1> texture { Red } }
  triangle { <-1, -1, 0>, <1, 1, 0>, <-1, 1, 0> uv_vectors <0, 0>, <1, 1>, <0, 1> texture_list { Red, Green, Blue } }
  triangle { <-1, 1, 0>, <1, 1, 0>, <0, 2, 0> uv_vectors <0, 0>, <2, 0>, <1, 2> }
  uv_mapping
  texture { pigment { gradient x color_map { [0 rgb <1, 1, 0>] [1 rgb <0, 0.5, 1>] } } }
  scale 0.9 rotate 25*y translate <3, 0.8, 0>
}
// texture_list with one and with three indices per face; texture uv_mapping.
mesh2 {
  vertex_vectors { 5, <-1, 0, 0>, <1, 0, 0>, <1, 1.5, 0>, <-1, 1.5, 0>, <0, 2.3, 0> }
  uv_vectors { 5, <0, 0>, <1, 0>, <1, 1>, <0, 1>, <0.5, 1.5> }
  texture_list { 4,
    texture { uv_mapping pigment { checker rgb <0.1, 0.3, 0.9>, rgb 1 scale 0.2 } }
    texture { Red } texture { Green } texture { Blue } }
  face_indices { 3, <0, 1, 2>, 0, <0, 2, 3>, 1, 2, 3, <3, 2, 4>, 3 }
  rotate 40*x translate <0, -1, -3>
}
