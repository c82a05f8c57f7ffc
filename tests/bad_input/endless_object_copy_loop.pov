// An endless loop placing copies of a declared union of ten spheres: every copy counts.
#version 3.7;
#declare U = union { #for (K, 1, 10) sphere { K * x, 1 } #end }
#while (1)
  object { U }
#end
