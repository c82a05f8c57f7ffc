#macro M()
  sphere { 0, 1 }
