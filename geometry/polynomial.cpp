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
    int count = 0;
    auto keep = [&](double x) {
        roots[count++] = x;
        return false;
    };
    each_polynomial_root(c, degree, lo, hi, keep);
    return count;
}

bool each_polynomial_root(const double* c, int degree, double lo, double hi, RootVisitor visit) {
    // Drop vanishing leading coefficients so the degree is the true one.
    while (degree > 0 && c[degree] == 0.0) --degree;
    if (degree <= 0 || degree > kMaxDegree || !(lo <= hi)) return false;
    if (degree == 2) {
        // Closed form, in the stable arrangement (no cancellation between -b and the root of the discriminant).
        const double disc = c[1] * c[1] - 4.0 * c[2] * c[0];
        if (disc < 0.0) return false;
        const double q = -0.5 * (c[1] + std::copysign(std::sqrt(disc), c[1]));
        double x0 = q / c[2], x1 = q != 0.0 ? c[0] / q : x0;
        if (x1 < x0) std::swap(x0, x1);
        const bool first = x0 >= lo && x0 <= hi;
        if (first && visit(x0)) return true;
        return x1 >= lo && x1 <= hi && (!first || x1 != x0) && visit(x1);
    }
    if (degree == 1) {
        const double x = -c[0] / c[1];
        return x >= lo && x <= hi && visit(x);
    }
    double dc[kMaxDegree];
    for (int i = 1; i <= degree; ++i) dc[i - 1] = i * c[i];
    // Monotone pieces between lo, the critical points (the derivative's roots, found as they are reached) and hi:
    // each holds at most one root.
    int count = 0;
    double last_root = 0.0;
    bool stopped = false;
    auto found = [&](double x) {
        ++count;
        last_root = x;
        stopped = visit(x);
        return stopped;
    };
    double edge = lo;
    double f_prev = evaluate(c, degree, edge);
    if (f_prev == 0.0 && found(edge)) return true;
    // The next edge: true to end the search (a root's visit stopped it, or every root there can be is found).
    auto next_edge = [&](double next) {
        if (count >= degree) return true;
        const double f_next = evaluate(c, degree, next);
        if (f_next == 0.0) {
            if ((count == 0 || last_root != next) && found(next)) return true;
        } else if (f_prev != 0.0 && (f_prev < 0.0) != (f_next < 0.0)) {
            if (found(refine(c, dc, degree, edge, next, f_prev, f_next))) return true;
        }
        f_prev = f_next;
        edge = next;
        return false;
    };
    if (each_polynomial_root(dc, degree - 1, lo, hi, next_edge)) return stopped;
    next_edge(hi);
    return stopped;
}

namespace {

// POV-Ray compat: polysolv.cpp's constants. A coefficient below kSmallEnough is zero; kRelError is the relative
// width at which a root is taken as found; kDifficultRatio (its FUDGE_FACTOR1) the spread of a quartic's
// coefficients beyond which the closed form gives way to Sturm sequences, which look for roots in [0, kMaxDistance].
constexpr double kSmallEnough = 1e-10;
constexpr double kRelError = 1e-12;
constexpr int kMaxIterations = 50;
constexpr double kDifficultRatio = 1e12;
constexpr double kMaxDistance = 1e7;

// One member of a Sturm sequence, lowest power first.
struct SturmPolynomial {
    int order = 0;
    double c[kMaxDegree + 1] = {};
};

// r = the remainder of u divided by v, as POV-Ray's modp computes it (a negative leading coefficient of v handled by
// sign flips rather than by division), with the top coefficients below kSmallEnough cleared; returns r's order.
int sturm_remainder(const SturmPolynomial& u, const SturmPolynomial& v, SturmPolynomial& r) {
    r = u;
    const int shift = u.order - v.order;
    if (v.c[v.order] < 0.0) {
        for (int k = shift - 1; k >= 0; k -= 2) r.c[k] = -r.c[k];
        for (int k = shift; k >= 0; --k)
            for (int j = v.order + k - 1; j >= k; --j) r.c[j] = -r.c[j] - r.c[v.order + k] * v.c[j - k];
    } else {
        for (int k = shift; k >= 0; --k)
            for (int j = v.order + k - 1; j >= k; --j) r.c[j] -= r.c[v.order + k] * v.c[j - k];
    }
    int k = v.order - 1;
    for (; k >= 0 && std::fabs(r.c[k]) < kSmallEnough; --k) r.c[k] = 0.0;
    r.order = k < 0 ? 0 : k;
    return r.order;
}

// Fills seq[1..] from seq[0]: the normalised derivative, then negated, normalised remainders until one is constant;
// returns the index of the last member.
int build_sturm(SturmPolynomial* seq) {
    const int order = seq[0].order;
    seq[1].order = order - 1;
    const double scale = std::fabs(seq[0].c[order] * order);
    for (int i = 1; i <= order; ++i) seq[1].c[i - 1] = seq[0].c[i] * i / scale;
    SturmPolynomial* s = seq + 2;
    while (sturm_remainder(s[-2], s[-1], *s) != 0) {
        const double norm = -std::fabs(s->c[s->order]);
        for (int i = s->order; i >= 0; --i) s->c[i] /= norm;
        ++s;
    }
    s->c[0] = -s->c[0];
    return static_cast<int>(s - seq);
}

// Sign changes along the sequence at x (a zero counts as a change, as POV-Ray counts it).
int sign_changes(int last, const SturmPolynomial* seq, double x) {
    int changes = 0;
    double before = evaluate(seq[0].c, seq[0].order, x);
    for (int i = 1; i <= last; ++i) {
        const double f = evaluate(seq[i].c, seq[i].order, x);
        if (before == 0.0 || before * f < 0) ++changes;
        before = f;
    }
    return changes;
}

// Sign changes at 0 less those at +infinity, from the constant and leading coefficients.
int positive_roots(int last, const SturmPolynomial* seq) {
    int at_zero = 0, at_infinity = 0;
    double lead = seq[0].c[seq[0].order], constant = seq[0].c[0];
    for (int i = 1; i <= last; ++i) {
        const double f = seq[i].c[seq[i].order], g = seq[i].c[0];
        if (lead == 0.0 || lead * f < 0) ++at_infinity;
        if (constant == 0.0 || constant * g < 0) ++at_zero;
        lead = f;
        constant = g;
    }
    return at_zero - at_infinity;
}

// The one root of p in [a, b] by the Illinois variant of regula falsi (the retained end's value halved when the
// same side is kept twice); false when p has one sign at both ends or the iterations run out.
bool regula_falsi(const SturmPolynomial& p, double a, double b, double& root) {
    double fa = evaluate(p.c, p.order, a), fb = evaluate(p.c, p.order, b);
    if (fa * fb > 0.0) return false;
    if (std::fabs(fa) < kSmallEnough) {
        root = a;
        return true;
    }
    if (std::fabs(fb) < kSmallEnough) {
        root = b;
        return true;
    }
    double previous = fa;
    for (int its = 0; its < kMaxIterations; ++its) {
        const double x = (fb * a - fa * b) / (fb - fa);
        const double fx = evaluate(p.c, p.order, x);
        if (std::fabs(x) > kRelError ? std::fabs(fx / x) < kRelError : std::fabs(fx) < kRelError) {
            root = x;
            return true;
        }
        // Replace the end whose value has fx's sign; halve the other end's value when fx kept its sign.
        const bool same_as_a = fa < 0 ? fx < 0 : !(fx < 0);
        if (same_as_a) {
            a = x;
            fa = fx;
            if (previous * fx > 0) fb /= 2;
        } else {
            b = x;
            fb = fx;
            if (previous * fx > 0) fa /= 2;
        }
        if (std::fabs(b - a) < kRelError) {
            root = x;
            return true;
        }
        previous = fx;
    }
    return false;
}

// True when [lo, hi] is narrow enough around mid to stop (relative to mid, or absolute near 0).
bool narrow(double lo, double hi, double mid) {
    return std::fabs(mid) > kRelError ? std::fabs((hi - lo) / mid) < kRelError : std::fabs(hi - lo) < kRelError;
}

// The roots in [lo, hi], where the sequence has `at_lo` and `at_hi` sign changes, by bisection on the counts
// (regula falsi for a single root); POV-Ray compat: sbisect, down to its early exits.
int sturm_bisect(int last, const SturmPolynomial* seq, double lo, double hi, int at_lo, int at_hi, double* roots) {
    double mid = lo;
    if (at_lo - at_hi == 1) {
        if (regula_falsi(seq[0], lo, hi, roots[0])) return 1;
        for (int its = 0; its < kMaxIterations; ++its) {
            mid = (lo + hi) / 2;
            const int at_mid = sign_changes(last, seq, mid);
            if (at_mid < at_hi || at_mid > at_lo) return 0;
            if (narrow(lo, hi, mid)) break;
            if (at_lo == at_mid) lo = mid;
            else hi = mid;
        }
        roots[0] = mid;
        return 1;
    }
    for (int its = 0; its < kMaxIterations; ++its) {
        mid = (lo + hi) / 2;
        const int at_mid = sign_changes(last, seq, mid);
        if (at_mid < at_hi || at_mid > at_lo) return 0;
        if (narrow(lo, hi, mid)) break;
        const int below = at_lo - at_mid, above = at_mid - at_hi;
        if (below != 0 && above != 0) {
            const int n = sturm_bisect(last, seq, lo, mid, at_lo, at_mid, roots);
            return n + sturm_bisect(last, seq, mid, hi, at_mid, at_hi, roots + n);
        }
        if (below == 0) lo = mid;
        else hi = mid;
    }
    roots[0] = mid;
    return 1;
}

// The roots in [0, kMaxDistance] of c (highest power first) by a Sturm sequence (POV-Ray compat: polysolve).
int sturm_roots(const double* c, int order, double* roots) {
    SturmPolynomial seq[kMaxDegree + 1];
    seq[0].order = order;
    for (int i = 0; i <= order; ++i) seq[0].c[order - i] = c[i] / c[0];
    const int last = build_sturm(seq);
    if (positive_roots(last, seq) == 0) return 0;
    const int at_lo = sign_changes(last, seq, 0.0);
    const int at_hi = sign_changes(last, seq, kMaxDistance);
    if (at_lo - at_hi == 0) return 0;
    return sturm_bisect(last, seq, 0.0, kMaxDistance, at_lo, at_hi, roots);
}

// Real roots of x[0] y² + x[1] y + x[2] (POV-Ray compat: solve_quadratic, a near-zero discriminant of the monic
// form taken as one double root).
int quadratic_roots(const double* x, double* y) {
    double a = x[0], b = -x[1], c = x[2];
    if (a == 0.0) {
        if (b == 0.0) return 0;
        y[0] = c / b;
        return 1;
    }
    b /= a;
    c /= a;
    const double d = b * b - 4.0 * c;
    if (d > -kSmallEnough && d < kSmallEnough) {
        y[0] = 0.5 * b;
        return 1;
    }
    if (d < 0.0) return 0;
    const double s = std::sqrt(d);
    y[0] = (b + s) / 2.0;
    y[1] = (b - s) / 2.0;
    return 2;
}

// Real roots of x[0] y³ + x[1] y² + x[2] y + x[3] in closed form: three by the trigonometric method when the
// discriminant allows, else one by Cardano's (POV-Ray compat: solve_cubic's arrangement and its lost precision).
int cubic_roots(const double* x, double* y) {
    if (x[0] == 0.0) return quadratic_roots(x + 1, y);
    double a1 = x[1], a2 = x[2], a3 = x[3];
    if (x[0] != 1.0) {
        a1 = x[1] / x[0];
        a2 = x[2] / x[0];
        a3 = x[3] / x[0];
    }
    const double a1_sq = a1 * a1;
    const double q = (a1_sq - 3.0 * a2) / 9.0;
    const double r = (a1 * (a1_sq - 4.5 * a2) + 13.5 * a3) / 27.0;
    const double q3 = q * q * q, r2 = r * r;
    const double shift = a1 / 3.0;
    if (q3 - r2 >= 0.0) {
        const double theta = std::acos(r / std::sqrt(q3)) / 3.0;
        const double scale = -2.0 * std::sqrt(q);
        // 2π/3 and 4π/3 as POV-Ray spells them.
        y[0] = scale * std::cos(theta) - shift;
        y[1] = scale * std::cos(theta + 2.0943951023931954923084) - shift;
        y[2] = scale * std::cos(theta + 4.1887902047863909846168) - shift;
        return 3;
    }
    const double s = std::pow(std::sqrt(r2 - q3) + std::fabs(r), 1.0 / 3.0);
    y[0] = (r < 0.0 ? s + q / s : -(s + q / s)) - shift;
    return 1;
}

// Real roots of x[0] y⁴ + ... + x[4] by Ferrari's method: a root z of the resolvent cubic of the depressed quartic
// splits it into two quadratics (POV-Ray compat: solve_quartic, its tolerances and its lost and spurious roots
// where the split is ill-conditioned).
int quartic_roots(const double* x, double* y) {
    double c1 = x[1], c2 = x[2], c3 = x[3], c4 = x[4];
    if (x[0] != 1.0) {
        c1 = x[1] / x[0];
        c2 = x[2] / x[0];
        c3 = x[3] / x[0];
        c4 = x[4] / x[0];
    }
    // y = w - c1/4 gives w⁴ + p w² + q w + r.
    const double c1_sq = c1 * c1;
    const double p = -0.375 * c1_sq + c2;
    const double q = 0.125 * c1_sq * c1 - 0.5 * c1 * c2 + c3;
    const double r = -0.01171875 * c1_sq * c1_sq + 0.0625 * c1_sq * c2 - 0.25 * c1 * c3 + c4;
    const double resolvent[4] = {1.0, -0.5 * p, -r, 0.5 * r * p - 0.125 * q * q};
    double z_roots[3];
    if (cubic_roots(resolvent, z_roots) <= 0) return 0;
    const double z = z_roots[0];
    // (w² + z)² = (2z - p) w² - q w + z² - r: the right side a square (d1 w - d2)².
    double d1 = 2.0 * z - p, d2;
    if (d1 < 0.0) {
        if (d1 <= -kSmallEnough) return 0;
        d1 = 0.0;
    }
    if (d1 < kSmallEnough) {
        d2 = z * z - r;
        if (d2 < 0.0) return 0;
        d2 = std::sqrt(d2);
    } else {
        d1 = std::sqrt(d1);
        d2 = 0.5 * q / d1;
    }
    const double d1_sq = d1 * d1, shift = -0.25 * c1;
    int n = 0;
    // w² + d1 w + z - d2 = 0 (POV-Ray compat: a double root shifted the wrong way).
    double disc = d1_sq - 4.0 * (z - d2);
    if (disc == 0) {
        y[n++] = -0.5 * d1 - shift;
    } else if (disc > 0) {
        disc = std::sqrt(disc);
        y[n++] = -0.5 * (d1 + disc) + shift;
        y[n++] = -0.5 * (d1 - disc) + shift;
    }
    // w² - d1 w + z + d2 = 0.
    disc = d1_sq - 4.0 * (z + d2);
    if (disc == 0) {
        y[n++] = 0.5 * d1 - shift;
    } else if (disc > 0) {
        disc = std::sqrt(disc);
        y[n++] = 0.5 * (d1 + disc) + shift;
        y[n++] = 0.5 * (d1 - disc) + shift;
    }
    return n;
}

// True when a quartic's coefficients span more than kDifficultRatio (POV-Ray compat: difficult_coeffs, whose
// running "largest" keeps the sign of the coefficient it was taken from).
bool difficult_coefficients(const double* x, int n) {
    double biggest = 0.0;
    for (int i = 0; i <= n; ++i)
        if (std::fabs(x[i]) > biggest) biggest = x[i];
    if (biggest == 0.0) return false;
    for (int i = 0; i <= n; ++i)
        if (x[i] != 0.0 && std::fabs(biggest / x[i]) > kDifficultRatio) return true;
    return false;
}

}  // namespace

int solve_polynomial_pov(const double* c0, int n, double* roots, bool sturm, double epsilon) {
    if (n < 0 || n > kMaxDegree) return 0;
    int lead = 0;
    while (std::fabs(c0[lead]) < kSmallEnough && lead < n) ++lead;
    n -= lead;
    const double* c = c0 + lead;
    switch (n) {
        case 0: return 0;
        case 1:
            if (c[0] == 0.0) return 0;
            roots[0] = -c[1] / c[0];
            return 1;
        case 2: return quadratic_roots(c, roots);
        case 3:
            // A constant negligible beside the linear term: the root near 0 is dropped.
            if (epsilon > 0.0 && c[2] != 0.0 && std::fabs(c[3] / c[2]) < epsilon) return quadratic_roots(c, roots);
            return sturm ? sturm_roots(c, 3, roots) : cubic_roots(c, roots);
        case 4:
            if (epsilon > 0.0 && c[3] != 0.0 && std::fabs(c[4] / c[3]) < epsilon)
                return sturm ? sturm_roots(c, 3, roots) : cubic_roots(c, roots);
            if (sturm || difficult_coefficients(c, 4)) return sturm_roots(c, 4, roots);
            return quartic_roots(c, roots);
        default: return sturm_roots(c, n, roots);
    }
}

}  // namespace wardray::geometry
