#macro Grow(N)
  Grow(N + 1)
#end
Grow(0)
