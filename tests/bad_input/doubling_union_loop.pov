// A union that swallows two copies of itself each turn: the object budget refuses the copy that crosses it,
// before making it.
#version 3.7;
#declare U = sphere { 0, 1 }
#while (1)
  #declare U = union { object { U } object { U translate x } }
#end
