// An endless loop calling a macro that makes two objects.
#version 3.7;
#macro Pair() sphere { 0, 1 } box { -1, 1 } #end
#while (1) Pair() #end
