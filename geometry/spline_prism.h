// SplinePrismShape: POV-Ray's prism with a quadratic, cubic or Bézier outline and a linear sweep, intersected
// analytically in object space.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "geometry/prism_outline.h"
#include "geometry/shape.h"
#include "scene/scene.h"

namespace wardray::geometry {

/// The outline (u, v) lies in the x-z plane and is swept along y from height1 to height2. A ray meets a piece's wall
/// where its x-z projection crosses the piece (a cubic in the piece parameter) at a height within the sweep; the
/// caps hold the points inside the outline by the even-odd rule. (Conic sweeps stay meshes: see prism.cpp.)
class SplinePrismShape {
public:
    /// Returns nothing for a linear outline, a conic sweep, equal heights or non-finite numbers.
    static std::optional<SplinePrismShape> create(const scene::Prism& prism);

    /// Crossings with t in (t_min, t_max), sorted.
    SurfaceHits intersect_all(const LocalRay& ray, double t_min, double t_max) const;
    /// Object-space bounds.
    std::optional<Bounds> bounds() const { return m_bounds; }
    /// Inside the outline and between the heights (POV-Ray's test, caps included).
    bool inside(const Vec3& p) const;
    /// Distance to the surface, negative inside.
    double implicit(const Vec3& p) const;

private:
    SplinePrismShape() = default;
    bool inside_outline(double u, double v) const;
    double outline_distance(double u, double v) const;

    /// A piece's extent in u and v.
    struct Box {
        double u_lo, u_hi, v_lo, v_hi;
    };

    std::shared_ptr<const std::vector<PrismPiece>> m_pieces;
    std::shared_ptr<const std::vector<Box>> m_boxes;  ///< per piece
    double m_h1 = 0.0;
    double m_h2 = 1.0;
    bool m_open = false;
    Bounds m_bounds;
};

}  // namespace wardray::geometry
