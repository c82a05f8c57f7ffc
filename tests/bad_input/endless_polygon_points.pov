// An endless #while giving the points of one polygon whose count it never reaches.
#version 3.7;
#declare I = 0;
polygon { 2000000000,
#while (1)
  <I, 0>,
  #declare I = I + 1;
#end
}
