union {
  sphere { 0, 1 }
  box { <0, 0, 0>, <1, 1, 1>
