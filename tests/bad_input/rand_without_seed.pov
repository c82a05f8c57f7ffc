#declare X = rand(3);
