polygon { 2, <0, 0>, <1, 1> }
