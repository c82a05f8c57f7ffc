// ParametricShape: POV-Ray 3.7's subdivision of the uv rectangle under interval bounds, with its precompute table.
#include "geometry/parametric.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <utility>

namespace wardray::geometry {

namespace {

constexpr double k_epsilon = 1e-10;         // POV-Ray's EPSILON
constexpr double k_bound_huge = 2.0e10;     // POV-Ray's BOUND_HUGE
constexpr double k_depth_tolerance = 1e-6;  // POV-Ray's DEPTH_TOLERANCE in boxes.cpp
constexpr std::int64_t k_max_sector = 10000000;  // POV-Ray's Max_intNumber: split numbers saturate here
// POV-Ray keeps 32 pieces on its stack (and overruns it below an accuracy of about 2^-31 of the rectangle); a
// deeper piece is taken as small enough here.
constexpr int k_stack = 64;

// POV-Ray's Box::Intersect on the object-space ray from depth 0: false when it misses or lies behind.
bool box_depths(const Vec3& lo, const Vec3& hi, const Vec3& p, const Vec3& d, double& t1, double& t2) {
    double tmin = 0.0, tmax = k_bound_huge;
    for (int k = 0; k < 3; ++k) {
        if (d[k] < -k_epsilon || d[k] > k_epsilon) {
            double a = (lo[k] - p[k]) / d[k], b = (hi[k] - p[k]) / d[k];
            if (a > b) std::swap(a, b);
            if (b < tmin || a > tmax) return false;
            tmin = std::fmax(tmin, a);
            tmax = std::fmin(tmax, b);
        } else if (p[k] < lo[k] || p[k] > hi[k]) {
            return false;
        }
    }
    if (tmax < k_depth_tolerance) return false;
    t1 = tmin;
    t2 = tmax;
    return true;
}

// POV-Ray's Sphere::Intersect on the normalised object-space ray, depths scaled back to the ray's own.
bool sphere_depths(const Vec3& c, double r, const Vec3& p, const Vec3& d, double& t1, double& t2) {
    const double len = length(d);
    if (!(len > 0.0)) return false;
    const Vec3 u = d / len;
    const Vec3 oc = c - p;
    const double oc2 = dot(oc, oc);
    const double closest = dot(oc, u);
    if (oc2 >= r * r && closest < k_epsilon) return false;
    const double half2 = r * r - oc2 + closest * closest;
    if (!(half2 > k_epsilon)) return false;
    const double half = std::sqrt(half2);
    t1 = (closest - half) / len;
    t2 = (closest + half) / len;
    return true;
}

// POV-Ray's Interval: the bounds of a function over a segment of length dx whose ends take a and b, when its
// slope is at most g: the ends widened by half of what the slope allows beyond their difference.
void widen(double dx, double a, double b, double g, double& lo, double& hi) {
    const double dy = std::fabs(a - b);
    const double ofs = std::fmax(0.0, g * (dx - dy / g) / 2.0);
    hi = std::fmax(a, b) + ofs;
    lo = std::fmin(a, b) - ofs;
}

}  // namespace

ParametricShape::ParametricShape(const scene::Parametric& par)
    : m_par(std::make_shared<const scene::Parametric>(par)) {
    m_context.noise_generator = par.noise_generator;
}

std::optional<ParametricShape> ParametricShape::create(const scene::Parametric& par) {
    for (const auto& f : par.functions)
        if (!f) return std::nullopt;
    if (par.sphere_container) {
        if (!(par.radius > 0.0) || !std::isfinite(par.radius) || !is_finite(par.center)) return std::nullopt;
    } else if (!is_finite(par.corner1) || !is_finite(par.corner2)) {
        return std::nullopt;
    }
    for (double v : {par.u_min, par.u_max, par.v_min, par.v_max, par.accuracy, par.max_gradient})
        if (!std::isfinite(v)) return std::nullopt;
    if (!(par.max_gradient != 0.0)) return std::nullopt;
    ParametricShape shape(par);
    if (par.precompute_axes != 0 && par.precompute_depth >= 1 && par.precompute_depth <= 20) {
        // POV-Ray's Precompute_Parametric_Values: the split tree down to `depth` levels, leaves evaluated, inner
        // nodes the hull of their children.
        shape.m_precomputed_nodes = 1 << par.precompute_depth;
        shape.m_first_leaf = 1 << (par.precompute_depth - 1);
        for (int k = 0; k < 3; ++k)
            if (par.precompute_axes & (1 << k))
                shape.m_table[k] = std::make_shared<std::vector<Range>>(shape.m_precomputed_nodes);
        shape.precompute(1, par.u_min, par.v_min, par.u_max, par.v_max);
    }
    return shape;
}

double ParametricShape::value(int axis, double u, double v) const {
    const std::array<double, 3> args{u, v, 0.0};
    return m_par->functions[static_cast<std::size_t>(axis)]->evaluate(args, m_context);
}

ParametricShape::Range ParametricShape::interval(int axis, double u0, double v0, double u1, double v1) const {
    // POV-Ray compat (Evaluate_Function_Interval_UV): the corner values less `accuracy`, which moves the surface
    // POV-Ray draws by -accuracy along each axis.
    const double a = m_par->accuracy, g = m_par->max_gradient;
    const double f00 = value(axis, u0, v0) - a, f01 = value(axis, u0, v1) - a;
    const double f10 = value(axis, u1, v0) - a, f11 = value(axis, u1, v1) - a;
    // Bounds along the two edges of constant u, then across them as if both extremes sat at the same v.
    double lo0, hi0, lo1, hi1, junk;
    widen(v1 - v0, f00, f01, g, lo0, hi0);
    widen(v1 - v0, f10, f11, g, lo1, hi1);
    Range r;
    widen(u1 - u0, hi0, hi1, g, junk, r.high);
    widen(u1 - u0, lo0, lo1, g, r.low, junk);
    return r;
}

void ParametricShape::precompute(int node, double u0, double v0, double u1, double v1) {
    if (node >= m_first_leaf) {
        for (int k = 0; k < 3; ++k)
            if (m_table[k]) (*m_table[k])[static_cast<std::size_t>(node)] = interval(k, u0, v0, u1, v1);
        return;
    }
    // The longer side is halved (u on a tie), as the intersection splits.
    if (u1 - u0 < v1 - v0) {
        precompute(2 * node, u0, v0, u1, (v0 + v1) / 2.0);
        precompute(2 * node + 1, u0, (v0 + v1) / 2.0, u1, v1);
    } else {
        precompute(2 * node, u0, v0, (u0 + u1) / 2.0, v1);
        precompute(2 * node + 1, (u0 + u1) / 2.0, v0, u1, v1);
    }
    for (int k = 0; k < 3; ++k) {
        if (!m_table[k]) continue;
        auto& t = *m_table[k];
        const auto n = static_cast<std::size_t>(node);
        t[n].high = std::max(t[2 * n].high, t[2 * n + 1].high);
        t[n].low = std::min(t[2 * n].low, t[2 * n + 1].low);
    }
}

SurfaceHits ParametricShape::intersect_all(const LocalRay& ray, double t_min, double t_max,
                                           double t_min_depth) const {
    SurfaceHits hits;
    const scene::Parametric& par = *m_par;
    // POV-Ray's depths are along unit parent-space rays: D is the object-space image of the unit direction.
    const double scale = (t_min_depth > 0.0 && std::isfinite(t_min_depth)) ? k_min_isect_depth / t_min_depth : 1.0;
    const Vec3 P = ray.origin;
    const Vec3 D = ray.direction / scale;
    double depth1 = 0.0, depth2 = 0.0;
    const bool met = par.sphere_container ? sphere_depths(par.center, par.radius, P, D, depth1, depth2)
                                          : box_depths(par.corner1, par.corner2, P, D, depth1, depth2);
    if (!met) return hits;
    if (depth1 == depth2) depth1 = 0.0;
    depth1 += 4.0 * par.accuracy;
    if (depth1 > depth2) return hits;
    // The caller's interval, beyond MIN_ISECT_DEPTH, narrows the search as a ray restarted there would.
    depth1 = std::fmax(depth1, std::fmax(t_min, t_min_depth) * scale);
    depth2 = std::fmin(depth2, t_max * scale);
    if (!(depth1 <= depth2)) return hits;

    struct Piece {
        double u0, v0, u1, v1;
        std::int64_t sector;  ///< POV-Ray's SectorNum: the piece's node in the split tree
    };
    std::array<Piece, k_stack> stack;
    stack[0] = {par.u_min, par.v_min, par.u_max, par.v_max, 1};
    int top = 0;
    double best = HUGE_VAL, best_u = 0.0, best_v = 0.0;
    const double accuracy = par.accuracy;
    while (top >= 0) {
        const Piece pc = stack[static_cast<std::size_t>(top)];
        double len = pc.u1 - pc.u0;
        bool split_v = false;
        if (pc.v1 - pc.v0 > len) {
            len = pc.v1 - pc.v0;
            split_v = true;
        }
        // Each axis in turn: the slab of depths where the ray is within the piece's bounds on that axis.
        double ray_min[3] = {0.0, 0.0, 0.0}, ray_max[3] = {0.0, 0.0, 0.0};
        bool parallel[3] = {false, false, false};
        double potential = 0.0, ray_len = 0.0;
        bool dropped = false;
        for (int k = 0; k < 3 && !dropped; ++k) {
            Range r;
            if (m_table[k] && pc.sector < m_precomputed_nodes) r = (*m_table[k])[static_cast<std::size_t>(pc.sector)];
            else r = interval(k, pc.u0, pc.v0, pc.u1, pc.v1);
            if (std::fabs(D[k]) < k_epsilon) {
                parallel[k] = true;
                if (r.high < P[k] || r.low > P[k]) dropped = true;
                continue;
            }
            double a = (r.high - P[k]) / D[k], b = (r.low - P[k]) / D[k];
            if (a > b) std::swap(a, b);
            ray_min[k] = a;
            ray_max[k] = b;
            if (a > depth2 || b < depth1) { dropped = true; continue; }
            potential = a;
            if (potential > best) { dropped = true; continue; }
            // The slab must overlap those of the axes before it.
            for (int j = 0; j < k && !dropped; ++j)
                if (!parallel[j] && (a > ray_max[j] || b < ray_min[j])) dropped = true;
            if (dropped) continue;
            ray_len = std::fmax(ray_len, b - a);
        }
        if (dropped) {
            --top;
            continue;
        }
        // POV-Ray compat: a piece is small enough when its longer uv side or its longest slab is below accuracy;
        // the hit is at the last slab's near side and the piece's low corner.
        if (len > ray_len) len = ray_len;
        if (len < accuracy || top + 1 >= k_stack) {
            if (best > potential && potential > depth1) {
                best = potential;
                best_u = pc.u0;
                best_v = pc.v0;
            }
            --top;
            continue;
        }
        // Split in halves: the lower half (node 2n) is searched first, the upper (2n + 1) stays below it.
        std::int64_t sector = std::min(pc.sector * 2, k_max_sector);
        Piece lower = pc, upper = pc;
        if (split_v) lower.v1 = upper.v0 = (pc.v1 + pc.v0) / 2.0;
        else lower.u1 = upper.u0 = (pc.u1 + pc.u0) / 2.0;
        upper.sector = sector + 1;
        lower.sector = sector;
        stack[static_cast<std::size_t>(top)] = upper;
        stack[static_cast<std::size_t>(++top)] = lower;
    }
    if (!(best < depth2)) return hits;
    const double t = best / scale;
    if (!(t > t_min && t < t_max)) return hits;
    const Vec3 n = normal_at(best_u, best_v);
    hits.push({t, n, dot(n, ray.direction) < 0.0});
    return hits;
}

std::optional<Bounds> ParametricShape::bounds() const {
    const scene::Parametric& par = *m_par;
    if (par.sphere_container) {
        const Vec3 r{par.radius, par.radius, par.radius};
        return Bounds{par.center - r, par.center + r};
    }
    return Bounds{par.corner1, par.corner2};
}

Vec3 ParametricShape::point(double u, double v) const { return {value(0, u, v), value(1, u, v), value(2, u, v)}; }

Vec3 ParametricShape::normal_at(double u, double v) const {
    const double a = m_par->accuracy;
    const Vec3 p = point(u, v);
    return cross(point(u + a, v) - p, point(u, v + a) - p);
}

}  // namespace wardray::geometry
