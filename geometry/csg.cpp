// CsgShape: children's crossings filtered by inside tests of the other children, and bounds from the rules.
#include "geometry/csg.h"

#include <cmath>
#include <limits>

#include "geometry/csg_bounds.h"
#include "geometry/instance.h"

namespace wardray::geometry {

namespace {

// The constraint a plane or quadric child puts on an intersection's inside, in the CSG's space: a plane facing
// along an axis, a quadric without mixed terms under a transform that only scales and moves along the axes (POV-Ray's
// Compute_Quadric_BBox bounds cones, cylinders, ellipsoids and hyperboloids so). Other children add none (their
// own boxes bound the intersection already).
void add_constraint(const ShapeInstance& child, IntersectionBounds& out) {
    const Transform& xf = child.transform();
    if (const auto* plane = std::get_if<PlaneShape>(&child.shape())) {
        // n·M⁻¹(p) <= d is (M⁻ᵀ n)·p <= d + (M⁻ᵀ n)·M(0).
        // POV-Ray compat (Compute_Plane_Min_Max): only a plane facing along an axis bounds the node, so its box (which
        // photons aim at) is POV-Ray's.
        Vec3 n = xf.normal(plane->normal());
        if (!is_finite(n)) return;
        const double tiny = 1e-10 * max_abs_component(n);
        int axes = 0;
        for (int k = 0; k < 3; ++k) {
            if (std::fabs(n[k]) <= tiny) n[k] = 0.0;
            else ++axes;
        }
        if (axes == 1) out.add(HalfSpace{n, plane->distance() + dot(n, xf.point(Vec3{}))});
        return;
    }
    const auto* quadric = std::get_if<QuadricShape>(&child.shape());
    if (!quadric || child.inverse()) return;
    const scene::Quadric& q = quadric->coefficients();
    if (q.mixed != Vec3{}) return;
    const Transform::Matrix34& m = xf.inverse_matrix();
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            if (r != c && m[r][c] != 0.0) return;
    // Object coordinate k is s_k p_k + t_k: a (s p + t)² + b (s p + t) = a s² p² + (2 a s t + b s) p + a t² + b t.
    AxisQuadric out_q;
    out_q.constant = q.constant;
    for (int k = 0; k < 3; ++k) {
        const double s = m[k][k], t = m[k][3], a = q.squares[k], b = q.linear[k];
        out_q.squares[k] = a * s * s;
        out_q.linear[k] = 2.0 * a * s * t + b * s;
        out_q.constant += a * t * t + b * t;
    }
    out.add(out_q);
}

}  // namespace

std::optional<CsgShape> CsgShape::create(const scene::Csg& csg, bool inverted, ObjectLifetime lifetime) {
    CsgShape shape;
    auto children = std::make_shared<std::vector<ShapeInstance>>();
    children->reserve(csg.children.size());
    for (std::size_t i = 0; i < csg.children.size(); ++i) {
        // POV-Ray compat: a difference is the first child intersected with every other child inverted.
        const bool flip = (csg.op == scene::Csg::Op::Difference && i > 0) != inverted;
        auto inst = ShapeInstance::create(csg.children[i], 0, flip, lifetime);
        if (!inst) return std::nullopt;
        inst->keep_all_crossings();
        children->push_back(std::move(*inst));
    }
    switch (csg.op) {
        case scene::Csg::Op::Union: shape.m_rule = inverted ? Rule::Inside : Rule::All; break;
        case scene::Csg::Op::Merge: shape.m_rule = inverted ? Rule::Inside : Rule::Outside; break;
        case scene::Csg::Op::Intersection:
        case scene::Csg::Op::Difference: shape.m_rule = inverted ? Rule::Outside : Rule::Inside; break;
    }
    shape.m_inside_all = shape.m_rule == Rule::Inside;
    const auto& kids = *children;
    if (kids.empty()) {
        // An empty CSG has no surface: a point-sized box far from nothing keeps the BVH happy.
        shape.m_bounds = Bounds{};
        shape.m_region = Bounds{};
    } else if (!shape.m_inside_all) {
        shape.m_bounds = kids.front().world_bounds();
        shape.m_region = kids.front().region_bounds();
        for (const ShapeInstance& k : kids) {
            shape.m_bounds = merge_bounds(shape.m_bounds, k.world_bounds());
            shape.m_region = merge_bounds(shape.m_region, k.region_bounds());
        }
    } else {
        // Kept crossings of child i lie on child i's surface and inside every other child's region: the regions
        // before i and after i, as running intersections from each end (linear in the children; boxes meet by
        // componentwise min and max, so the grouping changes no bound).
        const std::size_t n = kids.size();
        std::vector<std::optional<Bounds>> after(n + 1);
        for (std::size_t i = n; i-- > 0;) after[i] = intersect_bounds(kids[i].region_bounds(), after[i + 1]);
        shape.m_region = after[0];
        bool first = true;
        std::optional<Bounds> surface;
        std::optional<Bounds> before;
        for (std::size_t i = 0; i < n; ++i) {
            std::optional<Bounds> b = intersect_bounds(intersect_bounds(kids[i].world_bounds(), before), after[i + 1]);
            before = intersect_bounds(before, kids[i].region_bounds());
            if (b && b->empty()) continue;
            surface = first ? b : merge_bounds(surface, b);
            first = false;
        }
        shape.m_bounds = first ? std::optional<Bounds>(Bounds{}) : surface;
        // Planes and quadrics bound nothing alone, but a slab of planes cut from a hyperboloid (chess2.pov's pawns)
        // bounds a finite region: narrow the box by them, so the node is not tested by every ray.
        IntersectionBounds narrowing;
        for (const ShapeInstance& k : kids) add_constraint(k, narrowing);
        if (!narrowing.empty() && !first) {
            if (const std::optional<Bounds> region = narrowing.narrow(shape.m_region)) {
                shape.m_region = intersect_bounds(shape.m_region, region);
                shape.m_bounds = intersect_bounds(shape.m_bounds, region);
            }
        }
    }
    shape.m_children = std::move(children);
    return shape;
}

bool CsgShape::keeps(std::size_t child, const Vec3& p, std::size_t& rejecter) const {
    const auto& kids = *m_children;
    const std::size_t n = kids.size();
    // The scan starts at the child that rejected the last crossing and wraps around: the verdict is the same in any
    // order (a crossing is kept only when no other child rejects it), and neighbouring crossings are mostly rejected
    // by the same child or the next one, so a large node in an unlucky order (many nested spheres, the smallest
    // last) costs a few tests per crossing, not one per child.
    const std::size_t start = rejecter < n ? rejecter : 0;
    for (std::size_t k = 0; k < n; ++k) {
        const std::size_t j = start + k < n ? start + k : start + k - n;
        if (j == child) continue;
        if (kids[j].inside(p) != (m_rule == Rule::Inside)) {
            rejecter = j;
            return false;
        }
    }
    return true;
}

SurfaceHits CsgShape::intersect_all(const LocalRay& ray, double t_min, double t_max) const {
    SurfaceHits hits;
    const auto& kids = *m_children;
    std::size_t rejecter = kids.size();  // none yet
    for (std::size_t i = 0; i < kids.size(); ++i) {
        // Normals are mapped only for the crossings kept: most crossings of an intersection's children are not.
        for (const SurfaceHit& h : kids[i].object_crossings(ray.origin, ray.direction, t_min, t_max)) {
            if (m_rule != Rule::All && !keeps(i, ray.origin + h.t * ray.direction, rejecter)) continue;
            if (const auto hit = kids[i].to_parent(h)) hits.push(*hit);
        }
    }
    hits.sort_by_t();
    return hits;
}

bool CsgShape::inside(const Vec3& p) const {
    for (const ShapeInstance& k : *m_children) {
        const bool in = k.inside(p);
        if (m_inside_all && !in) return false;
        if (!m_inside_all && in) return true;
    }
    return m_inside_all && !m_children->empty();
}

double CsgShape::implicit(const Vec3& p) const {
    double best = std::numeric_limits<double>::infinity();
    for (const ShapeInstance& k : *m_children) best = std::fmin(best, std::fabs(k.object_implicit(p)));
    return best;
}

}  // namespace wardray::geometry
