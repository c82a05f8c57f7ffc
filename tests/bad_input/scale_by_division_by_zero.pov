box { 0, 1 scale 1/0 }
