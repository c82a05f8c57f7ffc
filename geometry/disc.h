// DiscShape: POV-Ray's `disc { center, normal, radius [, hole_radius] }` in object space.
#pragma once

#include <optional>

#include "geometry/shape.h"
#include "scene/scene.h"

namespace wardray::geometry {

/// A flat annulus; like a plane, its inside is the half-space opposite to its normal.
class DiscShape {
public:
    /// Returns nothing for a zero normal, a zero radius or non-finite numbers.
    static std::optional<DiscShape> create(const scene::Disc& disc);

    /// The single crossing with t in (t_min, t_max), if the ray passes through the annulus.
    SurfaceHits intersect_all(const LocalRay& ray, double t_min, double t_max) const;
    /// Object-space bounding box of the disc.
    std::optional<Bounds> bounds() const;
    /// The inside is a half-space: unbounded.
    std::optional<Bounds> region_bounds() const { return std::nullopt; }
    /// True for points strictly behind the disc's plane.
    bool inside(const Vec3& p) const { return dot(m_normal, p - m_center) < 0.0; }
    /// Distance from the disc's plane (zero on the surface).
    double implicit(const Vec3& p) const { return dot(m_normal, p - m_center); }

private:
    DiscShape(const Vec3& c, const Vec3& n, double r, double h) : m_center(c), m_normal(n), m_r2(r * r), m_h2(h * h) {}

    Vec3 m_center;
    Vec3 m_normal;  ///< unit
    double m_r2;
    double m_h2;
};

}  // namespace wardray::geometry
