// TorusShape: POV-Ray's `torus { major, minor }` around the y axis, in object space.
#pragma once

#include <optional>

#include "geometry/polynomial.h"
#include "geometry/shape.h"
#include "scene/scene.h"

namespace wardray::geometry {

/// A ring torus: (|p|² + R² - r²)² = 4 R² (x² + z²); the quartic is solved on a shifted, normalised ray.
class TorusShape {
public:
    /// Returns nothing for non-finite or zero radii.
    static std::optional<TorusShape> create(const scene::Torus& torus);

    /// Up to four crossings with t in (t_min, t_max), sorted.
    SurfaceHits intersect_all(const LocalRay& ray, double t_min, double t_max) const;
    /// intersect_all()'s crossings, the same in the same order, handed to `take` (returning true to stop) as they
    /// are found: the nearest crossing costs one root of the quartic, not all of them.
    template <typename Take>
    void intersect_until(const LocalRay& ray, double t_min, double t_max, Take&& take) const {
        const std::optional<Quartic> q = quartic(ray, t_min, t_max);
        if (!q) return;
        auto at = [&](double s) {
            const double t = (q->s0 + s) / q->len;
            return t > t_min && t < t_max && static_cast<bool>(take(crossing(ray, t)));
        };
        each_polynomial_root(q->c, 4, q->lo, q->hi, at);
    }
    /// Object-space bounding box.
    std::optional<Bounds> bounds() const;
    /// True for points strictly inside the tube.
    bool inside(const Vec3& p) const { return implicit(p) < 0.0; }
    /// Distance to the tube's surface (negative inside).
    double implicit(const Vec3& p) const;

private:
    TorusShape(double major, double minor) : m_major(major), m_minor(minor) {}
    /// True when the chord o + s u, lo <= s <= hi (u a unit vector), provably misses the tube: it never enters the
    /// slab |y| <= r or the ring R - r <= sqrt(x² + z²) <= R + r there, with a margin against rounding.
    bool misses_tube(const Vec3& u, const Vec3& o, double lo, double hi) const;
    /// The quartic in s along the unit ray o + s u from its point nearest the centre (t = (s0 + s) / len), and the
    /// stretch [lo, hi] of the chord through the bounding sphere within (t_min, t_max), where its roots are the
    /// crossings; nothing where the ray provably misses there.
    struct Quartic {
        double c[5];
        double s0, len, lo, hi;
    };
    std::optional<Quartic> quartic(const LocalRay& ray, double t_min, double t_max) const;
    /// The crossing at t (a root of the quartic): its unnormalised normal and whether the ray enters there.
    SurfaceHit crossing(const LocalRay& ray, double t) const;

    double m_major;
    double m_minor;
};

}  // namespace wardray::geometry
