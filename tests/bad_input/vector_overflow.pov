#declare V = <1e308, 0, 0> * 10;
sphere { V, 1 }
