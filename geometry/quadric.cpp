// QuadricShape: the quadratic along the ray, solved in stable form with one Newton step.
#include "geometry/quadric.h"

#include <algorithm>
#include <cmath>

#include "core/constants.h"

namespace wardray::geometry {

std::optional<QuadricShape> QuadricShape::create(const scene::Quadric& q) {
    if (!is_finite(q.squares) || !is_finite(q.mixed) || !is_finite(q.linear) || !std::isfinite(q.constant))
        return std::nullopt;
    if (q.squares == Vec3{} && q.mixed == Vec3{} && q.linear == Vec3{}) return std::nullopt;
    return QuadricShape(q);
}

double QuadricShape::implicit(const Vec3& p) const {
    const Vec3& a = m_q.squares;
    const Vec3& m = m_q.mixed;
    return a.x * p.x * p.x + a.y * p.y * p.y + a.z * p.z * p.z + m.x * p.x * p.y + m.y * p.x * p.z +
           m.z * p.y * p.z + dot(m_q.linear, p) + m_q.constant;
}

Vec3 QuadricShape::gradient(const Vec3& p) const {
    const Vec3& a = m_q.squares;
    const Vec3& m = m_q.mixed;
    return Vec3{2 * a.x * p.x + m.x * p.y + m.y * p.z, 2 * a.y * p.y + m.x * p.x + m.z * p.z,
                2 * a.z * p.z + m.y * p.x + m.z * p.y} +
           m_q.linear;
}

std::optional<Bounds> QuadricShape::clipped_bounds() const {
    // POV-Ray's coefficients: x² y² z² (A E H), half the mixed (B C F) and linear (D G I) ones, the constant J;
    // those below its epsilon count as 0.
    auto tiny = [](double v) { return std::fabs(v) < kPovEpsilon ? 0.0 : v; };
    double a = tiny(m_q.squares.x), e = tiny(m_q.squares.y), h = tiny(m_q.squares.z);
    double d = tiny(m_q.linear.x / 2.0), g = tiny(m_q.linear.y / 2.0), i = tiny(m_q.linear.z / 2.0);
    double j = tiny(m_q.constant);
    if (tiny(m_q.mixed.x / 2.0) != 0.0 || tiny(m_q.mixed.y / 2.0) != 0.0 || tiny(m_q.mixed.z / 2.0) != 0.0)
        return std::nullopt;
    // Linear terms: the centre moves to t, and the constant with it.
    Vec3 t;
    if (d != 0.0 || g != 0.0 || i != 0.0) {
        auto centre = [&](double sq, double lin) { return sq != 0.0 ? -lin / sq : lin != 0.0 ? j / (2.0 * lin) : 0.0; };
        t = {centre(a, d), centre(e, g), centre(h, i)};
        d += a * t.x;
        g += e * t.y;
        i += h * t.z;
        j -= t.x * (a * t.x + 2.0 * d) + t.y * (e * t.y + 2.0 * g) + t.z * (h * t.z + 2.0 * i);
    }
    if (a < 0.0) {
        a = -a;
        e = -e;
        h = -h;
        j = -j;
    }
    if (!(j < 0.0)) return std::nullopt;
    constexpr double k_half_huge = 1e10;  // POV-Ray's BOUND_HUGE / 2
    Vec3 lo{-k_half_huge, -k_half_huge, -k_half_huge}, hi{k_half_huge, k_half_huge, k_half_huge};
    // POV-Ray's closed forms: all three squares positive, or two with the third 0.
    if (e < 0.0 || h < 0.0 || int(a > 0.0) + int(e > 0.0) + int(h > 0.0) < 2) return std::nullopt;
    // Ellipsoid, or a cylinder along the axis whose square is missing: the other axes reach sqrt(-J / square).
    if (a > 0.0) lo.x = -(hi.x = std::sqrt(-j / a));
    if (e > 0.0) lo.y = -(hi.y = std::sqrt(-j / e));
    if (h > 0.0) lo.z = -(hi.z = std::sqrt(-j / h));
    return Bounds{lo + t, hi + t};
}

SurfaceHits QuadricShape::intersect_all(const LocalRay& ray, double t_min, double t_max) const {
    SurfaceHits hits;
    const Vec3& o = ray.origin;
    const Vec3& d = ray.direction;
    // f(o + t d) = qa t² + qb t + qc, with qa the quadratic form of d and qb the gradient at o along d.
    const Vec3& a = m_q.squares;
    const Vec3& m = m_q.mixed;
    const double qa = a.x * d.x * d.x + a.y * d.y * d.y + a.z * d.z * d.z + m.x * d.x * d.y + m.y * d.x * d.z +
                      m.z * d.y * d.z;
    const double qb = dot(gradient(o), d);
    const double qc = implicit(o);
    double roots[2];
    int n = 0;
    if (qa == 0.0) {
        if (qb != 0.0) roots[n++] = -qc / qb;
    } else {
        const double disc = qb * qb - 4.0 * qa * qc;
        if (disc >= 0.0) {
            const double q = -0.5 * (qb + std::copysign(std::sqrt(disc), qb));
            if (q != 0.0) {
                roots[n++] = qc / q;
                roots[n++] = q / qa;
            } else {
                roots[n++] = 0.0;
            }
        }
    }
    std::sort(roots, roots + n);
    for (int i = 0; i < n; ++i) {
        double t = roots[i];
        const double df = 2.0 * qa * t + qb;
        if (df != 0.0) t -= ((qa * t + qb) * t + qc) / df;
        if (!(t > t_min && t < t_max) || !std::isfinite(t)) continue;
        const Vec3 normal = gradient(o + t * d);
        hits.push({t, normal, dot(normal, d) < 0.0});
    }
    return hits;
}

}  // namespace wardray::geometry
