// TorusShape: the quartic in the distance along the unit ray from its point nearest the centre.
#include "geometry/torus.h"

#include <algorithm>
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
    intersect_until(ray, t_min, t_max, [&](const SurfaceHit& hit) {
        hits.push(hit);
        return false;
    });
    return hits;
}

std::optional<TorusShape::Quartic> TorusShape::quartic(const LocalRay& ray, double t_min, double t_max) const {
    const auto line = centre_line(ray);
    if (!line) return std::nullopt;
    const auto& [u, o, s0, len] = *line;
    const double outer = m_major + m_minor;
    const double h2 = outer * outer - dot(o, o);
    if (h2 < 0.0) return std::nullopt;
    const double half = std::sqrt(h2) * (1.0 + 1e-9) + 1e-12 * outer;
    // Only the stretch of the chord within (t_min, t_max), as PolyShape searches: a gather or shadow ray starts on a
    // surface, often with most of the chord through the bounding sphere behind it.
    const double lo = std::fmax(-half, t_min * len - s0), hi = std::fmin(half, t_max * len - s0);
    if (!(lo <= hi) || misses_tube(u, o, lo, hi)) return std::nullopt;
    // (|o + s u|² + R² - r²)² - 4R²((ox + s ux)² + (oz + s uz)²) with |u| = 1 and o·u = 0.
    const double R2 = m_major * m_major;
    const double k = dot(o, o) + R2 - m_minor * m_minor;
    const double oxz = o.x * o.x + o.z * o.z;
    const double oduxz = o.x * u.x + o.z * u.z;
    const double uxz = u.x * u.x + u.z * u.z;
    return Quartic{{k * k - 4.0 * R2 * oxz, -8.0 * R2 * oduxz, 2.0 * k - 4.0 * R2 * uxz, 0.0, 1.0}, s0, len, lo, hi};
}

SurfaceHit TorusShape::crossing(const LocalRay& ray, double t) const {
    const Vec3 p = ray.origin + t * ray.direction;
    // Gradient of the quartic: 4 (|p|² + R² - r²) p - 8 R² (x, 0, z).
    const double R2 = m_major * m_major;
    const double g = dot(p, p) + R2 - m_minor * m_minor;
    const Vec3 normal = g * p - 2.0 * R2 * Vec3{p.x, 0.0, p.z};
    return {t, normal, dot(normal, ray.direction) < 0.0};
}

bool TorusShape::misses_tube(const Vec3& u, const Vec3& o, double lo, double hi) const {
    // The quartic is positive wherever |y| > r or the distance from the axis is outside [R - r, R + r] (there
    // (|p|² + R² - r²)² > 4 R² (x² + z²)), so a chord that stays out of that ring has no root to find. The margin
    // keeps the quartic well above its rounding error where this says "no"; below r = 1e-6 R it would not.
    const double r = m_minor, R = m_major;
    if (!(r >= 1e-6 * R)) return false;
    const double margin = 1e-4 * (R + r);
    const double slab = r + margin;
    // The chord's stretch within the slab |y| <= r + margin.
    if (u.y != 0.0) {
        double a = (-slab - o.y) / u.y, b = (slab - o.y) / u.y;
        if (a > b) std::swap(a, b);
        lo = std::fmax(lo, a);
        hi = std::fmin(hi, b);
        if (!(lo <= hi)) return true;
    } else if (!(std::fabs(o.y) <= slab)) {
        return true;
    }
    // x² + z² over that stretch: largest at an end, smallest at an end or at the parabola's vertex.
    auto rho2 = [&](double s) {
        const double x = o.x + s * u.x, z = o.z + s * u.z;
        return x * x + z * z;
    };
    const double at_lo = rho2(lo), at_hi = rho2(hi);
    double smallest = std::fmin(at_lo, at_hi);
    const double uxz = u.x * u.x + u.z * u.z;
    if (uxz > 0.0) {
        const double vertex = -(o.x * u.x + o.z * u.z) / uxz;
        if (vertex > lo && vertex < hi) smallest = std::fmin(smallest, rho2(vertex));
    }
    const double outer = R + r + margin;
    if (smallest > outer * outer) return true;
    const double inner = R - r - margin;
    return inner > 0.0 && std::fmax(at_lo, at_hi) < inner * inner;
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
