// An endless #while adding components to one blob: the components count against the object budget.
#version 3.7;
#declare I = 0;
blob { threshold 0.5
#while (1)
  sphere { <I, 0, 0>, 1, 1 }
  #declare I = I + 1;
#end
}
