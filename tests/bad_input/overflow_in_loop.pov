// Grows until it overflows to infinity.
#declare X = 1;
#while (X > 0)
  #declare X = X * 10;
#end
