// SphereShape: stable quadratic intersection with one refinement step for distant ray origins.
#include "geometry/sphere.h"

#include <cmath>
#include <utility>

namespace wardray::geometry {

namespace {

// The root of a s^2 + 2 b s + c = 0 with the smallest magnitude, or 0 when the line misses the sphere.
double smallest_root(double a, double b, double c) {
    const double disc = b * b - a * c;
    if (disc < 0.0) return 0.0;
    const double q = -(b + std::copysign(std::sqrt(disc), b));
    return q != 0.0 ? c / q : 0.0;
}

}  // namespace

std::optional<SphereShape> SphereShape::create(const scene::Sphere& sphere) {
    // POV-Ray compat: a negative radius renders like its absolute value (checked with povray 3.7).
    const double r = std::fabs(sphere.radius);
    if (!is_finite(sphere.center) || !std::isfinite(r) || r == 0.0) return std::nullopt;
    return SphereShape(sphere.center, r);
}

SurfaceHits SphereShape::intersect_all(const LocalRay& ray, double t_min, double t_max) const {
    SurfaceHits hits;
    const Vec3& d = ray.direction;
    const double a = dot(d, d);
    if (!(a > 0.0)) return hits;
    const Vec3 oc = ray.origin - m_center;
    const double b = dot(d, oc);
    // Discriminant from the closest point of the line to the centre, which avoids the cancellation in b^2 - a c
    // for origins far away compared to the radius (Haines et al., Ray Tracing Gems ch. 7).
    const Vec3 f = oc - (b / a) * d;
    const double h2 = m_radius * m_radius - dot(f, f);
    if (h2 < 0.0) return hits;
    const double c = dot(oc, oc) - m_radius * m_radius;
    // Stable roots: q carries the sign of -b so that no difference of nearly equal numbers is formed.
    const double q = -(b + std::copysign(std::sqrt(a * h2), b));
    double roots[2];
    if (q == 0.0) {
        roots[0] = roots[1] = 0.0;  // b = 0 and h2 = 0: the ray touches the sphere at its origin
    } else {
        roots[0] = c / q;
        roots[1] = q / a;
    }
    if (roots[0] > roots[1]) std::swap(roots[0], roots[1]);
    for (int i = 0; i < 2; ++i) {
        double t = roots[i];
        // One refinement step from the approximate hit point: a far origin leaves an absolute error in t
        // proportional to the distance; solving again near the surface shrinks it to the scale of the point.
        const Vec3 p = ray.origin + t * d - m_center;
        t += smallest_root(a, dot(d, p), dot(p, p) - m_radius * m_radius);
        if (!(t > t_min && t < t_max)) continue;
        const Vec3 n = (ray.origin + t * d - m_center) / m_radius;
        hits.push({t, n, i == 0});
    }
    return hits;
}

std::optional<Bounds> SphereShape::bounds() const {
    const Vec3 r{m_radius, m_radius, m_radius};
    return Bounds{m_center - r, m_center + r};
}

bool SphereShape::inside(const Vec3& p) const {
    const Vec3 v = p - m_center;
    return dot(v, v) < m_radius * m_radius;
}

}  // namespace wardray::geometry
