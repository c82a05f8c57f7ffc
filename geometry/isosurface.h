// IsosurfaceShape: POV-Ray's `isosurface`, the surface f = threshold of a user function inside a box or sphere.
#pragma once

#include <atomic>
#include <memory>
#include <optional>

#include "geometry/shape.h"
#include "scene/scene.h"

namespace wardray::geometry {

/// The largest gradient the root finder met along any ray, shared by the copies of one isosurface, for POV-Ray's
/// warning that `max_gradient` is too low (or needlessly high); and, with `evaluate`, the gradient bound carried
/// from ray to ray.
struct IsosurfaceGradient {
    std::atomic<double> found{0.0};
    /// With `evaluate`: the largest bound any ray ended with, where the next ray starts (POV-Ray's max_gradient).
    std::atomic<double> carried{0.0};
    /// Raises the maximum to `g` (relaxed: only the final value matters).
    void observe(double g) { raise(found, g); }
    /// Raises `value` to `g` (relaxed).
    static void raise(std::atomic<double>& value, double g) {
        double seen = value.load(std::memory_order_relaxed);
        while (g > seen && !value.compare_exchange_weak(seen, g, std::memory_order_relaxed)) {}
    }
};

/// POV-Ray 3.7's isosurface solver (R. Suzuki's method 2): along the ray inside the container, an interval is
/// split in halves while the end values could still hide a root under the Lipschitz bound `max_gradient`, down to
/// `accuracy`; up to `max_trace` crossings; a closed surface is capped by the container where f < threshold.
class IsosurfaceShape {
public:
    /// Returns nothing without a function or for a degenerate container.
    static std::optional<IsosurfaceShape> create(const scene::Isosurface& iso);

    /// The crossings POV-Ray finds with t in (t_min, t_max), sorted.
    SurfaceHits intersect_all(const LocalRay& ray, double t_min, double t_max) const;
    /// The container's box.
    std::optional<Bounds> bounds() const;
    /// Inside the container where f < threshold.
    bool inside(const Vec3& p) const;
    /// max(f - threshold, signed distance to the container): zero on the surface, negative inside.
    double implicit(const Vec3& p) const;
    /// The function minus the threshold at an object-space point.
    double field(const Vec3& p) const;

    /// The isosurface as the scene gave it.
    const scene::Isosurface& description() const { return *m_iso; }
    /// The largest gradient met so far.
    double gradient_found() const { return m_gradient->found.load(std::memory_order_relaxed); }
    /// After rendering: POV-Ray's warning that max_gradient is lower than the gradient found (holes) or much
    /// higher (slow), at the function; nothing when it fits or with `evaluate`.
    std::optional<Diagnostic> gradient_warning() const;

private:
    struct Trace;
    explicit IsosurfaceShape(const scene::Isosurface& iso);
    bool container_interval(const LocalRay& ray, double& t1, double& t2, int& side1, int& side2) const;
    /// POV-Ray's All_Intersections for a ray from its origin: intersect_all's work.
    SurfaceHits crossings(const LocalRay& ray, double t_min, double t_max) const;
    Vec3 container_normal(const Vec3& p, int side) const;
    Vec3 function_normal(const Vec3& p) const;
    bool find_root(Trace& tr, double& tmin, double tmax, double& maxg) const;
    bool find_root_in(Trace& tr, double t1, double f1, double t2, double f2, double dt, double t21, double len,
                      double& maxg) const;

    std::shared_ptr<const scene::Isosurface> m_iso;
    std::shared_ptr<IsosurfaceGradient> m_gradient;
    function::EvalContext m_context;
};

}  // namespace wardray::geometry
