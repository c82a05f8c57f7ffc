// ParametricShape: POV-Ray's `parametric`, the surface (x(u, v), y(u, v), z(u, v)) over a uv rectangle.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "geometry/shape.h"
#include "scene/scene.h"

namespace wardray::geometry {

/// POV-Ray 3.7's parametric solver: the uv rectangle is split in halves (the longer side first), each piece's x,
/// y and z bounded from its corner values and `max_gradient`, and a piece is dropped when the ray's slabs through
/// those bounds miss each other or the container; a piece smaller than `accuracy` (in uv or along the ray) is a
/// hit at its nearest slab. Only the nearest crossing is found, and nothing is inside (POV-Ray's Inside is false).
class ParametricShape {
public:
    /// Returns nothing without three functions, for a degenerate container or non-finite settings.
    static std::optional<ParametricShape> create(const scene::Parametric& par);

    /// POV-Ray's MIN_ISECT_DEPTH along the parent-space direction; its ratio to `t_min_depth` is the length of the
    /// parent-space direction, which POV-Ray's depths (of unit rays) are measured in.
    static constexpr double k_min_isect_depth = 1e-4;
    /// The nearest crossing POV-Ray finds, when its t lies in (t_min, t_max) beyond `t_min_depth`.
    SurfaceHits intersect_all(const LocalRay& ray, double t_min, double t_max, double t_min_depth) const;
    /// The container's box.
    std::optional<Bounds> bounds() const;
    /// POV-Ray compat: a parametric has no inside.
    bool inside(const Vec3&) const { return false; }
    /// +1 everywhere: no inside, no distance.
    double implicit(const Vec3&) const { return 1.0; }
    /// The surface point at (u, v), for tests.
    Vec3 point(double u, double v) const;
    /// The normal POV-Ray computes at (u, v): forward differences with step `accuracy` (not unit length).
    Vec3 normal_at(double u, double v) const;

private:
    /// Lower and upper bounds of one coordinate over a uv piece.
    struct Range {
        double low = 0.0, high = 0.0;
    };
    explicit ParametricShape(const scene::Parametric& par);
    double value(int axis, double u, double v) const;
    Range interval(int axis, double u0, double v0, double u1, double v1) const;
    void precompute(int node, double u0, double v0, double u1, double v1);

    std::shared_ptr<const scene::Parametric> m_par;
    function::EvalContext m_context;
    int m_precomputed_nodes = 0;  ///< nodes 1 .. m_precomputed_nodes - 1 of the split tree hold bounds
    int m_first_leaf = 0;         ///< POV-Ray's PrecompLastDepth
    /// Per axis, per node of the split tree (root 1, children 2n and 2n + 1): the bounds of the precomputed axes.
    std::shared_ptr<std::vector<Range>> m_table[3];
};

}  // namespace wardray::geometry
