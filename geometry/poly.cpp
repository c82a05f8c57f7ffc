// PolyShape: the polynomial along the ray from products of powers of the linear coordinate polynomials; cubics
// and quartics expanded and solved as POV-Ray does.
#include "geometry/poly.h"

#include <cmath>
#include <vector>

#include "geometry/polynomial.h"

namespace wardray::geometry {

namespace {

double ipow(double v, int e) {
    double r = 1.0;
    for (int n = 0; n < e; ++n) r *= v;
    return r;
}

// POV-Ray's MAX_ORDER.
constexpr int k_max_order = 35;
// POV-Ray's INSIDE_TOLERANCE of poly.cpp (its quartic, torus and blob code tests against 0).
constexpr double k_poly_inside_tolerance = 1e-4;
// POV-Ray compat: poly.cpp's DEPTH_TOLERANCE (roots nearer the ray's origin are dropped) and ROOT_TOLERANCE (the
// epsilon of Solve_Polynomial's dropping of a root near 0).
constexpr double k_depth_tolerance = 1e-4;
constexpr double k_root_tolerance = 1e-4;

// The binomial coefficient n over k, exact for the orders allowed.
double binomial(int n, int k) {
    double b = 1.0;
    for (int i = 1; i <= k; ++i) b = b * (n - k + i) / i;
    return b;
}

// Coefficients (in s) of (o + s d)^e for e = 0..order, row e at out[e * (order + 1)].
void linear_powers(double o, double d, int order, double* out) {
    const int w = order + 1;
    for (int n = 0; n < w * w; ++n) out[n] = 0.0;
    out[0] = 1.0;
    for (int e = 1; e <= order; ++e)
        for (int n = 0; n <= e; ++n)
            out[e * w + n] = o * out[(e - 1) * w + n] + (n > 0 ? d * out[(e - 1) * w + n - 1] : 0.0);
}

}  // namespace

std::optional<PolyShape> PolyShape::from_coefficients(const double* coefficients, int order) {
    if (order < 1 || order > k_max_order) return std::nullopt;
    PolyShape shape;
    shape.m_order = order;
    int index = 0;
    bool any = false;
    // POV-Ray's order: descending powers of x, then of y, then of z.
    for (int i = order; i >= 0; --i)
        for (int j = order - i; j >= 0; --j)
            for (int k = order - i - j; k >= 0; --k) {
                const double a = coefficients[index++];
                if (!std::isfinite(a)) return std::nullopt;
                if (a == 0.0) continue;
                any = any || i + j + k > 0;
                shape.m_terms.push_back({a, i, j, k});
            }
    if (!any) return std::nullopt;
    return shape;
}

std::optional<PolyShape> PolyShape::create(const scene::Quartic& q) {
    auto shape = from_coefficients(q.coefficients.data(), 4);
    if (shape) shape->m_sturm = q.sturm;
    return shape;
}

std::optional<PolyShape> PolyShape::create(const scene::Poly& p) {
    const std::size_t terms = static_cast<std::size_t>((p.order + 1) * (p.order + 2) * (p.order + 3) / 6);
    if (p.order < 1 || p.order > k_max_order || p.coefficients.size() != terms) return std::nullopt;
    auto shape = from_coefficients(p.coefficients.data(), p.order);
    if (shape) {
        shape->m_inside_tolerance = k_poly_inside_tolerance;
        shape->m_sturm = p.sturm;
    }
    return shape;
}

double PolyShape::implicit(const Vec3& p) const {
    double f = 0.0;
    for (const Term& t : m_terms) {
        f += t.a * ipow(p.x, t.i) * ipow(p.y, t.j) * ipow(p.z, t.k);
    }
    return f;
}

Vec3 PolyShape::gradient(const Vec3& p) const {
    Vec3 g;
    for (const Term& t : m_terms) {
        const double px = ipow(p.x, t.i), py = ipow(p.y, t.j), pz = ipow(p.z, t.k);
        if (t.i > 0) g.x += t.a * t.i * ipow(p.x, t.i - 1) * py * pz;
        if (t.j > 0) g.y += t.a * t.j * px * ipow(p.y, t.j - 1) * pz;
        if (t.k > 0) g.z += t.a * t.k * px * py * ipow(p.z, t.k - 1);
    }
    return g;
}

SurfaceHits PolyShape::intersect_all(const LocalRay& ray, double t_min, double t_max) const {
    return m_order == 3 || m_order == 4 ? intersect_pov(ray, t_min, t_max) : intersect_centred(ray, t_min, t_max);
}

SurfaceHits PolyShape::intersect_pov(const LocalRay& ray, double t_min, double t_max) const {
    SurfaceHits hits;
    const double len = length(ray.direction);
    if (!(len > 0.0) || !std::isfinite(len)) return hits;
    const Vec3 d = ray.direction * (1.0 / len);
    const int w = m_order + 1;
    // Powers 0..order of the origin's and the unit direction's coordinates, by repeated multiplication.
    std::vector<double> work(static_cast<std::size_t>(6 * w + 3 * w + w));
    double* p_pow[3] = {work.data(), work.data() + w, work.data() + 2 * w};
    double* d_pow[3] = {work.data() + 3 * w, work.data() + 4 * w, work.data() + 5 * w};
    double* expanded[3] = {work.data() + 6 * w, work.data() + 7 * w, work.data() + 8 * w};
    double* eqn = work.data() + 9 * w;  // eqn[h]: the coefficient of s^(order - h)
    const double p[3] = {ray.origin.x, ray.origin.y, ray.origin.z}, u[3] = {d.x, d.y, d.z};
    for (int a = 0; a < 3; ++a) {
        p_pow[a][0] = d_pow[a][0] = 1.0;
        for (int e = 1; e <= m_order; ++e) {
            p_pow[a][e] = p[a] * (e > 1 ? p_pow[a][e - 1] : 1.0);
            d_pow[a][e] = u[a] * (e > 1 ? d_pow[a][e - 1] : 1.0);
        }
    }
    // POV-Ray compat (Poly::intersect): each monomial's factors (p + s u)^e expanded by the binomial theorem, index
    // h the power of p, and their products summed term by term in POV-Ray's order.
    for (const Term& t : m_terms) {
        const int e[3] = {t.i, t.j, t.k};
        for (int a = 0; a < 3; ++a)
            for (int h = 0; h <= e[a]; ++h) expanded[a][h] = binomial(e[a], h) * d_pow[a][e[a] - h] * p_pow[a][h];
        const int offset = m_order - (t.i + t.j + t.k);
        for (int i1 = 0; i1 <= t.i; ++i1)
            for (int j1 = 0; j1 <= t.j; ++j1)
                for (int k1 = 0; k1 <= t.k; ++k1) {
                    double v = t.a;
                    v *= expanded[0][i1];
                    v *= expanded[1][j1];
                    v *= expanded[2][k1];
                    eqn[offset + i1 + j1 + k1] += v;
                }
    }
    // Leading coefficients exactly zero lower the order; below a quadratic POV-Ray finds nothing.
    int lead = 0;
    while (lead <= m_order && eqn[lead] == 0.0) ++lead;
    const int order = m_order - lead;
    if (order <= 1) return hits;
    std::vector<double> depths(static_cast<std::size_t>(order));
    const int n = solve_polynomial_pov(eqn + lead, order, depths.data(), m_sturm, k_root_tolerance);
    for (int r = 0; r < n; ++r) {
        if (!(depths[r] > k_depth_tolerance)) continue;
        bool repeated = false;
        for (int q = 0; q < r; ++q) repeated = repeated || depths[q] == depths[r];
        const double t = depths[r] / len;
        if (repeated || !(t > t_min && t < t_max)) continue;
        const Vec3 normal = gradient(ray.origin + t * ray.direction);
        if (!(length(normal) > 0.0)) continue;
        hits.push({t, normal, dot(normal, ray.direction) < 0.0});
    }
    hits.sort_by_t();
    return hits;
}

SurfaceHits PolyShape::intersect_centred(const LocalRay& ray, double t_min, double t_max) const {
    SurfaceHits hits;
    const auto line = centre_line(ray);
    if (!line) return hits;
    const auto& [u, o, s0, len] = *line;
    const int w = m_order + 1;
    std::vector<double> powers(static_cast<std::size_t>(3 * w * w + 2 * w));
    double* px = powers.data();
    double* py = px + w * w;
    double* pz = py + w * w;
    double* c = pz + w * w;
    double* xy = c + w;
    linear_powers(o.x, u.x, m_order, px);
    linear_powers(o.y, u.y, m_order, py);
    linear_powers(o.z, u.z, m_order, pz);
    for (const Term& t : m_terms) {
        // Product of the three power polynomials; the total degree never exceeds the order.
        for (int n = 0; n <= t.i + t.j; ++n) xy[n] = 0.0;
        for (int a = 0; a <= t.i; ++a)
            for (int b = 0; b <= t.j; ++b) xy[a + b] += px[t.i * w + a] * py[t.j * w + b];
        for (int ab = 0; ab <= t.i + t.j; ++ab)
            for (int e = 0; e <= t.k; ++e) c[ab + e] += t.a * xy[ab] * pz[t.k * w + e];
    }
    int degree = m_order;
    while (degree > 0 && c[degree] == 0.0) --degree;
    if (degree == 0) return hits;
    // Cauchy's bound: every real root lies within 1 + max |c_i / c_degree|.
    double bound = 0.0;
    for (int i = 0; i < degree; ++i) bound = std::fmax(bound, std::fabs(c[i] / c[degree]));
    bound += 1.0;
    const double lo = std::fmax(t_min * len - s0, -bound);
    const double hi = std::fmin(t_max * len - s0, bound);
    if (!(lo < hi)) return hits;
    std::vector<double> roots(static_cast<std::size_t>(degree));
    const int n = polynomial_roots(c, degree, lo, hi, roots.data());
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
