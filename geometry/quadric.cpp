// QuadricShape: the quadratic along the ray, solved in stable form with one Newton step.
#include "geometry/quadric.h"

#include <algorithm>
#include <cmath>

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
