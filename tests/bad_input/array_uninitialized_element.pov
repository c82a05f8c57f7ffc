#declare A = array[3];
sphere { 0, A[1] }
