#declare A = array[3] {1, 2, 3};
#declare X = A[3];
