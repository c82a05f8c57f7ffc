#declare X = mod(5, 0);
