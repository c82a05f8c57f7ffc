// PlaneShape: POV-Ray's unbounded `plane { normal, distance }` in object space.
#pragma once

#include <optional>

#include "core/constants.h"
#include "geometry/shape.h"
#include "scene/scene.h"

namespace wardray::geometry {

/// The half-space dot(n̂, p) <= d, whose surface is the plane dot(n̂, p) = d.
class PlaneShape {
public:
    /// Returns nothing for a zero or non-finite normal or a non-finite distance.
    static std::optional<PlaneShape> create(const scene::Plane& plane);

    /// The single crossing with t in (t_min, t_max), if the ray is not parallel to the plane.
    SurfaceHits intersect_all(const LocalRay& ray, double t_min, double t_max) const;
    /// Planes are unbounded: always nothing.
    std::optional<Bounds> bounds() const { return std::nullopt; }
    /// True for points below the plane (on the side opposite to the normal) and those on it. POV-Ray compat:
    /// Plane::Inside tests dot(n̂, p) - d < EPSILON, so a CSG keeps a surface that coincides with a plane's.
    bool inside(const Vec3& p) const { return dot(m_normal, p) - m_distance < kPovEpsilon; }
    /// The plane with its inside and outside swapped. POV-Ray compat: `inverse` negates a plane's normal and
    /// distance (Plane::Invert), so the points on it stay inside, which flipping the inside test would lose.
    PlaneShape inverted() const { return PlaneShape(-m_normal, -m_distance); }
    /// Signed distance to the plane (negative inside).
    double implicit(const Vec3& p) const { return dot(m_normal, p) - m_distance; }

    /// The unit normal and the distance along it in object space.
    const Vec3& normal() const { return m_normal; }
    double distance() const { return m_distance; }

private:
    PlaneShape(const Vec3& unit_normal, double distance) : m_normal(unit_normal), m_distance(distance) {}

    Vec3 m_normal;
    double m_distance;
};

}  // namespace wardray::geometry
