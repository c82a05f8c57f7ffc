// LatheShape: POV-Ray's `lathe`, a spline profile (radius, height) turned about the y axis, in object space.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <vector>

#include "geometry/shape.h"
#include "scene/scene.h"

namespace wardray::geometry {

/// The profile is a chain of cubic pieces r(w), y(w) with w in [0, 1] (POV-Ray's linear, quadratic, Catmull-Rom
/// cubic or Bézier segments). A ray meets piece k where its squared distance from the axis at height y(w) equals
/// r(w)²: a polynomial in w of degree 2, 4 or 6. Inside follows POV-Ray: within the profile's radius and height
/// range, an odd number of profile crossings at the point's height at radii not below the point's.
class LatheShape {
public:
    /// Returns nothing for too few points or non-finite numbers.
    static std::optional<LatheShape> create(const scene::Lathe& lathe);

    /// Crossings with t in (t_min, t_max), sorted.
    SurfaceHits intersect_all(const LocalRay& ray, double t_min, double t_max) const;
    /// Object-space bounds of the turned profile.
    std::optional<Bounds> bounds() const { return m_bounds; }
    /// POV-Ray's inside test.
    bool inside(const Vec3& p) const;
    /// Distance to the surface in the (radius, height) half-plane, negative inside.
    double implicit(const Vec3& p) const;

    /// One piece: r(w) = Σ r[i] wⁱ, y(w) = Σ y[i] wⁱ, and its extent.
    struct Piece {
        std::array<double, 4> r{};
        std::array<double, 4> y{};
        double r_end = 0.0;  ///< the profile point the piece ends on, exactly (the polynomials at 1 may round)
        double y_end = 0.0;
        double r_max = 0.0;  ///< largest |r|
        double r_min = 0.0;  ///< smallest |r| (0 where r changes sign)
        double y_min = 0.0;
        double y_max = 0.0;
    };

private:
    LatheShape() = default;
    bool inside_profile(double radius, double height) const;

    std::shared_ptr<const std::vector<Piece>> m_pieces;
    int m_degree = 1;  ///< of r and y in w
    double m_r_min = 0.0, m_r_max = 0.0, m_y_min = 0.0, m_y_max = 0.0;
    Bounds m_bounds;
};

}  // namespace wardray::geometry
