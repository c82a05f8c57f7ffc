sphere { 0, 1 pigment { rgb <1, 0, 0> * (1e300 * 1e300) } }
