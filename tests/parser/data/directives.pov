// Arrays, loops, macros (recursion, by-reference arguments, #local), #switch, colour promotion, strings, rand(),
// user functions and standard include macros, printed with #debug. directives_povray37.txt is what POV-Ray
// 3.7.0.10 prints for this file: povray +W16 +H12 -D -A +Oo.png directives.pov 2>&1 | grep -E '^D[0-9]'
#declare A = array[2][3] { {1, 2, 3}, {4, 5, 6} }
#debug concat("D0 ", str(dimensions(A), 0, 0), " ", str(dimension_size(A, 1), 0, 0), " ", str(dimension_size(A, 2), 0, 0), " ", str(A[1][2], 0, 0), "\n")
#declare S = 0;
#for (I, 1, 10, 3) #declare S = S + I; #end
#debug concat("D1 ", str(S, 0, 0), "\n")
#declare S = 0; #declare I = 0;
#while (I < 5) #declare I = I + 1; #if (mod(I, 2) = 0) #declare S = S + I; #end #end
#debug concat("D2 ", str(S, 0, 0), "\n")
#macro Fact(N) #if (N <= 1) 1 #else N * Fact(N - 1) #end #end
#debug concat("D3 ", str(Fact(6), 0, 0), "\n")
#macro Inc(V) #declare V = V + 1; #end
#declare K = 5; Inc(K)
#debug concat("D4 ", str(K, 0, 0), "\n")
#macro Loc() #local Z = 7; Z #end
#declare Z = 1;
#debug concat("D5 ", str(Loc() + Z, 0, 0), "\n")
#declare Q = 3;
#switch (Q)
  #case (1) #declare W = 10; #break
  #range (2, 4) #declare W = 20; #break
  #else #declare W = 30;
#end
#debug concat("D6 ", str(W, 0, 0), "\n")
#declare C = color rgb <0.2, 0.4, 0.6>;
#debug concat("D7 ", vstr(5, C, ",", 0, 3), "\n")
#declare C2 = color 0.5;
#debug concat("D8 ", vstr(5, C2, ",", 0, 3), "\n")
#declare C3 = rgb 0.5;
#debug concat("D9 ", vstr(5, C3, ",", 0, 3), "\n")
#declare C4 = rgbt <1, 0, 0, 0.5> * 2;
#debug concat("D10 ", vstr(5, C4, ",", 0, 3), "\n")
#declare C5 = C + <0.1, 0.1, 0.1>;
#debug concat("D11 ", vstr(5, C5, ",", 0, 3), "\n")
#declare V2 = <1, 2>;
#debug concat("D12 ", vstr(2, V2, ",", 0, 3), " ", str(V2.u, 0, 1), "\n")
#if ("abc" = "abc") #debug "D14 eq\n" #end
#debug concat("D15 ", str(strcmp("a", "b"), 0, 0), " ", str(strcmp("b", "a"), 0, 0), "\n")
#declare R = seed(123);
#debug concat("D16 ", str(rand(R), 0, 9), " ", str(rand(R), 0, 9), " ", str(rand(R), 0, 9), "\n")
#declare F = function(x, y) { x * y + sin(x) }
#debug concat("D17 ", str(F(2, 3), 0, 9), "\n")
#declare G = function { x + y * 2 + z * 3 }
#debug concat("D18 ", str(G(1, 2, 3), 0, 9), "\n")
#include "math.inc"
#debug concat("D19 ", str(f_sqr(3), 0, 3), " ", str(sind(30), 0, 9), " ", str(max3(1, 7, 2), 0, 0), "\n")
#include "strings.inc"
#debug concat("D21 [", CRGBStr(<0.2, 0.4, 0.6>, 0, 2), "]\n")
#include "transforms.inc"
#declare T = transform { Axis_Rotate_Trans(<1, 1, 0>, 45) }
#declare P = vtransform(<1, 0, 0>, T);
#debug concat("D22 ", vstr(3, P, ",", 0, 6), "\n")
#declare M = transform { matrix <1,0,0, 0,2,0, 0,0,3, 1,2,3> }
#debug concat("D23 ", vstr(3, vtransform(<1,1,1>, M), ",", 0, 6), " ", vstr(3, vinv_transform(<1,1,1>, M), ",", 0, 6), "\n")
