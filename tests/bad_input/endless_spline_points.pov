// An endless #while giving the points of one spline.
#version 3.7;
#declare I = 0;
#declare S = spline { linear_spline
#while (1)
  I, <I, 0, 0>
  #declare I = I + 1;
#end
}
