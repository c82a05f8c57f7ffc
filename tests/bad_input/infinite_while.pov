// An empty loop whose condition never changes.
#while (1)
#end
