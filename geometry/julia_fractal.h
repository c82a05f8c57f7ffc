// JuliaFractalShape: POV-Ray's `julia_fractal`, a 3-D slice of a quaternion or hypercomplex Julia set.
#pragma once

#include <array>
#include <optional>

#include "geometry/shape.h"
#include "scene/scene.h"

namespace wardray::geometry {

/// One point of the 4-D algebra (x + y i + z j + w k for quaternions).
struct Quad {
    double x = 0.0, y = 0.0, z = 0.0, w = 0.0;
};

/// The set of points whose orbit under z -> f(z) + c stays within POV-Ray's escape radius for `max_iteration`
/// steps, traced as POV-Ray 3.7 does: fixed steps of 1 / precision from the bounding sphere, each change of
/// state polished by bisection down to 1e-7, the normal from the derivative of the orbit.
class JuliaFractalShape {
public:
    /// Returns nothing for non-finite parameters.
    static std::optional<JuliaFractalShape> create(const scene::JuliaFractal& fractal);

    /// The changes of state POV-Ray finds along the ray with t in (t_min, t_max), in order. POV-Ray compat: on its
    /// own the fractal stops at its first crossing, which is then the only one, or none when it lies before t_min.
    /// Every crossing counts (a CSG child or a clipped object).
    void keep_all_crossings() { m_first_only = false; }
    /// POV-Ray's MIN_ISECT_DEPTH: crossings nearer the ray's origin (along the parent-space direction) are lost.
    static constexpr double k_min_isect_depth = 1e-4;
    /// Crossings before `t_min_depth` (POV-Ray's MIN_ISECT_DEPTH as a ray parameter) are lost.
    SurfaceHits intersect_all(const LocalRay& ray, double t_min, double t_max, double t_min_depth = 0.0) const;
    /// The cube around the bounding sphere.
    std::optional<Bounds> bounds() const { return Bounds{{-m_radius, -m_radius, -m_radius}, {m_radius, m_radius, m_radius}}; }
    /// True where the orbit does not escape (POV-Ray's Inside).
    bool inside(const Vec3& p) const;
    /// -1 inside, +1 outside (the set has no distance function).
    double implicit(const Vec3& p) const { return inside(p) ? -1.0 : 1.0; }
    /// The outward normal POV-Ray computes at an object-space point of the set (not unit length).
    Vec3 normal_at(const Vec3& p) const;

private:
    explicit JuliaFractalShape(const scene::JuliaFractal& fractal);
    /// The orbit of p into `orbit` (max_iteration + 1 entries); false when it escapes. With `step`, POV-Ray's
    /// D_Iteration (the marching test): the orbit from p itself, and in *step the distance to march on along `u`
    /// (its distance estimate, at least the precision's step once the caller clamps it). Without, POV-Ray's
    /// Iteration (inside tests and bisection).
    bool iterate(const Vec3& p, Quad* orbit, double* step = nullptr, const Vec3& u = {}) const;
    Quad apply(const Quad& q) const;
    /// POV-Ray's Normal_Calc over the first `n` steps of the orbit.
    Vec3 orbit_normal(const Quad* orbit, int n) const;
    /// POV-Ray's distance estimate when orbit[i - 1] escaped.
    double escape_step(const Quad* orbit, int i, const Vec3& u) const;

    scene::JuliaFractal m_f;
    double m_radius = 2.0;      ///< of the bounding sphere
    double m_exit = 4.0;        ///< the escape value of |z|²
    bool m_first_only = true;
};

}  // namespace wardray::geometry
