// A mesh_camera whose rays start on its mesh at z = -5.5, far from its `location` offset <0, 0, 0.5>, which lies
// inside a solid sphere: camera rays start in the objects around the mesh (none here), so fog fills every ray.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare CameraMesh = mesh2 {
  vertex_vectors { 4, <-2, -1.5, 0>, <2, -1.5, 0>, <2, 1.5, 0>, <-2, 1.5, 0> }
  normal_vectors { 4, <-0.4, -0.3, 1>, <0.4, -0.3, 1>, <0.4, 0.3, 1>, <-0.4, 0.3, 1> }
  uv_vectors { 4, <0, 0>, <1, 0>, <1, 1>, <0, 1> }
  face_indices { 2, <0, 2, 1>, <0, 3, 2> }
}
camera {
  mesh_camera { 1 3 mesh { CameraMesh rotate 10*x translate <0, 1.5, -6> } smooth }
  location <0, 0, 0.5>
}
light_source { <-5, 8, -4> color rgb 1 }
fog { distance 6 color rgb <0.5, 0.6, 0.7> }
plane { y, 0 pigment { checker rgb 0.9, rgb 0.3 } }
sphere { <0, 0.2, 0.5>, 0.8 pigment { rgb <0.9, 0.4, 0.2> } finish { phong 0.6 } }
sphere { <2.5, 1, 3>, 1 pigment { rgb <0.2, 0.5, 0.9> } }
box { <-3, 0, 1.5>, <-1.5, 2.5, 2.5> pigment { rgb <0.4, 0.9, 0.9> } }
