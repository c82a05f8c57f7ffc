sphere { <0, "one", 0>, 1 }
