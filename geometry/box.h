// BoxShape: POV-Ray's axis-aligned `box { corner1, corner2 }` in object space.
#pragma once

#include <optional>

#include "geometry/shape.h"
#include "scene/scene.h"

namespace wardray::geometry {

/// An axis-aligned box intersected with the slab method.
class BoxShape {
public:
    /// Returns nothing when a corner is not finite. The corners may be given in any order.
    static std::optional<BoxShape> create(const scene::Box& box);

    /// Surface crossings with t in (t_min, t_max): the entering face, then the leaving face.
    SurfaceHits intersect_all(const LocalRay& ray, double t_min, double t_max) const;
    /// Object-space bounding box (the box itself).
    std::optional<Bounds> bounds() const { return Bounds{m_lower, m_upper}; }
    /// True for points strictly inside the box.
    bool inside(const Vec3& p) const;
    /// Signed distance to the surface (negative inside), exact outside and inside.
    double implicit(const Vec3& p) const;

    /// The minimum and maximum corners in object space.
    const Vec3& lower() const { return m_lower; }
    const Vec3& upper() const { return m_upper; }

private:
    BoxShape(const Vec3& lower, const Vec3& upper) : m_lower(lower), m_upper(upper) {}

    Vec3 m_lower;
    Vec3 m_upper;
};

}  // namespace wardray::geometry
