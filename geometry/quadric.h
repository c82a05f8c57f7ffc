// QuadricShape: POV-Ray's general second-degree surface `quadric { <A,B,C>, <D,E,F>, <G,H,I>, J }`.
#pragma once

#include <optional>

#include "geometry/shape.h"
#include "scene/scene.h"

namespace wardray::geometry {

/// The surface f(p) = 0 of a quadratic polynomial; inside where f < 0. Unbounded unless clipped or intersected.
class QuadricShape {
public:
    /// Returns nothing when a coefficient is not finite or all second- and first-degree ones vanish.
    static std::optional<QuadricShape> create(const scene::Quadric& quadric);

    /// Up to two crossings with t in (t_min, t_max), sorted.
    SurfaceHits intersect_all(const LocalRay& ray, double t_min, double t_max) const;
    /// Quadrics are treated as unbounded.
    std::optional<Bounds> bounds() const { return std::nullopt; }
    /// POV-Ray's bounding box of a clipped quadric where it needs no clip box (Quadric::Compute_BBox): an ellipsoid
    /// or a cylinder along an axis without mixed terms; nothing for the other forms.
    std::optional<Bounds> clipped_bounds() const;
    /// True where the polynomial is negative.
    bool inside(const Vec3& p) const { return implicit(p) < 0.0; }
    /// The polynomial's value.
    double implicit(const Vec3& p) const;
    /// Its coefficients, as `implicit` uses them.
    const scene::Quadric& coefficients() const { return m_q; }

private:
    explicit QuadricShape(const scene::Quadric& q) : m_q(q) {}
    Vec3 gradient(const Vec3& p) const;

    scene::Quadric m_q;
};

}  // namespace wardray::geometry
