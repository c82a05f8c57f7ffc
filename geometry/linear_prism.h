// LinearPrismShape: POV-Ray's prism with a linear outline and a linear sweep, intersected as POV-Ray 3.7 does.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "geometry/shape.h"
#include "scene/scene.h"

namespace wardray::geometry {

/// The outline's points (u, v) lie in the x-z plane and are swept along y from height1 to height2. POV-Ray compat
/// (Prism::All_Intersections, in_curve, Inside): the segments, the crossings, the caps' even-odd test and the height
/// tests in POV-Ray's arithmetic, so that ties land on POV-Ray's side: a ray level with a cap meets the walls
/// (their heights include both ends), a point on the top cap is outside. (Conic sweeps stay meshes: prism.cpp.)
class LinearPrismShape {
public:
    /// Returns nothing for a spline outline, a conic sweep, equal heights, fewer than three points or non-finite
    /// numbers. An unclosed outline is closed as POV-Ray's parser closes it.
    static std::optional<LinearPrismShape> create(const scene::Prism& prism);

    /// Crossings with t in (t_min, t_max), sorted; normals point out of the outline.
    SurfaceHits intersect_all(const LocalRay& ray, double t_min, double t_max) const;
    /// Object-space bounds.
    std::optional<Bounds> bounds() const { return m_bounds; }
    /// POV-Ray compat (Prism::Inside): inside the outline, height1 <= y < height2.
    bool inside(const Vec3& p) const;
    /// Distance to the surface, negative inside.
    double implicit(const Vec3& p) const;

    /// One segment of the outline, (u, v)(w) = d + w c for w in [0, 1], with its extent and outward side.
    struct Segment {
        double cu, cv;  ///< POV-Ray's C: the segment's end minus its start
        double du, dv;  ///< POV-Ray's D: its start
        double u_lo, u_hi, v_lo, v_hi;
        double side;    ///< +1 when (cv, -cu) points out of the outline, -1 when into it
    };

private:
    LinearPrismShape() = default;
    /// POV-Ray's in_curve: an odd number of segments met on the way from (u, v) toward +u.
    bool in_curve(double u, double v) const;

    std::shared_ptr<const std::vector<Segment>> m_segments;
    double m_u_lo = 0.0, m_u_hi = 0.0, m_v_lo = 0.0, m_v_hi = 0.0;  ///< the outline's extent
    double m_h1 = 0.0;
    double m_h2 = 1.0;
    bool m_open = false;
    Bounds m_bounds;
};

}  // namespace wardray::geometry
