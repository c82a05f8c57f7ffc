// Real roots of polynomials on an interval, isolated by the roots of the derivative.
#pragma once

namespace wardray::geometry {

/// Finds the real roots of c[0] + c[1] x + ... + c[degree] x^degree in [lo, hi] (degree 1..35), sorted
/// ascending, into roots (room for `degree` values); returns their count. Each sign change between consecutive
/// critical points is bracketed and refined by safeguarded Newton steps until |f| is within the rounding error of
/// its evaluation, so no root is lost to cancellation as in closed-form quartic formulas; double roots without a
/// sign change (grazing rays) may be missed. Quadratics are solved in closed form.
int polynomial_roots(const double* c, int degree, double lo, double hi, double* roots);

}  // namespace wardray::geometry
