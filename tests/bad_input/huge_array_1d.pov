#declare A = array[1e15];
