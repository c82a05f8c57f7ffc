// SuperellipsoidShape: marching with bisection refinement, analytic gradient for the normal.
#include "geometry/superellipsoid.h"

#include <algorithm>
#include <cmath>
#include <array>
#include <limits>

#if defined(__x86_64__) && defined(WARDRAY_HAVE_MVEC)
#include <immintrin.h>
// glibc's libmvec: pow on four doubles at once (AVX2; within 4 ulp of the exact power).
extern "C" __m256d _ZGVdN4vv_pow(__m256d x, __m256d y);
#define WARDRAY_VECTOR_POW 1
#endif

namespace wardray::geometry {
namespace {

#ifdef WARDRAY_VECTOR_POW
bool cpu_has_avx2() {
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
}
const bool kCpuHasAvx2 = cpu_has_avx2();
bool g_vector_pow = kCpuHasAvx2;

/// level() at the points origin + t[i] direction for i < count (a multiple of 4), four at a time.
__attribute__((target("avx2,fma"))) void levels_avx2(const Vec3& origin, const Vec3& direction, const double* t,
                                                      std::size_t count, double a, double e_over_n, double b,
                                                      double* out) {
    const __m256d sign = _mm256_set1_pd(-0.0);
    const __m256d va = _mm256_set1_pd(a), vb = _mm256_set1_pd(b), ven = _mm256_set1_pd(e_over_n);
    const __m256d one = _mm256_set1_pd(1.0);
    const __m256d ox = _mm256_set1_pd(origin.x), oy = _mm256_set1_pd(origin.y), oz = _mm256_set1_pd(origin.z);
    const __m256d dx = _mm256_set1_pd(direction.x), dy = _mm256_set1_pd(direction.y),
                  dz = _mm256_set1_pd(direction.z);
    for (std::size_t i = 0; i < count; i += 4) {
        const __m256d vt = _mm256_loadu_pd(t + i);
        // origin + t · direction, as the scalar code rounds it (a multiply, then an add: no fused step).
        const __m256d x = _mm256_andnot_pd(sign, _mm256_add_pd(ox, _mm256_mul_pd(vt, dx)));
        const __m256d y = _mm256_andnot_pd(sign, _mm256_add_pd(oy, _mm256_mul_pd(vt, dy)));
        const __m256d z = _mm256_andnot_pd(sign, _mm256_add_pd(oz, _mm256_mul_pd(vt, dz)));
        const __m256d xy = _mm256_add_pd(_ZGVdN4vv_pow(x, va), _ZGVdN4vv_pow(y, va));
        const __m256d f = _mm256_add_pd(_ZGVdN4vv_pow(xy, ven), _ZGVdN4vv_pow(z, vb));
        _mm256_storeu_pd(out + i, _mm256_sub_pd(f, one));
    }
}
#endif

}  // namespace

bool SuperellipsoidShape::use_vector_pow(bool wanted) {
#ifdef WARDRAY_VECTOR_POW
    g_vector_pow = wanted && kCpuHasAvx2;
    return g_vector_pow;
#else
    (void)wanted;
    return false;
#endif
}

std::optional<SuperellipsoidShape> SuperellipsoidShape::create(const scene::Superellipsoid& s) {
    if (!(s.e > 0.0) || !(s.n > 0.0) || !std::isfinite(s.e) || !std::isfinite(s.n)) return std::nullopt;
    return SuperellipsoidShape(s.e, s.n);
}

double SuperellipsoidShape::implicit(const Vec3& p) const {
    // Raised to the power n/2, the function behaves like a distance near the surface for every exponent.
    const double xy = std::pow(std::fabs(p.x), 2.0 / m_e) + std::pow(std::fabs(p.y), 2.0 / m_e);
    const double f = std::pow(xy, m_e / m_n) + std::pow(std::fabs(p.z), 2.0 / m_n);
    return std::pow(f, m_n / 2.0) - 1.0;
}

double SuperellipsoidShape::level(const Vec3& p) const {
    const double xy = std::pow(std::fabs(p.x), 2.0 / m_e) + std::pow(std::fabs(p.y), 2.0 / m_e);
    return std::pow(xy, m_e / m_n) + std::pow(std::fabs(p.z), 2.0 / m_n) - 1.0;
}

Vec3 SuperellipsoidShape::gradient(const Vec3& p) const {
    const double a = 2.0 / m_e;
    const double b = 2.0 / m_n;
    const double ax = std::fabs(p.x), ay = std::fabs(p.y), az = std::fabs(p.z);
    const double xy = std::pow(ax, a) + std::pow(ay, a);
    const double outer = xy > 0.0 ? (m_e / m_n) * std::pow(xy, m_e / m_n - 1.0) : 0.0;
    auto dpow = [](double v, double e) { return v > 0.0 ? e * std::pow(v, e - 1.0) : 0.0; };
    return {std::copysign(outer * dpow(ax, a), p.x), std::copysign(outer * dpow(ay, a), p.y),
            std::copysign(dpow(az, b), p.z)};
}

SurfaceHits SuperellipsoidShape::intersect_all(const LocalRay& ray, double t_min, double t_max) const {
    SurfaceHits hits;
    // Clip the ray to the unit box (slightly grown so surface points on the box faces are not lost).
    double t0 = t_min, t1 = t_max;
    for (int k = 0; k < 3; ++k) {
        const double o = ray.origin[k], d = ray.direction[k];
        if (d == 0.0) {
            if (std::fabs(o) > 1.0 + 1e-9) return hits;
            continue;
        }
        double ta = (-1.0 - 1e-9 - o) / d, tb = (1.0 + 1e-9 - o) / d;
        if (ta > tb) std::swap(ta, tb);
        t0 = std::fmax(t0, ta);
        t1 = std::fmin(t1, tb);
    }
    if (!(t0 < t1)) return hits;
    // Only signs and a bracketed root are needed: the level function (no final power) has the implicit's sign.
    auto f = [&](double t) { return level(ray.origin + t * ray.direction); };
    // Samples: even steps fine enough for the corners of small exponents, plus the ray's crossings of the nine
    // symmetry planes (x, y, z = 0 and x = ±y, x = ±z, y = ±z). The thin spikes of exponents above 2 lie along
    // those planes' intersections, where a sign change can hide between even steps (as POV-Ray samples them).
    constexpr int steps = 96;
    std::array<double, steps + 10> ts;
    std::size_t count = 0;
    for (int i = 0; i < steps; ++i) ts[count++] = t0 + i * ((t1 - t0) / steps);
    ts[count++] = t1;
    static constexpr double planes[9][3] = {{1, 1, 0}, {1, -1, 0}, {1, 0, 1}, {1, 0, -1}, {0, 1, 1},
                                            {0, 1, -1}, {1, 0, 0},  {0, 1, 0}, {0, 0, 1}};
    for (const auto& n : planes) {
        const double d = n[0] * ray.direction.x + n[1] * ray.direction.y + n[2] * ray.direction.z;
        if (std::fabs(d) < 1e-12) continue;
        const double t = -(n[0] * ray.origin.x + n[1] * ray.origin.y + n[2] * ray.origin.z) / d;
        if (t > t0 && t < t1) ts[count++] = t;
    }
    // The even steps are in order: sort the few plane crossings and merge them in.
    std::sort(ts.begin() + steps + 1, ts.begin() + count);
    std::inplace_merge(ts.begin(), ts.begin() + steps + 1, ts.begin() + count);
    // The samples' signs, four at a time where the CPU can (the powers within a few ulp: a sign can differ from the
    // exact one only within about 1e-15 of the surface, where a root at the sample is as good as one beside it);
    // the roots are refined with the exact function.
    std::array<double, steps + 12> fs;
    std::size_t evaluated = 0;
#ifdef WARDRAY_VECTOR_POW
    if (g_vector_pow) {
        evaluated = count / 4 * 4;
        levels_avx2(ray.origin, ray.direction, ts.data(), evaluated, 2.0 / m_e, m_e / m_n, 2.0 / m_n, fs.data());
    }
#endif
    for (std::size_t i = evaluated; i < count; ++i) fs[i] = f(ts[i]);
    double ta = ts[0];
    double fa = fs[0];
    for (std::size_t i = 1; i < count; ++i) {
        const double tb = ts[i];
        if (!(tb > ta)) continue;
        const double fb = fs[i];
        if ((fa < 0.0) != (fb < 0.0)) {
            // The Illinois form of false position: superlinear on these steep functions where bisection needs
            // some 50 halvings, and the root stays bracketed.
            double lo = ta, hi = tb, flo = fa, fhi = fb;
            int kept = 0;  // which end the last two steps kept: -1 lo moved, +1 hi moved
            for (int it = 0; it < 100 && hi - lo > 1e-14 * std::fmax(1.0, std::fabs(lo)); ++it) {
                double mid = (flo * hi - fhi * lo) / (flo - fhi);
                if (!(mid > lo && mid < hi)) mid = 0.5 * (lo + hi);
                const double fm = f(mid);
                if (fm == 0.0) {
                    lo = hi = mid;
                    break;
                }
                if ((fm < 0.0) == (flo < 0.0)) {
                    lo = mid;
                    flo = fm;
                    if (kept == -1) fhi *= 0.5;
                    kept = -1;
                } else {
                    hi = mid;
                    fhi = fm;
                    if (kept == 1) flo *= 0.5;
                    kept = 1;
                }
            }
            const double t = 0.5 * (lo + hi);
            if (t > t_min && t < t_max) {
                const Vec3 normal = gradient(ray.origin + t * ray.direction);
                hits.push({t, normal, fa >= 0.0});
            }
        }
        ta = tb;
        fa = fb;
    }
    return hits;
}

}  // namespace wardray::geometry
