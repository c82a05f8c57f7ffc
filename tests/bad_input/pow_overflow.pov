#declare Big = pow(10, 400);
sphere { 0, Big }
