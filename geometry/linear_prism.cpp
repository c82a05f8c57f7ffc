// LinearPrismShape: POV-Ray 3.7's linear-spline, linear-sweep prism (Compute_Prism, All_Intersections, in_curve).
#include "geometry/linear_prism.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/constants.h"

namespace wardray::geometry {

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();
// POV-Ray compat: Solve_Polynomial's SMALL_ENOUGH, below which in_curve's linear coefficient counts as zero.
constexpr double kSmallEnough = 1e-10;

bool same_point(const Vec3& a, const Vec3& b) {
    return std::fabs(a.x - b.x) < kPovEpsilon && std::fabs(a.y - b.y) < kPovEpsilon;
}

// Squared distance from (u, v) to the segment.
double segment_distance2(const LinearPrismShape::Segment& s, double u, double v) {
    const double len2 = s.cu * s.cu + s.cv * s.cv;
    double w = len2 > 0.0 ? ((u - s.du) * s.cu + (v - s.dv) * s.cv) / len2 : 0.0;
    w = std::clamp(w, 0.0, 1.0);
    const double eu = s.du + w * s.cu - u, ev = s.dv + w * s.cv - v;
    return eu * eu + ev * ev;
}

}  // namespace

std::optional<LinearPrismShape> LinearPrismShape::create(const scene::Prism& prism) {
    if (prism.spline != scene::Prism::Spline::Linear || prism.conic) return std::nullopt;
    if (prism.points.size() < 3) return std::nullopt;
    for (const Vec3& p : prism.points)
        if (!is_finite(p)) return std::nullopt;
    if (!std::isfinite(prism.height1) || !std::isfinite(prism.height2) || prism.height1 == prism.height2)
        return std::nullopt;
    std::vector<Vec3> P = prism.points;
    // POV-Ray compat (Parse_Prism): the outline is closed when a point repeats its sub-polygon's first point and
    // the last sub-polygon ends that way; otherwise the last sub-polygon's first point is appended.
    {
        bool closed = false;
        Vec3 first = P[0];
        for (std::size_t i = 1; i < P.size(); ++i) {
            closed = false;
            if (same_point(first, P[i])) {
                ++i;
                if (i < P.size()) first = P[i];
                closed = true;
            }
        }
        if (!closed) P.push_back(first);
    }
    // POV-Ray compat (Compute_Prism): a segment from each point to the next, none from a sub-polygon's last point.
    auto segments = std::make_shared<std::vector<Segment>>();
    LinearPrismShape shape;
    shape.m_u_lo = shape.m_v_lo = inf;
    shape.m_u_hi = shape.m_v_hi = -inf;
    Vec3 first = P[0];
    for (std::size_t i = 0; i + 1 < P.size(); ++i) {
        const Vec3& a = P[i];
        const Vec3& b = P[i + 1];
        Segment s;
        s.cu = -1.0 * a.x + 1.0 * b.x;
        s.cv = -1.0 * a.y + 1.0 * b.y;
        s.du = 1.0 * a.x;
        s.dv = 1.0 * a.y;
        s.u_lo = std::min(a.x, b.x);
        s.u_hi = std::max(a.x, b.x);
        s.v_lo = std::min(a.y, b.y);
        s.v_hi = std::max(a.y, b.y);
        s.side = 1.0;
        segments->push_back(s);
        shape.m_u_lo = std::min(shape.m_u_lo, s.u_lo);
        shape.m_u_hi = std::max(shape.m_u_hi, s.u_hi);
        shape.m_v_lo = std::min(shape.m_v_lo, s.v_lo);
        shape.m_v_hi = std::max(shape.m_v_hi, s.v_hi);
        if (same_point(b, first)) {
            ++i;
            if (i + 1 < P.size()) first = P[i + 1];
        }
    }
    shape.m_segments = segments;
    shape.m_h1 = std::fmin(prism.height1, prism.height2);
    shape.m_h2 = std::fmax(prism.height1, prism.height2);
    shape.m_open = prism.open;
    shape.m_bounds = {{shape.m_u_lo, shape.m_h1, shape.m_v_lo}, {shape.m_u_hi, shape.m_h2, shape.m_v_hi}};
    if (!is_finite(shape.m_bounds.lower) || !is_finite(shape.m_bounds.upper)) return std::nullopt;
    // Which side of each segment is outside: the even-odd test a hair beside it, at three places voting (one may
    // lie level with a vertex of the outline, where the test counts that vertex twice).
    const double scale = shape.m_bounds.magnitude();
    for (Segment& s : *segments) {
        const double len = std::hypot(s.cu, s.cv);
        if (!(len > 0.0)) continue;
        const double step = 1e-7 * (scale + len);
        int inside = 0;
        for (const double w : {0.381966, 0.5, 0.618034})
            inside += shape.in_curve(s.du + w * s.cu + step * s.cv / len, s.dv + w * s.cv - step * s.cu / len);
        if (inside >= 2) s.side = -1.0;
    }
    return shape;
}

bool LinearPrismShape::in_curve(double u, double v) const {
    if (!(u >= m_u_lo && u <= m_u_hi && v >= m_v_lo && v <= m_v_hi)) return false;
    int crossings = 0;
    for (const Segment& s : *m_segments) {
        if (!(v >= s.v_lo && v <= s.v_hi && u <= s.u_hi)) continue;
        // POV-Ray compat: the cubic (0, 0, cv, dv - v) reduced to its linear part, none when cv is tiny.
        if (!(std::fabs(s.cv) >= kSmallEnough)) continue;
        const double w = -(s.dv - v) / s.cv;
        if (w >= 0.0 && w <= 1.0 && w * s.cu + s.du - u >= 0.0) ++crossings;
    }
    return (crossings & 1) != 0;
}

bool LinearPrismShape::inside(const Vec3& p) const {
    return p.y >= m_h1 && p.y < m_h2 && in_curve(p.x, p.z);
}

SurfaceHits LinearPrismShape::intersect_all(const LocalRay& ray, double t_min, double t_max) const {
    SurfaceHits hits;
    const Vec3& P = ray.origin;
    // POV-Ray compat: crossings at distances k along the unit direction, t = k / len.
    const double len = std::sqrt(ray.direction.x * ray.direction.x + ray.direction.y * ray.direction.y +
                                 ray.direction.z * ray.direction.z);
    if (!(len > 0.0) || !std::isfinite(len)) return hits;
    const double inv_len = 1.0 / len;
    const Vec3 D{ray.direction.x * inv_len, ray.direction.y * inv_len, ray.direction.z * inv_len};
    // A query reaching behind its origin (t_min < 0) wants the whole line: none of the one-way culls then.
    const bool forward = t_min >= 0.0;
    auto misses_box = [&](double u_lo, double u_hi, double v_lo, double v_hi) {
        return forward && ((D.x >= 0.0 && P.x > u_hi) || (D.x <= 0.0 && P.x < u_lo) || (D.z >= 0.0 && P.z > v_hi) ||
                           (D.z <= 0.0 && P.z < v_lo));
    };
    if (misses_box(m_u_lo, m_u_hi, m_v_lo, m_v_hi)) return hits;
    auto push = [&](double k, const Vec3& normal) {
        const double t = k / len;
        if (t > t_min && t < t_max) hits.push({t, normal, dot(normal, D) < 0.0});
    };
    if (std::fabs(D.y) < kPovEpsilon) {
        // Level with the caps: the walls only, and none outside the heights (both included).
        if (P.y < m_h1 || P.y > m_h2) return hits;
    } else if (!m_open) {
        for (const auto& [h, ny] : {std::pair{m_h2, 1.0}, std::pair{m_h1, -1.0}}) {
            const double k = (h - P.y) / D.y;
            if (in_curve(P.x + k * D.x, P.z + k * D.z)) push(k, {0.0, ny, 0.0});
        }
    }
    if (std::fabs(D.x) > kPovEpsilon || std::fabs(D.z) > kPovEpsilon) {
        for (const Segment& s : *m_segments) {
            if (misses_box(s.u_lo, s.u_hi, s.v_lo, s.v_hi)) continue;
            // Where the ray's x-z projection crosses the segment's line: x0 w + x1 = 0.
            const double x0 = s.cu * D.z - s.cv * D.x;
            const double x1 = D.z * (s.du - P.x) - D.x * (s.dv - P.z);
            if (!(std::fabs(x0) > kPovEpsilon)) continue;
            const double w = -x1 / x0;
            if (!(w >= 0.0 && w <= 1.0)) continue;
            const double k =
                std::fabs(D.x) > kPovEpsilon ? (w * s.cu + s.du - P.x) / D.x : (w * s.cv + s.dv - P.z) / D.z;
            // The crossing's height, both ends included.
            const double h = P.y + k * D.y;
            if (h >= m_h1 && h <= m_h2) push(k, {s.side * s.cv, 0.0, -s.side * s.cu});
        }
    }
    hits.sort_by_t();
    return without_repeated_crossings(hits);
}

double LinearPrismShape::implicit(const Vec3& p) const {
    double d2 = inf;
    for (const Segment& s : *m_segments) d2 = std::fmin(d2, segment_distance2(s, p.x, p.z));
    const double d_uv = std::sqrt(d2);
    const bool in_uv = in_curve(p.x, p.z);
    const bool in_y = p.y >= m_h1 && p.y <= m_h2;
    if (in_uv && in_y) return -(m_open ? d_uv : std::fmin(d_uv, std::fmin(p.y - m_h1, m_h2 - p.y)));
    const double dy = std::fmax(0.0, std::fmax(m_h1 - p.y, p.y - m_h2));
    if (in_y) return d_uv;
    if (in_uv) return m_open ? std::hypot(d_uv, dy) : dy;
    return std::hypot(d_uv, dy);
}

}  // namespace wardray::geometry
