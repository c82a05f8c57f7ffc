// Real roots of polynomials: on an interval, isolated by the roots of the derivative; or as POV-Ray 3.7 finds them.
#pragma once

#include "core/stop_callback.h"

namespace wardray::geometry {

/// Finds the real roots of c[0] + c[1] x + ... + c[degree] x^degree in [lo, hi] (degree 1..35), sorted
/// ascending, into roots (room for `degree` values); returns their count. Each sign change between consecutive
/// critical points is bracketed and refined by safeguarded Newton steps until |f| is within the rounding error of
/// its evaluation, so no root is lost to cancellation as in closed-form quartic formulas; double roots without a
/// sign change (grazing rays) may be missed. Quadratics are solved in closed form.
int polynomial_roots(const double* c, int degree, double lo, double hi, double* roots);

/// Takes a root and returns true to stop the search.
using RootVisitor = StopCallback<double>;

/// polynomial_roots() one root at a time: calls `visit` with each root polynomial_roots() finds, the same values in
/// the same ascending order, until a call returns true; returns whether one did. A root is refined only when
/// reached, and the critical points only as far as the roots reached need them, so a caller that wants the first
/// root in an interval (a ray's nearest crossing) pays for that root alone.
bool each_polynomial_root(const double* c, int degree, double lo, double hi, RootVisitor visit);

/// POV-Ray compat: the real roots of c[0] x^n + c[1] x^(n-1) + ... + c[n] (highest power first, n <= 35) as POV-Ray
/// 3.7's Solve_Polynomial (polysolv.cpp) finds them, unsorted, into roots (room for n values); returns their count.
/// Leading coefficients below 1e-10 in magnitude are dropped; quadratics, cubics and quartics are solved in closed
/// form unless `sturm` is set (or a quartic's coefficients span more than 12 orders of magnitude), when the roots in
/// [0, 1e7] are isolated by a Sturm sequence. With `epsilon` > 0, a cubic or quartic whose constant is below epsilon
/// times its linear coefficient loses its root near 0. The closed forms lose roots and invent spurious ones where
/// they are ill-conditioned; shapes that must draw what POV-Ray draws use this, not polynomial_roots.
int solve_polynomial_pov(const double* c, int n, double* roots, bool sturm, double epsilon);

}  // namespace wardray::geometry
