// SplinePrismShape: walls as roots of a cubic in the piece parameter, caps by the even-odd inside test with
// half-open crossing rules on pieces split where v turns.
#include "geometry/spline_prism.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>
#include <utility>

#include "geometry/polynomial.h"

namespace wardray::geometry {

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();
// Piece parameters this far outside [0, 1] still count, so that no crack opens where two pieces meet.
constexpr double kSlack = 1e-9;

// Parameters in (0, 1) where v(w) turns, sorted, with 0 and 1 around them; returns the count.
int monotone_cuts(const PrismPiece& p, double cuts[4]) {
    const double d[3] = {p.cv[1], 2.0 * p.cv[2], 3.0 * p.cv[3]};
    double roots[2];
    const int n = polynomial_roots(d, 2, 0.0, 1.0, roots);
    int k = 0;
    cuts[k++] = 0.0;
    for (int i = 0; i < n; ++i)
        if (roots[i] > 0.0 && roots[i] < 1.0) cuts[k++] = roots[i];
    cuts[k++] = 1.0;
    return k;
}

}  // namespace

std::optional<SplinePrismShape> SplinePrismShape::create(const scene::Prism& prism) {
    if (prism.spline == scene::Prism::Spline::Linear || prism.conic) return std::nullopt;
    for (const Vec3& p : prism.points)
        if (!is_finite(p)) return std::nullopt;
    if (!std::isfinite(prism.height1) || !std::isfinite(prism.height2) || prism.height1 == prism.height2)
        return std::nullopt;
    auto pieces = std::make_shared<std::vector<PrismPiece>>(prism_spline_pieces(prism));
    if (pieces->empty()) return std::nullopt;
    SplinePrismShape shape;
    shape.m_h1 = std::fmin(prism.height1, prism.height2);
    shape.m_h2 = std::fmax(prism.height1, prism.height2);
    shape.m_open = prism.open;
    // Bounds: each piece's ends and the places where u or v turns.
    auto boxes = std::make_shared<std::vector<Box>>();
    for (const PrismPiece& p : *pieces) {
        double at[6] = {0.0, 1.0};
        int n = 2;
        for (const double* c : {p.cu, p.cv}) {
            const double d[3] = {c[1], 2.0 * c[2], 3.0 * c[3]};
            n += polynomial_roots(d, 2, 0.0, 1.0, at + n);
        }
        Box b{inf, -inf, inf, -inf};
        for (int k = 0; k < n; ++k) {
            const Vec3 q = p.at(at[k]);
            b = {std::fmin(b.u_lo, q.x), std::fmax(b.u_hi, q.x), std::fmin(b.v_lo, q.y), std::fmax(b.v_hi, q.y)};
        }
        boxes->push_back(b);
    }
    Box all = boxes->front();
    for (const Box& b : *boxes)
        all = {std::fmin(all.u_lo, b.u_lo), std::fmax(all.u_hi, b.u_hi), std::fmin(all.v_lo, b.v_lo),
               std::fmax(all.v_hi, b.v_hi)};
    shape.m_bounds = {{all.u_lo, shape.m_h1, all.v_lo}, {all.u_hi, shape.m_h2, all.v_hi}};
    shape.m_boxes = std::move(boxes);
    if (!is_finite(shape.m_bounds.lower) || !is_finite(shape.m_bounds.upper)) return std::nullopt;
    shape.m_pieces = std::move(pieces);
    return shape;
}

bool SplinePrismShape::inside_outline(double u, double v) const {
    // Even-odd count of crossings on the ray from (u, v) toward +u; each monotone part of a piece counts by the
    // half-open rule "above v", so the ends shared by two parts count once.
    int crossings = 0;
    for (std::size_t i = 0; i < m_pieces->size(); ++i) {
        const Box& box = (*m_boxes)[i];
        if (v < box.v_lo || v > box.v_hi || u >= box.u_hi) continue;
        const PrismPiece& p = (*m_pieces)[i];
        double cuts[4];
        const int n = monotone_cuts(p, cuts);
        for (int k = 0; k + 1 < n; ++k) {
            const double va = p.at(cuts[k]).y, vb = p.at(cuts[k + 1]).y;
            if ((va > v) == (vb > v)) continue;
            double c[4] = {p.cv[0] - v, p.cv[1], p.cv[2], p.cv[3]};
            double w[3];
            const int nw = polynomial_roots(c, 3, cuts[k], cuts[k + 1], w);
            const double wk = nw > 0 ? w[0] : (std::fabs(va - v) < std::fabs(vb - v) ? cuts[k] : cuts[k + 1]);
            crossings += p.at(wk).x > u;
        }
    }
    return (crossings & 1) != 0;
}

bool SplinePrismShape::inside(const Vec3& p) const {
    // POV-Ray compat: both caps belong to the inside.
    return p.y >= m_h1 && p.y <= m_h2 && inside_outline(p.x, p.z);
}

SurfaceHits SplinePrismShape::intersect_all(const LocalRay& ray, double t_min, double t_max) const {
    SurfaceHits hits;
    const Vec3& P = ray.origin;
    const Vec3& D = ray.direction;
    if (!m_open && D.y != 0.0) {
        for (const auto& [h, ny] : {std::pair{m_h1, -1.0}, std::pair{m_h2, 1.0}}) {
            const double t = (h - P.y) / D.y;
            if (t > t_min && t < t_max && inside_outline(P.x + t * D.x, P.z + t * D.z))
                hits.push({t, {0.0, ny, 0.0}, ny * D.y < 0.0});
        }
    }
    if (D.x != 0.0 || D.z != 0.0) {
        const double scale = std::fmax(max_abs_component(m_bounds.lower), max_abs_component(m_bounds.upper));
        // The part of the ray between the heights (all of it for a level ray between them).
        double y0 = t_min, y1 = t_max;
        if (D.y != 0.0) {
            double a = (m_h1 - P.y) / D.y, b = (m_h2 - P.y) / D.y;
            if (a > b) std::swap(a, b);
            y0 = std::fmax(y0, a);
            y1 = std::fmin(y1, b);
        } else if (P.y < m_h1 || P.y > m_h2) {
            y1 = -inf;
        }
        const double pad = 1e-9 * (1.0 + scale);
        for (std::size_t i = 0; i < m_pieces->size() && y0 <= y1; ++i) {
            // The piece's box in u and v must meet that part of the ray.
            const Box& box = (*m_boxes)[i];
            double s0 = y0, s1 = y1;
            for (const auto& [o, d, lo, hi] : {std::tuple{P.x, D.x, box.u_lo, box.u_hi}, std::tuple{P.z, D.z, box.v_lo, box.v_hi}}) {
                if (d == 0.0) {
                    if (o < lo - pad || o > hi + pad) s1 = -inf;
                    continue;
                }
                double a = (lo - pad - o) / d, b = (hi + pad - o) / d;
                if (a > b) std::swap(a, b);
                s0 = std::fmax(s0, a);
                s1 = std::fmin(s1, b);
            }
            if (!(s0 <= s1)) continue;
            const PrismPiece& p = (*m_pieces)[i];
            // cross((u(w), v(w)) - (Px, Pz), (Dx, Dz)) = 0.
            double c[4];
            for (int i = 0; i < 4; ++i) c[i] = p.cu[i] * D.z - p.cv[i] * D.x;
            c[0] -= P.x * D.z - P.z * D.x;
            double w[3];
            const int n = polynomial_roots(c, 3, -kSlack, 1.0 + kSlack, w);
            for (int i = 0; i < n; ++i) {
                const double wk = std::clamp(w[i], 0.0, 1.0);
                const Vec3 q = p.at(wk);
                const double t = std::fabs(D.x) >= std::fabs(D.z) ? (q.x - P.x) / D.x : (q.y - P.z) / D.z;
                if (!(t > t_min && t < t_max)) continue;
                const double y = P.y + t * D.y;
                if (y < m_h1 || y > m_h2) continue;
                Vec3 tan = p.tangent(wk);
                if (tan.x == 0.0 && tan.y == 0.0) tan = p.at(1.0) - p.at(0.0);
                const double len = std::hypot(tan.x, tan.y);
                if (!(len > 0.0)) continue;
                // The wall's normal turned away from the outline's inside.
                Vec3 normal{tan.y, 0.0, -tan.x};
                const double step = 1e-7 * scale;
                if (inside_outline(q.x + step * tan.y / len, q.y - step * tan.x / len)) normal = -normal;
                hits.push({t, normal, dot(normal, D) < 0.0});
            }
        }
    }
    hits.sort_by_t();
    return without_repeated_crossings(hits);
}

double SplinePrismShape::outline_distance(double u, double v) const {
    double best = inf;
    for (const PrismPiece& p : *m_pieces) {
        auto dist2 = [&](double w) {
            const Vec3 q = p.at(w);
            return (q.x - u) * (q.x - u) + (q.y - v) * (q.y - v);
        };
        best = std::fmin(best, minimum_on_unit_interval(dist2));
    }
    return std::sqrt(best);
}

double SplinePrismShape::implicit(const Vec3& p) const {
    const double d_uv = outline_distance(p.x, p.z);
    const bool in_uv = inside_outline(p.x, p.z);
    const bool in_y = p.y >= m_h1 && p.y <= m_h2;
    const double dy_in = std::fmin(p.y - m_h1, m_h2 - p.y);
    if (in_uv && in_y) return -(m_open ? d_uv : std::fmin(d_uv, dy_in));
    const double dy = std::fmax(0.0, std::fmax(m_h1 - p.y, p.y - m_h2));
    if (in_y) return d_uv;
    if (in_uv) return m_open ? std::hypot(d_uv, dy) : dy;
    return std::hypot(d_uv, dy);
}

}  // namespace wardray::geometry
