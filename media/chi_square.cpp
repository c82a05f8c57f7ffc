// The inverse chi-square tail POV-Ray's media methods 1 and 2 take their sample thresholds from (Cephes' chdtri).
#include <cmath>

#include "media/participating_media.h"

namespace wardray::media {

namespace {

// The regularised upper incomplete gamma function Q(a, x): a power series for x < a + 1, else Lentz's continued
// fraction (Press et al., Numerical Recipes, 3rd ed., §6.2).
double upper_gamma(double a, double x) {
    if (x <= 0.0) return 1.0;
    const double log_prefix = a * std::log(x) - x - std::lgamma(a);
    if (x < a + 1.0) {
        double term = 1.0 / a, sum = term;
        for (int n = 1; n < 1000 && std::fabs(term) > std::fabs(sum) * 1e-16; ++n) {
            term *= x / (a + n);
            sum += term;
        }
        return 1.0 - sum * std::exp(log_prefix);
    }
    constexpr double kTiny = 1e-300;
    double b = x + 1.0 - a, c = 1.0 / kTiny, d = 1.0 / b, h = d;
    for (int i = 1; i < 1000; ++i) {
        const double an = -i * (i - a);
        b += 2.0;
        d = an * d + b;
        if (std::fabs(d) < kTiny) d = kTiny;
        c = b + an / c;
        if (std::fabs(c) < kTiny) c = kTiny;
        d = 1.0 / d;
        const double delta = d * c;
        h *= delta;
        if (std::fabs(delta - 1.0) < 1e-16) break;
    }
    return std::exp(log_prefix) * h;
}

}  // namespace

double inverse_chi_square_tail(double df, double y) {
    // chdtri(df, y) = 2 igami(df/2, y): the x where Q(df/2, x/2) = y, found by bisection (Q falls with x).
    if (!(y > 0.0) || !(y < 1.0) || !(df >= 1.0)) return 0.0;
    const double a = 0.5 * df;
    double lo = 0.0, hi = 1.0;
    while (upper_gamma(a, hi) > y && hi < 1e12) hi *= 2.0;
    for (int i = 0; i < 200 && hi - lo > 1e-15 * hi; ++i) {
        const double mid = 0.5 * (lo + hi);
        if (upper_gamma(a, mid) > y) lo = mid;
        else hi = mid;
    }
    return 2.0 * 0.5 * (lo + hi);
}

}  // namespace wardray::media
