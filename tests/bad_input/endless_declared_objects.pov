// Declaring an object over and over keeps memory flat but creates objects: the object budget ends it.
#version 3.7;
#while (1)
  #declare S = sphere { 0, 1 }
#end
