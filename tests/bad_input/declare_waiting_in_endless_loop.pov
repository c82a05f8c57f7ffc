// A #declare that waits for its "=" while the loop around it jumps back: each pass nests one directive deeper.
#while (1)
  #declare S
#end
