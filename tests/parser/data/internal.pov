// functions.inc's internal functions that wardray evaluates, printed with #debug. internal_povray37.txt is what POV-Ray
// 3.7.0.10 prints for this file: povray +W16 +H12 -D -A +Oo.png internal.pov 2>&1 | grep -E '^I[0-9]'
#include "functions.inc"
#debug concat("I0 ", str(f_sphere(1, 2, 3, 1), 0, 9), "\n")
#debug concat("I1 ", str(f_torus(1, 0.5, 0.2, 1, 0.25), 0, 9), "\n")
#debug concat("I2 ", str(f_torus2(0.3, 0.2, 0.9, 1, 0.8, 0.2), 0, 9), "\n")
#debug concat("I3 ", str(f_torus2(3, 2, 1, 1, 0.8, 0.2), 0, 9), "\n")
#debug concat("I4 ", str(f_ellipsoid(1, 2, 3, 0.5, 0.25, 2), 0, 9), "\n")
#debug concat("I5 ", str(f_paraboloid(0.3, 0.5, -0.2, 2), 0, 9), "\n")
#debug concat("I6 ", str(f_paraboloid(3, -5, 2, 2), 0, 9), "\n")
#debug concat("I7 ", str(f_r(1, 2, 2), 0, 9), " ", str(f_th(1, 2, 3), 0, 9), " ", str(f_ph(1, 2, 3), 0, 9), "\n")
#debug concat("I8 ", str(f_rounded_box(1.2, 0.3, -2, 0.1, 1, 1, 1), 0, 9), " ", str(f_rounded_box(0, 0, 0, 0.1, 1, 1, 1), 0, 9), "\n")
#debug concat("I9 ", str(f_rounded_box(0.5, 0.2, 0.1, 2, 1, 1, 1), 0, 9), "\n")
#debug concat("I10 ", str(f_superellipsoid(0.5, 0.3, 0.2, 0.5, 1.5), 0, 9), " ", str(f_superellipsoid(-0.7, 0.1, 0.4, 2, 0.25), 0, 9), "\n")
#declare F = function { f_sphere(x, y, z, 2) + f_torus(x, y, z, 1, 0.1) }
#debug concat("I11 ", str(F(0.5, 1, 1.5), 0, 9), "\n")
