#if (1)
  sphere { 0, 1 }
