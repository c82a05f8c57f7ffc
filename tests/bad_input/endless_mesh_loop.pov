// An endless loop of mesh triangles makes no objects: the memory budget stops it.
#version 3.7;
#declare I = 0;
mesh {
#while (1)
  triangle { <I, 0, 0>, <I, 1, 0>, <I, 0, 1> }
  #declare I = I + 1;
#end
}
