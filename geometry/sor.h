// SorShape: POV-Ray's `sor`, a surface of revolution whose squared radius is a cubic in height, in object space.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <vector>

#include "geometry/shape.h"
#include "scene/scene.h"

namespace wardray::geometry {

/// Between consecutive inner points the squared radius is f(y) = A y³ + B y² + C y + D, the cubic through both
/// points with slopes from their neighbours (POV-Ray's Compute_Sor); a ray meets a piece where its squared
/// distance from the axis equals f at its height, a cubic in the distance along the ray. Unless open, discs close
/// the lowest and the highest height. Inside: within the height range, the squared radius not above f.
/// POV-Ray compat: the pieces, their bounding shells and the crossings are computed in POV-Ray's arithmetic
/// (cofactor inverse, closed-form cubic), so that nearly singular pieces (inner points a hair apart in height)
/// come out as POV-Ray draws them.
class SorShape {
public:
    /// Returns nothing for fewer than four points, heights too close or non-finite numbers.
    static std::optional<SorShape> create(const scene::Sor& sor);

    /// Crossings with t in (t_min, t_max), sorted.
    SurfaceHits intersect_all(const LocalRay& ray, double t_min, double t_max) const;
    /// Object-space bounds.
    std::optional<Bounds> bounds() const { return m_bounds; }
    /// POV-Ray compat (IS_CHILD_OBJECT): as a CSG child or clipped, every crossing is reported; on its own the shape
    /// stops at the first bounding shell the ray enters beyond its nearest crossing.
    void keep_all_crossings() { m_first_only = false; }
    /// POV-Ray's inside test (the solid of revolution, open or not).
    bool inside(const Vec3& p) const;
    /// Distance-like value: zero on the surface, negative inside.
    double implicit(const Vec3& p) const;

    /// One piece: f(y) = c[3] y³ + c[2] y² + c[1] y + c[0] for y in [y_min, y_max], inside a shell of squared
    /// radii [r2_inner, r2_outer] (POV-Ray's bounding cylinders; either may be NaN, as POV-Ray's can be).
    struct Piece {
        std::array<double, 4> c{};
        double y_min = 0.0;
        double y_max = 0.0;
        double r2_inner = 0.0;
        double r2_outer = 0.0;
    };

private:
    SorShape() = default;
    const Piece* piece_at(double y) const;

    std::shared_ptr<const std::vector<Piece>> m_pieces;
    bool m_open = false;
    bool m_first_only = true;
    double m_base_r2 = 0.0;  ///< squared radius of the base disc (at the lowest height)
    double m_cap_r2 = 0.0;   ///< squared radius of the cap disc (at the highest height)
    double m_r_max = 0.0;  ///< the bounding cylinder's radius (POV-Ray's Radius2)
    Bounds m_bounds;
};

}  // namespace wardray::geometry
