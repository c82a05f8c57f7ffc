// An endless loop filling declared strings: the memory budget stops it.
#version 3.7;
#declare I = 0;
#while (1)
  #declare S = concat("name", str(I, 0, 0));
  #declare A = array[1000] { S, S, S, S, S, S, S, S, S, S }
  #declare I = I + 1;
#end
