#declare X = ln(0);
sphere { 0, X }
