#for (I, 0, 10, 0)
  sphere { <I, 0, 0>, 0.1 }
#end
