sphere { 0, 1e999 pigment { rgb 1 } }
