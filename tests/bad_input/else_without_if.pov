sphere { 0, 1 }
#else
