// An endless #while that stores a fresh array of a thousand strings at each turn.
#version 3.7;
#declare Rows = array[1000000];
#declare I = 0;
#while (1)
  #declare Row = array[1000];
  #for (J, 0, 999) #declare Row[J] = "0123456789abcdef0123456789abcdef"; #end
  #declare Rows[I] = Row;
  #declare I = I + 1;
#end
