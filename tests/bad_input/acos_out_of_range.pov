#declare A = acos(2);
