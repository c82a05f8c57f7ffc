#declare R = Make_Radius(2);
