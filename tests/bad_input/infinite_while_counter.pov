#declare I = 0;
#while (I >= 0)
  #declare I = I + 1;
#end
