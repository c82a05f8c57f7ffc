// An intersection nested by a loop is a real tree: each copy of it counts every node, so the object budget
// ends the quadratic copying (copies are bounded at ten times --max-objects).
#version 3.7;
#declare U = sphere { 0, 1 }
#for (I, 1, 100000)
  #declare U = intersection { object { U } sphere { 0, 2 } }
#end
object { U }
