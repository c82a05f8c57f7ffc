sphere { 0, 1 }
/* a comment that never ends
  sphere { 1, 1 }