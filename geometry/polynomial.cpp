// Polynomial root isolation: recursive on derivatives, bisection safeguarded Newton refinement.
#include "geometry/polynomial.h"

#include <cmath>
#include <utility>

namespace wardray::geometry {

namespace {

constexpr int kMaxDegree = 35;

double evaluate(const double* c, int degree, double x) {
    double v = c[degree];
    for (int i = degree - 1; i >= 0; --i) v = v * x + c[i];
    return v;
}

// f(x), with `noise` set to one rounding of the terms' size, eps * sum |c_i| |x|^i: Horner's error is a small
// multiple of it (Higham, "Accuracy and Stability of Numerical Algorithms", sec. 5.1), and below it the sign of f
// says little.
double evaluate(const double* c, int degree, double x, double& noise) {
    const double ax = std::fabs(x);
    double v = c[degree], m = std::fabs(c[degree]);
    for (int i = degree - 1; i >= 0; --i) {
        v = v * x + c[i];
        m = m * ax + std::fabs(c[i]);
    }
    noise = 1.2e-16 * m;
    return v;
}

// The root of f in [a, b], where f(a) = fa and f(b) = fb have opposite signs: Newton's method kept inside the
// bracket, falling back to bisection, from the secant's crossing (the bracket's ends are critical points or the
// interval's ends, and the secant lands far nearer the root than the middle does). Once |f| is within its
// rounding noise, one last Newton step ends it: bisecting on noisy signs to the last bit took up to 60 steps.
double refine(const double* c, const double* dc, int degree, double a, double b, double fa, double fb) {
    double x = a - fa * (b - a) / (fb - fa);
    if (!(x > a && x < b)) x = 0.5 * (a + b);
    for (int iter = 0; iter < 100; ++iter) {
        double noise = 0.0;
        const double fx = evaluate(c, degree, x, noise);
        if (fx == 0.0) return x;
        // Keep the bracket: the sign of f at a never changes.
        if ((fx < 0.0) == (fa < 0.0)) a = x;
        else b = x;
        const double d = evaluate(dc, degree - 1, x);
        double next = d != 0.0 ? x - fx / d : 0.5 * (a + b);
        // Within the rounding error of f, one more Newton step is as near as any.
        if (std::fabs(fx) <= noise) return next > a && next < b ? next : x;
        // Newton steps that leave the bracket fall back to bisection.
        if (!(next > a && next < b)) next = 0.5 * (a + b);
        if (next == x || b - a <= 4e-16 * std::fmax(std::fabs(a), std::fabs(b))) return next;
        x = next;
    }
    return x;
}

}  // namespace

int polynomial_roots(const double* c, int degree, double lo, double hi, double* roots) {
    // Drop vanishing leading coefficients so the degree is the true one.
    while (degree > 0 && c[degree] == 0.0) --degree;
    if (degree <= 0 || degree > kMaxDegree || !(lo <= hi)) return 0;
    if (degree == 2) {
        // Closed form, in the stable arrangement (no cancellation between -b and the root of the discriminant).
        const double disc = c[1] * c[1] - 4.0 * c[2] * c[0];
        if (disc < 0.0) return 0;
        const double q = -0.5 * (c[1] + std::copysign(std::sqrt(disc), c[1]));
        double x0 = q / c[2], x1 = q != 0.0 ? c[0] / q : x0;
        if (x1 < x0) std::swap(x0, x1);
        int count = 0;
        if (x0 >= lo && x0 <= hi) roots[count++] = x0;
        if (x1 >= lo && x1 <= hi && (count == 0 || x1 != roots[0])) roots[count++] = x1;
        return count;
    }
    if (degree == 1) {
        const double x = -c[0] / c[1];
        if (x >= lo && x <= hi) {
            roots[0] = x;
            return 1;
        }
        return 0;
    }
    double dc[kMaxDegree];
    for (int i = 1; i <= degree; ++i) dc[i - 1] = i * c[i];
    double critical[kMaxDegree];
    const int n_crit = polynomial_roots(dc, degree - 1, lo, hi, critical);
    // Monotone pieces between lo, the critical points and hi: each holds at most one root.
    double edges[kMaxDegree + 2];
    int n_edges = 0;
    edges[n_edges++] = lo;
    for (int i = 0; i < n_crit; ++i) edges[n_edges++] = critical[i];
    edges[n_edges++] = hi;
    int count = 0;
    double f_prev = evaluate(c, degree, edges[0]);
    if (f_prev == 0.0) roots[count++] = edges[0];
    for (int i = 1; i < n_edges && count < degree; ++i) {
        const double f_next = evaluate(c, degree, edges[i]);
        if (f_next == 0.0) {
            if (count == 0 || roots[count - 1] != edges[i]) roots[count++] = edges[i];
        } else if (f_prev != 0.0 && (f_prev < 0.0) != (f_next < 0.0)) {
            roots[count++] = refine(c, dc, degree, edges[i - 1], edges[i], f_prev, f_next);
        }
        f_prev = f_next;
    }
    return count;
}

}  // namespace wardray::geometry
