// Parity scene: blobs of sphere and cylinder components (old and new syntax), negative strength, component
// transforms (an ellipsoid and a turned cylinder), a blob in CSG, on a floor under two point lights.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 4, -9> look_at <0, 0.8, 0> angle 50 }

light_source { <-5, 10, -6> color rgb 1 }
light_source { <6, 4, -3> color rgb 0.4 }

plane { y, 0 pigment { rgb <0.8, 0.8, 0.7> } finish { ambient 0.1 diffuse 0.7 } }

// Three spheres in the old syntax (objects/blob.pov's).
blob {
  threshold 0.6
  component 1.0, 1.0, <0.75, 0, 0>
  component 1.0, 1.0, <-0.375, 0.64952, 0>
  component 1.0, 1.0, <-0.375, -0.64952, 0>
  pigment { rgb <0.7, 0, 0.05> } finish { ambient 0.1 diffuse 0.7 phong 1 }
  rotate 30*y translate <-3, 1.2, 1>
}

// Crossed cylinders with a sphere of negative strength biting into them.
blob {
  threshold 0.5
  cylinder { <-1.5, 0, 0>, <1.5, 0, 0>, 0.8, 2 }
  cylinder { <0, 0, -1.5>, <0, 0, 1.5>, 0.8, strength 2 }
  sphere { <0, 0.6, 0>, 0.7, -4 }
  pigment { rgb <0.2, 0.5, 0.9> } finish { phong 0.6 }
  rotate <-20, 25, 0> translate <0.6, 1.0, 1.5>
}

// Component transforms: a sphere scaled into an ellipsoid, a cylinder turned and moved, sturm and hierarchy.
blob {
  threshold 0.4
  sphere { 0, 1, 1 scale <1.6, 0.6, 0.8> }
  cylinder { <0, -0.8, 0>, <0, 0.8, 0>, 0.4, 1.5 rotate 40*z translate 0.5*x }
  sphere { <0.9, 0.7, 0>, 0.6, 1.2 }
  sturm
  hierarchy off
  pigment { rgb <0.3, 0.8, 0.3> } finish { phong 0.5 }
  translate <3.3, 1.0, 0.8>
}

// A blob with a box cut out of it, so the inside test shows.
difference {
  blob {
    threshold 0.3
    sphere { <-0.5, 0, 0>, 1, 1 }
    sphere { <0.5, 0, 0>, 1, 1 }
  }
  box { <-2, 0, -2>, <0, 2, 0> }
  pigment { rgb <0.9, 0.8, 0.2> } finish { phong 0.3 }
  translate <-1.2, 0.6, -2.2>
}
