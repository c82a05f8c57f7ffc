// TorusShape: POV-Ray's `torus { major, minor }` around the y axis, in object space.
#pragma once

#include <optional>

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
    /// Object-space bounding box.
    std::optional<Bounds> bounds() const;
    /// True for points strictly inside the tube.
    bool inside(const Vec3& p) const { return implicit(p) < 0.0; }
    /// Distance to the tube's surface (negative inside).
    double implicit(const Vec3& p) const;

private:
    TorusShape(double major, double minor) : m_major(major), m_minor(minor) {}
    /// True when the chord o + s u, |s| <= half (u a unit vector), provably misses the tube: it never enters the
    /// slab |y| <= r or the ring R - r <= sqrt(x² + z²) <= R + r there, with a margin against rounding.
    bool misses_tube(const Vec3& u, const Vec3& o, double half) const;

    double m_major;
    double m_minor;
};

}  // namespace wardray::geometry
