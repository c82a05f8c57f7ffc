#declare X = 0 * 1e999;
