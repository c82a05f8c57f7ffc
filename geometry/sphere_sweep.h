// SphereSweepShape: POV-Ray's `sphere_sweep`, a sphere moved along a linear, B- or Catmull-Rom spline, in object
// space.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <vector>

#include "geometry/shape.h"
#include "scene/scene.h"

namespace wardray::geometry {

/// The union of POV-Ray's parts: a sphere at each end of each segment, and each segment's tube, the envelope of
/// the spheres whose centre c(u) and radius r(u) are polynomials in u ∈ [0, 1] (degree 1 or 3), closed by the
/// discs where the envelope touches its end spheres. A line meets a tube where |p - c(u)|² = r(u)² and its u
/// derivative vanish together: eliminating the line parameter leaves a polynomial in u (degree 2 or 10) whose roots
/// in [0, 1] are found numerically, per segment. POV-Ray compat: the crossings of every part along the whole line
/// are sorted and thinned by its enter/leave count (Find_Valid_Points), spline tubes report both crossings of the
/// sphere at each root, and a point is inside where, on some segment, r(u)² - |p - c(u)|² changes sign or
/// vanishes for u ∈ [0, 1] (not where it stays positive: POV-Ray's Inside).
class SphereSweepShape {
public:
    /// Returns nothing for too few spheres or non-finite numbers.
    static std::optional<SphereSweepShape> create(const scene::SphereSweep& sweep);

    /// POV-Ray's MIN_ISECT_DEPTH: the instance passes it as a ray parameter, which tells the parent-space length.
    static constexpr double k_min_isect_depth = 1e-4;
    /// Crossings with t in (t_min, t_max), sorted; those within the sweep's tolerance (a parent-space distance,
    /// found from `t_min_depth`, MIN_ISECT_DEPTH as a ray parameter) of the ray's origin are lost.
    SurfaceHits intersect_all(const LocalRay& ray, double t_min, double t_max, double t_min_depth = 0.0) const;
    /// Object-space bounds: each segment's spheres lie within the hull of its Bézier control spheres.
    std::optional<Bounds> bounds() const { return m_bounds; }
    /// POV-Ray's inside test (see the class comment).
    bool inside(const Vec3& p) const;
    /// Distance-like value: the least |p - c(u)| - r(u) over all segments; zero on the surface, negative inside.
    double implicit(const Vec3& p) const;

    /// One segment: c(u) = Σ c[k] u^k, r(u) = Σ r[k] u^k for k ≤ degree, and what its intersection needs.
    struct Segment {
        std::array<Vec3, 4> c{};
        std::array<double, 4> r{};
        int degree = 1;
        Bounds box;
        Vec3 ref;          ///< the box's centre: the origin of the normalised coordinates
        double scale = 1;  ///< the box's half size: the unit of the normalised coordinates
        std::array<Vec3, 4> cn{};  ///< c in normalised coordinates: (c[0] - ref) / scale, c[k] / scale
        std::array<double, 4> rn{};  ///< r / scale
    };

private:
    SphereSweepShape() = default;

    std::shared_ptr<const std::vector<Segment>> m_segments;
    double m_tolerance = 1e-6;
    bool m_spline = false;
    Bounds m_bounds;
};

}  // namespace wardray::geometry
