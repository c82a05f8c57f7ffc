// SphereShape: POV-Ray's `sphere { center, radius }` in object space.
#pragma once

#include <optional>

#include "geometry/shape.h"
#include "scene/scene.h"

namespace wardray::geometry {

/// A sphere with a numerically stable ray intersection.
class SphereShape {
public:
    /// Returns nothing when the sphere is degenerate (zero or non-finite radius, non-finite centre).
    static std::optional<SphereShape> create(const scene::Sphere& sphere);

    /// Surface crossings with t in (t_min, t_max), entering first.
    SurfaceHits intersect_all(const LocalRay& ray, double t_min, double t_max) const;
    /// Object-space bounding box.
    std::optional<Bounds> bounds() const;
    /// True for points strictly inside the sphere.
    bool inside(const Vec3& p) const;
    /// Signed distance-like implicit function: |p - c| - r (negative inside).
    double implicit(const Vec3& p) const { return length(p - m_center) - m_radius; }

    /// Centre and (non-negative) radius in object space.
    const Vec3& center() const { return m_center; }
    double radius() const { return m_radius; }

private:
    SphereShape(const Vec3& center, double radius) : m_center(center), m_radius(radius) {}

    Vec3 m_center;
    double m_radius;
};

}  // namespace wardray::geometry
