#declare F = function(x) { F(x) + 1 }
#declare Y = F(1);
