// Polynomial root isolation: recursive on derivatives, bisection safeguarded Newton refinement.
#include "geometry/polynomial.h"

#include <cmath>

namespace wardray::geometry {

namespace {

constexpr int kMaxDegree = 35;

double evaluate(const double* c, int degree, double x) {
    double v = c[degree];
    for (int i = degree - 1; i >= 0; --i) v = v * x + c[i];
    return v;
}

// The root of f in [a, b] where f(a) and f(b) have opposite signs.
double refine(const double* c, const double* dc, int degree, double a, double b, double fa) {
    double x = 0.5 * (a + b);
    for (int iter = 0; iter < 100; ++iter) {
        const double fx = evaluate(c, degree, x);
        if (fx == 0.0) return x;
        // Keep the bracket: the sign of f at a never changes.
        if ((fx < 0.0) == (fa < 0.0)) a = x;
        else b = x;
        const double d = evaluate(dc, degree - 1, x);
        double next = d != 0.0 ? x - fx / d : 0.5 * (a + b);
        // Newton steps that leave the bracket fall back to bisection.
        if (!(next > a && next < b)) next = 0.5 * (a + b);
        if (std::fabs(next - x) <= 1e-15 * std::fmax(std::fabs(x), 1e-300) || b - a <= 0.0) return next;
        x = next;
        if (b - a <= 4e-16 * std::fmax(std::fabs(a), std::fabs(b))) return x;
    }
    return x;
}

}  // namespace

int polynomial_roots(const double* c, int degree, double lo, double hi, double* roots) {
    // Drop vanishing leading coefficients so the degree is the true one.
    while (degree > 0 && c[degree] == 0.0) --degree;
    if (degree <= 0 || degree > kMaxDegree || !(lo <= hi)) return 0;
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
            roots[count++] = refine(c, dc, degree, edges[i - 1], edges[i], f_prev);
        }
        f_prev = f_next;
    }
    return count;
}

}  // namespace wardray::geometry
