#declare Size = -1;
#if (Size < 0)
  #error "Size must be positive"
#end
