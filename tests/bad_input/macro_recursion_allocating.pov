// A runaway macro recursion that holds a large array at every level: memory, not depth, runs out first
// unless something stops it.
#version 3.7;
#macro Grow(N)
  #local A = array[1000000];
  Grow(N + 1)
#end
Grow(0)
