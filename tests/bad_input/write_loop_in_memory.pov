// An endless #write while file writes are off: the in-memory copy must stop growing.
#declare S = "0123456789";
#declare S = concat(S, S, S, S, S, S, S, S, S, S);
#declare S = concat(S, S, S, S, S, S, S, S, S, S);
#fopen Log "endless.txt" write
#while (1)
  #write (Log, S, "\n")
#end
