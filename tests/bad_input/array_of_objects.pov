// A large array filled with objects crosses a lowered object budget.
#version 3.7;
#declare A = array[1000000];
#for (I, 0, 999999)
  #declare A[I] = sphere { I * x, 1 }
#end
