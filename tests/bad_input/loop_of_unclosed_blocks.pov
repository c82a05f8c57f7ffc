// Error recovery inside an endless loop whose body opens blocks it never closes.
#declare I = 0;
#while (I >= 0)
  #declare I = I + 1;
  union {
    union {
      x ^
#end
