// BoxShape: slab intersection that stays NaN-free for directions parallel to a face.
#include "geometry/box.h"

#include <cmath>
#include <utility>
#include <limits>

namespace wardray::geometry {

std::optional<BoxShape> BoxShape::create(const scene::Box& box) {
    if (!is_finite(box.corner1) || !is_finite(box.corner2)) return std::nullopt;
    // POV-Ray compat: the two corners may be any opposite pair; the box spans their component-wise min and max.
    return BoxShape(min(box.corner1, box.corner2), max(box.corner1, box.corner2));
}

SurfaceHits BoxShape::intersect_all(const LocalRay& ray, double t_min, double t_max) const {
    constexpr double inf = std::numeric_limits<double>::infinity();
    SurfaceHits hits;
    double t_enter = -inf;
    double t_exit = inf;
    int axis_enter = -1;
    int axis_exit = -1;
    for (int k = 0; k < 3; ++k) {
        const double o = ray.origin[k];
        const double d = ray.direction[k];
        if (d == 0.0) {
            // Parallel to this slab: either always between its planes or never (no 0 * inf products).
            if (o < m_lower[k] || o > m_upper[k]) return hits;
            continue;
        }
        double t0 = (m_lower[k] - o) / d;
        double t1 = (m_upper[k] - o) / d;
        if (t0 > t1) std::swap(t0, t1);
        if (t0 > t_enter) {
            t_enter = t0;
            axis_enter = k;
        }
        if (t1 < t_exit) {
            t_exit = t1;
            axis_exit = k;
        }
    }
    if (t_enter > t_exit || axis_enter < 0 || axis_exit < 0) return hits;
    // The outward normal of a face is ±axis, opposite to the ray on entry and along it on exit.
    if (t_enter > t_min && t_enter < t_max) {
        Vec3 n;
        n[axis_enter] = ray.direction[axis_enter] > 0.0 ? -1.0 : 1.0;
        hits.push({t_enter, n, true});
    }
    if (t_exit > t_min && t_exit < t_max) {
        Vec3 n;
        n[axis_exit] = ray.direction[axis_exit] > 0.0 ? 1.0 : -1.0;
        hits.push({t_exit, n, false});
    }
    return hits;
}

bool BoxShape::inside(const Vec3& p) const {
    // POV-Ray compat: a point on a face is inside (Box::Inside compares with < and >), so where two cut-away boxes
    // of a difference share a face, neither keeps it.
    for (int k = 0; k < 3; ++k)
        if (!(p[k] >= m_lower[k] && p[k] <= m_upper[k])) return false;
    return true;
}

double BoxShape::implicit(const Vec3& p) const {
    const Vec3 centre = 0.5 * (m_lower + m_upper);
    const Vec3 half = 0.5 * (m_upper - m_lower);
    Vec3 q;
    for (int k = 0; k < 3; ++k) q[k] = std::fabs(p[k] - centre[k]) - half[k];
    const Vec3 outside = max(q, Vec3{});
    return length(outside) + std::fmin(std::fmax(q.x, std::fmax(q.y, q.z)), 0.0);
}

}  // namespace wardray::geometry
