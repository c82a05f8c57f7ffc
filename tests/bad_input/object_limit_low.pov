// The object budget, lowered on the command line: the 11th sphere crosses it.
#version 3.7;
#for (I, 1, 20) sphere { I * x, 1 } #end
