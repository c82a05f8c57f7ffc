// mesh2 face_indices that claims two billion faces and gives one.
#version 3.7;
mesh2 {
  vertex_vectors { 3, <0, 0, 0>, <1, 0, 0>, <0, 1, 0> }
  face_indices { 2000000000, <0, 1, 2> }
}
