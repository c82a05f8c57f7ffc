sphere { 0, sqrt(-1) pigment { rgb 1 } }
