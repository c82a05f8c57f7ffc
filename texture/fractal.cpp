// Fractal patterns: POV-Ray 3.7's mandel, julia (exponents 2 to 33) and magnet 1/2 mandel/julia, with their
// exterior and interior colourings, iterated in the x-y plane of pattern space exactly as POV-Ray does.
#include "texture/fractal.h"

#include <array>
#include <cmath>

namespace wardray::texture {

namespace {

constexpr int kMaxExponent = 33;  // POV-Ray's FRACTAL_MAX_EXPONENT

// Rows 0..33 of Pascal's triangle, entry k carrying the sign of i^k (POV-Ray's BinomialCoefficients).
struct Binomials {
    std::array<int, (kMaxExponent + 1) * (kMaxExponent + 2) / 2> c{};
    Binomials() {
        for (int n = 0; n <= kMaxExponent; ++n) {
            int* row = &c[n * (n + 1) / 2];
            const int* above = n > 0 ? &c[(n - 1) * n / 2] : nullptr;
            row[0] = row[n] = 1;
            for (int k = 1; k < n; ++k) row[k] = above[k - 1] + above[k];
        }
        for (int n = 1; n <= kMaxExponent; ++n) {
            int* row = &c[n * (n + 1) / 2];
            for (int k = 1; k <= n; ++k)
                if (k & 2) row[k] = -row[k];
        }
    }
    const int* row(int n) const { return &c[n * (n + 1) / 2]; }
};

const Binomials& binomials() {
    static const Binomials b;
    return b;
}

double exterior(const scene::Pattern& pat, int iters, double a, double b) {
    const double f = pat.params->exterior_factor;
    switch (pat.params->exterior_type) {
        case 0:
            return f;
        case 1:
            return static_cast<double>(iters) / static_cast<double>(pat.params->fractal_iterations);
        case 2:
            return a * f;
        case 3:
            return b * f;
        case 4:
            return a * a * f;
        case 5:
            return b * b * f;
        case 6:
            return std::sqrt(a * a + b * b) * f;
        case 7:
            return static_cast<double>(static_cast<unsigned>(iters) % static_cast<unsigned>(f)) / f;
        case 8:
            return static_cast<double>(static_cast<unsigned>(iters) % static_cast<unsigned>(1 + f)) / f;
        default:
            return 0.0;
    }
}

double interior(const scene::Pattern& pat, double a, double b, double mindist2) {
    const double f = pat.params->interior_factor;
    switch (pat.params->interior_type) {
        case 0:
            return f;
        case 1:
            return std::sqrt(mindist2) * f;
        case 2:
            return a * f;
        case 3:
            return b * f;
        case 4:
            return a * a * f;
        case 5:
            return b * b * f;
        case 6:
            return a * a + b * b * f;  // POV-Ray compat: the factor scales b² only.
        default:
            return 0.0;
    }
}

// z ← z^n + c for the exponents POV-Ray unrolls (2, 3, 4) and the binomial form above them.
template <int N>
void power_step(double& a, double& b, double a2, double b2, double cr, double ci) {
    if constexpr (N == 2) {
        b = 2.0 * a * b + ci;
        a = a2 - b2 + cr;
    } else if constexpr (N == 3) {
        b = 3.0 * a2 * b - b2 * b + ci;
        a = a2 * a - 3.0 * a * b2 + cr;
    } else {
        b = 4.0 * (a2 * a * b - a * b2 * b) + ci;
        a = a2 * a2 - 6.0 * a2 * b2 + b2 * b2 + cr;
    }
}

template <int N>
double escape(const scene::Pattern& pat, double a, double b, double cr, double ci) {
    double a2 = a * a, b2 = b * b;
    double mindist2 = a2 + b2;
    const int it_max = pat.params->fractal_iterations;
    for (int col = 0; col < it_max; ++col) {
        power_step<N>(a, b, a2, b2, cr, ci);
        a2 = a * a;
        b2 = b * b;
        const double dist2 = a2 + b2;
        if (dist2 < mindist2) mindist2 = dist2;
        if (dist2 > 4.0) return exterior(pat, col, a, b);
    }
    return interior(pat, a, b, mindist2);
}

double escape_x(const scene::Pattern& pat, double a, double b, double cr, double ci) {
    const int n = pat.params->fractal_exponent;
    const int* coeff = binomials().row(n);
    double mindist2 = a * a + b * b;
    const int it_max = pat.params->fractal_iterations;
    for (int col = 0; col < it_max; ++col) {
        double new_a = std::pow(a, n);
        for (int k = 2; k <= n; k += 2) new_a += coeff[k] * std::pow(a, n - k) * std::pow(b, k);
        double new_b = 0.0;
        for (int k = 1; k <= n; k += 2) new_b += coeff[k] * std::pow(a, n - k) * std::pow(b, k);
        a = new_a + cr;
        b = new_b + ci;
        const double dist2 = a * a + b * b;
        if (dist2 < mindist2) mindist2 = dist2;
        if (dist2 > 4.0) return exterior(pat, col, a, b);
    }
    return interior(pat, a, b, mindist2);
}

double power_fractal(const scene::Pattern& pat, double a, double b, double cr, double ci) {
    switch (pat.params->fractal_exponent) {
        case 2:
            return escape<2>(pat, a, b, cr, ci);
        case 3:
            return escape<3>(pat, a, b, cr, ci);
        case 4:
            return escape<4>(pat, a, b, cr, ci);
        default:
            return escape_x(pat, a, b, cr, ci);
    }
}

// One magnet step: z ← ((z² + c − 1) / (2z + c − 2))² (type 1) or its cubic form (type 2).
double magnet(const scene::Pattern& pat, double a, double b, double cr, double ci, double mindist2) {
    double a2 = a * a, b2 = b * b;
    const double c1r = cr - 1.0, c2r = cr - 2.0;
    const double c1c2r = c1r * c2r - ci * ci, c1c2i = (c1r + c2r) * ci;
    const int it_max = pat.params->fractal_iterations;
    for (int col = 0; col < it_max; ++col) {
        double t1r, t1i, t2r, t2i;
        if (pat.params->magnet_type == 1) {
            t1r = a2 - b2 + cr - 1;
            t1i = 2 * a * b + ci;
            t2r = 2 * a + cr - 2;
            t2i = 2 * b + ci;
        } else {
            t1r = a2 * a - 3 * a * b2 + 3 * (a * c1r - b * ci) + c1c2r;
            t1i = 3 * a2 * b - b2 * b + 3 * (a * ci + b * c1r) + c1c2i;
            t2r = 3 * (a2 - b2) + 3 * (a * c2r - b * ci) + c1c2r + 1;
            t2i = 6 * a * b + 3 * (a * ci + b * c2r) + c1c2i;
        }
        const double t = t2r * t2r + t2i * t2i;
        a = (t1r * t2r + t1i * t2i) / t;
        b = (t1i * t2r - t1r * t2i) / t;
        b2 = b * b;
        b = 2 * a * b;
        a = a * a - b2;
        a2 = a * a;
        b2 = b * b;
        const double dist2 = a2 + b2;
        if (dist2 < mindist2) mindist2 = dist2;
        const double d = a - 1;
        if (dist2 > 10000.0 || d * d + b2 < 1 / 10000.0) return exterior(pat, col, a, b);
    }
    return interior(pat, a, b, mindist2);
}

}  // namespace

double mandel_pattern(const scene::Pattern& pat, const Vec3& p, int) {
    return power_fractal(pat, p.x, p.y, p.x, p.y);
}

double julia_pattern(const scene::Pattern& pat, const Vec3& p, int) {
    return power_fractal(pat, p.x, p.y, pat.params->julia_re, pat.params->julia_im);
}

double magnet_pattern(const scene::Pattern& pat, const Vec3& p, int) {
    if (pat.params->magnet_julia) return magnet(pat, p.x, p.y, pat.params->julia_re, pat.params->julia_im, p.x * p.x + p.y * p.y);
    return magnet(pat, 0.0, 0.0, p.x, p.y, 10000.0);
}

}  // namespace wardray::texture
