// An endless #while that makes an object on every turn: the object budget stops it (the .args raise the loop
// limit, so the loop guard is not what ends it).
#version 3.7;
#declare I = 0;
#while (1)
  sphere { <I, 0, 0>, 1 }
  #declare I = I + 1;
#end
