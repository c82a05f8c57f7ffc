#declare A = array[-1];
