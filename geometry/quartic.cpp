// QuarticShape: the polynomial along the ray from products of powers of the linear coordinate polynomials.
#include "geometry/quartic.h"

#include <cmath>

#include "geometry/polynomial.h"

namespace wardray::geometry {

namespace {

double ipow(double v, int e) {
    double r = 1.0;
    for (int n = 0; n < e; ++n) r *= v;
    return r;
}

// Coefficients (in s) of (o + s d)^e for e = 0..4.
void linear_powers(double o, double d, double out[5][5]) {
    for (int e = 0; e <= 4; ++e)
        for (int n = 0; n <= 4; ++n) out[e][n] = 0.0;
    out[0][0] = 1.0;
    for (int e = 1; e <= 4; ++e)
        for (int n = 0; n <= e; ++n) out[e][n] = o * out[e - 1][n] + (n > 0 ? d * out[e - 1][n - 1] : 0.0);
}

}  // namespace

std::optional<QuarticShape> QuarticShape::create(const scene::Quartic& q) {
    QuarticShape shape;
    int index = 0;
    bool any = false;
    // POV-Ray's order: descending powers of x, then of y, then of z.
    for (int i = 4; i >= 0; --i)
        for (int j = 4 - i; j >= 0; --j)
            for (int k = 4 - i - j; k >= 0; --k) {
                const double a = q.coefficients[index++];
                if (!std::isfinite(a)) return std::nullopt;
                if (a == 0.0) continue;
                any = any || i + j + k > 0;
                shape.m_terms[shape.m_count++] = {a, i, j, k};
            }
    if (!any) return std::nullopt;
    return shape;
}

double QuarticShape::implicit(const Vec3& p) const {
    double f = 0.0;
    for (int n = 0; n < m_count; ++n) {
        const Term& t = m_terms[n];
        f += t.a * ipow(p.x, t.i) * ipow(p.y, t.j) * ipow(p.z, t.k);
    }
    return f;
}

Vec3 QuarticShape::gradient(const Vec3& p) const {
    Vec3 g;
    for (int n = 0; n < m_count; ++n) {
        const Term& t = m_terms[n];
        const double px = ipow(p.x, t.i), py = ipow(p.y, t.j), pz = ipow(p.z, t.k);
        if (t.i > 0) g.x += t.a * t.i * ipow(p.x, t.i - 1) * py * pz;
        if (t.j > 0) g.y += t.a * t.j * px * ipow(p.y, t.j - 1) * pz;
        if (t.k > 0) g.z += t.a * t.k * px * py * ipow(p.z, t.k - 1);
    }
    return g;
}

SurfaceHits QuarticShape::intersect_all(const LocalRay& ray, double t_min, double t_max) const {
    SurfaceHits hits;
    const auto line = centre_line(ray);
    if (!line) return hits;
    const auto& [u, o, s0, len] = *line;
    double px[5][5], py[5][5], pz[5][5];
    linear_powers(o.x, u.x, px);
    linear_powers(o.y, u.y, py);
    linear_powers(o.z, u.z, pz);
    double c[5] = {0, 0, 0, 0, 0};
    for (int n = 0; n < m_count; ++n) {
        const Term& t = m_terms[n];
        // Product of the three power polynomials; the total degree never exceeds 4.
        double xy[5] = {0, 0, 0, 0, 0};
        for (int a = 0; a <= t.i; ++a)
            for (int b = 0; b <= t.j; ++b) xy[a + b] += px[t.i][a] * py[t.j][b];
        for (int ab = 0; ab <= t.i + t.j; ++ab)
            for (int e = 0; e <= t.k; ++e) c[ab + e] += t.a * xy[ab] * pz[t.k][e];
    }
    int degree = 4;
    while (degree > 0 && c[degree] == 0.0) --degree;
    if (degree == 0) return hits;
    // Cauchy's bound: every real root lies within 1 + max |c_i / c_degree|.
    double bound = 0.0;
    for (int i = 0; i < degree; ++i) bound = std::fmax(bound, std::fabs(c[i] / c[degree]));
    bound += 1.0;
    const double lo = std::fmax(t_min * len - s0, -bound);
    const double hi = std::fmin(t_max * len - s0, bound);
    if (!(lo < hi)) return hits;
    double roots[4];
    const int n = polynomial_roots(c, degree, lo, hi, roots);
    for (int i = 0; i < n; ++i) {
        const double t = (s0 + roots[i]) / len;
        if (!(t > t_min && t < t_max)) continue;
        const Vec3 normal = gradient(ray.origin + t * ray.direction);
        if (!(length(normal) > 0.0)) continue;
        hits.push({t, normal, dot(normal, ray.direction) < 0.0});
    }
    return hits;
}

}  // namespace wardray::geometry
