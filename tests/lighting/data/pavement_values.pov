// Prints POV-Ray 3.7's pavement values for tests/lighting/pavement_test.cpp: every paving of squares, triangles and
// hexagons with exterior, interior and form varied, at 12 points on a 1/1024 grid each. Regenerate with
//   povray +Ipavement_values.pov -F +W8 +H8 -D 2>&1 | grep '^pavement ' > pavement_values.txt
#version 3.7;
global_settings { assumed_gamma 1 }
#include "functions.inc"
#declare Sides = array[3] { 4, 3, 6 }
#declare Forms = array[3] { 4, 3, 3 }
#declare Counts = array[3] { array[6] { 1, 1, 2, 5, 12, 35 }, array[6] { 1, 1, 1, 3, 4, 12 }, array[5] { 1, 1, 3, 7, 22 } }
#declare R = seed(7);
#for (S, 0, 2)
  #for (Tiles, 1, dimension_size(Counts[S], 1))
    #for (N, 1, Counts[S][Tiles - 1])
      #declare E = mod(N + Tiles, 3);
      #declare I = mod(N * 2 + S, 3);
      #declare F = mod(N + Tiles * 2 + S, Forms[S]);
      #declare P = pigment { pavement number_of_sides Sides[S] number_of_tiles Tiles pattern N exterior E
                             interior I form F color_map { [0 rgb 0] [1 rgb 1] } }
      #for (K, 1, 12)
        #declare X = floor(rand(R) * 14336) / 1024 - 7;
        #declare Z = floor(rand(R) * 14336) / 1024 - 7;
        #debug concat("pavement ", str(Sides[S], 0, 0), " ", str(Tiles, 0, 0), " ", str(N, 0, 0), " ", str(E, 0, 0),
                      " ", str(I, 0, 0), " ", str(F, 0, 0), " ", str(X, 0, 10), " ", str(Z, 0, 10), " ",
                      str(eval_pigment(P, <X, 0, Z>).red, 0, 9), "\n")
      #end
    #end
  #end
#end
sphere { 0, 1 pigment { rgb 1 } }
