#switch (2)
#case (1)
  sphere { 0, 1 }
#break
