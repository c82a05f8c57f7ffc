// TorusShape: the quartic in the distance along the unit ray from its point nearest the centre.
#include "geometry/torus.h"

#include <cmath>

#include "geometry/polynomial.h"

namespace wardray::geometry {

std::optional<TorusShape> TorusShape::create(const scene::Torus& t) {
    // POV-Ray compat: both radii are used by absolute value.
    const double major = std::fabs(t.major);
    const double minor = std::fabs(t.minor);
    if (!std::isfinite(major) || !std::isfinite(minor) || minor == 0.0) return std::nullopt;
    return TorusShape(major, minor);
}

SurfaceHits TorusShape::intersect_all(const LocalRay& ray, double t_min, double t_max) const {
    SurfaceHits hits;
    const auto line = centre_line(ray);
    if (!line) return hits;
    const auto& [u, o, s0, len] = *line;
    const double outer = m_major + m_minor;
    const double h2 = outer * outer - dot(o, o);
    if (h2 < 0.0) return hits;
    const double half = std::sqrt(h2) * (1.0 + 1e-9) + 1e-12 * outer;
    // (|o + s u|² + R² - r²)² - 4R²((ox + s ux)² + (oz + s uz)²) with |u| = 1 and o·u = 0.
    const double R2 = m_major * m_major;
    const double k = dot(o, o) + R2 - m_minor * m_minor;
    const double oxz = o.x * o.x + o.z * o.z;
    const double oduxz = o.x * u.x + o.z * u.z;
    const double uxz = u.x * u.x + u.z * u.z;
    const double c[5] = {k * k - 4.0 * R2 * oxz, -8.0 * R2 * oduxz, 2.0 * k - 4.0 * R2 * uxz, 0.0, 1.0};
    double roots[4];
    const int n = polynomial_roots(c, 4, -half, half, roots);
    for (int i = 0; i < n; ++i) {
        const double t = (s0 + roots[i]) / len;
        if (!(t > t_min && t < t_max)) continue;
        const Vec3 p = ray.origin + t * ray.direction;
        // Gradient of the quartic: 4 (|p|² + R² - r²) p - 8 R² (x, 0, z).
        const double g = dot(p, p) + R2 - m_minor * m_minor;
        const Vec3 normal = g * p - 2.0 * R2 * Vec3{p.x, 0.0, p.z};
        hits.push({t, normal, dot(normal, ray.direction) < 0.0});
    }
    return hits;
}

std::optional<Bounds> TorusShape::bounds() const {
    const double outer = m_major + m_minor;
    return Bounds{{-outer, -m_minor, -outer}, {outer, m_minor, outer}};
}

double TorusShape::implicit(const Vec3& p) const {
    const double ring = std::sqrt(p.x * p.x + p.z * p.z) - m_major;
    return std::sqrt(ring * ring + p.y * p.y) - m_minor;
}

}  // namespace wardray::geometry
