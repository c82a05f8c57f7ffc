#declare I = 0;
#while (I < 3)
  #declare I = I + 1;
