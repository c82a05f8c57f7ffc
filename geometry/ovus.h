// OvusShape: POV-Ray 3.7's `ovus { bottom_radius, top_radius }`, an egg of two spheres and a spindle band.
#pragma once

#include <optional>

#include "geometry/shape.h"
#include "scene/scene.h"

namespace wardray::geometry {

/// Around the y axis: the bottom sphere (radius b at the origin) below y = bottom_vertical, the top sphere (radius
/// t at <0, b, 0>) above y = top_vertical, and between them the inner ("lemon") part of a spindle torus whose tube
/// radius is twice the larger radius, tangent to both spheres. POV-Ray compat: with t >= 2 b, the top sphere alone.
class OvusShape {
public:
    /// Returns nothing for negative, non-finite or all-zero radii.
    static std::optional<OvusShape> create(const scene::Ovus& ovus);

    /// Up to two crossings (four where rounding splits a tangent join) with t in (t_min, t_max), sorted.
    SurfaceHits intersect_all(const LocalRay& ray, double t_min, double t_max) const;
    /// POV-Ray's box: |x|, |z| up to the widest radius, y from -b to b + t.
    std::optional<Bounds> bounds() const;
    /// Inside either sphere, or inside the band's spindle between the two joins (POV-Ray's Inside).
    bool inside(const Vec3& p) const;
    /// Least signed distance to the three pieces (zero on the surface, negative inside).
    double implicit(const Vec3& p) const;

private:
    OvusShape() = default;

    double m_bottom = 1.0;       ///< b
    double m_top = 0.5;          ///< t
    double m_horizontal = 0.0;   ///< distance of the spindle's tube centre from the axis (on the far side)
    double m_vertical = 0.0;     ///< height of the spindle's centre plane
    double m_bottom_join = 0.0;  ///< y where the band meets the bottom sphere
    double m_top_join = 0.0;     ///< y where the band meets the top sphere
    double m_connecting = 0.0;   ///< the spindle's tube radius
    bool m_sphere_only = false;  ///< t >= 2 b: the top sphere alone
};

}  // namespace wardray::geometry
