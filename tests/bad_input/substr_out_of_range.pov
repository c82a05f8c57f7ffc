#declare S = substr("abc", 5, 10);
