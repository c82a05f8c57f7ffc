// SorShape: POV-Ray 3.7's pieces of squared radius (sor.cpp, Compute_Sor) and the cubic in the distance along a
// ray recentred at its point nearest the origin.
#include "geometry/sor.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

#include "core/constants.h"
#include "geometry/polynomial.h"

namespace wardray::geometry {

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();
// POV-Ray compat: its EPSILON, and the DEPTH_TOLERANCE below which a closing disc is left out.
constexpr double kEpsilon = kPovEpsilon;
constexpr double kDiscTolerance = 1e-4;

double cubic(const std::array<double, 4>& c, double y) { return ((c[3] * y + c[2]) * y + c[1]) * y + c[0]; }
double dcubic(const std::array<double, 4>& c, double y) { return (3.0 * c[3] * y + 2.0 * c[2]) * y + c[1]; }

// Solves the 4x4 system m x = b by Gaussian elimination with partial pivoting; false when singular.
bool solve4(double m[4][4], double b[4], double x[4]) {
    for (int col = 0; col < 4; ++col) {
        int pivot = col;
        for (int r = col + 1; r < 4; ++r)
            if (std::fabs(m[r][col]) > std::fabs(m[pivot][col])) pivot = r;
        if (m[pivot][col] == 0.0) return false;
        std::swap(m[col], m[pivot]);
        std::swap(b[col], b[pivot]);
        for (int r = col + 1; r < 4; ++r) {
            const double f = m[r][col] / m[col][col];
            for (int k = col; k < 4; ++k) m[r][k] -= f * m[col][k];
            b[r] -= f * b[col];
        }
    }
    for (int r = 3; r >= 0; --r) {
        double v = b[r];
        for (int k = r + 1; k < 4; ++k) v -= m[r][k] * x[k];
        x[r] = v / m[r][r];
    }
    return true;
}

// POV-Ray compat: Compute_Sor bounds a piece by the radii at its ends and at the extremes of f, as sqrt(f); where
// f dips below zero that is NaN, and when the NaN lands where std::min and std::max keep it, the piece's bounding
// cylinder rejects every ray, so POV-Ray never draws the piece. This repeats its root order and min/max order.
bool pov_bound_is_nan(const std::array<double, 4>& c, double y0, double y1, double x0, double x1) {
    double x[4] = {x0, x1, x0, x1};
    // Roots of 3A y² + 2B y + C as POV-Ray's Solve_Polynomial orders them: the larger first.
    const double q2 = 3.0 * c[3], q1 = 2.0 * c[2], q0 = c[1];
    double r[2];
    int n = 0;
    if (std::fabs(q2) >= 1e-10) {
        const double b = -q1 / q2, cc = q0 / q2;
        const double d = b * b - 4.0 * cc;
        if (d > -1e-10 && d < 1e-10) {
            r[n++] = 0.5 * b;
        } else if (d >= 0.0) {
            r[n++] = 0.5 * (b + std::sqrt(d));
            r[n++] = 0.5 * (b - std::sqrt(d));
        }
    } else if (std::fabs(q1) >= 1e-10) {
        r[n++] = -q0 / q1;
    }
    while (n--)
        if (r[n] >= y0 && r[n] <= y1) x[n] = std::sqrt(cubic(c, r[n]));
    const double lo = std::min(std::min(x[0], x[1]), std::min(x[2], x[3]));
    const double hi = std::max(std::max(x[0], x[1]), std::max(x[2], x[3]));
    return std::isnan(lo) || std::isnan(hi);
}

}  // namespace

std::optional<SorShape> SorShape::create(const scene::Sor& sor) {
    const auto& P = sor.points;
    const int n = static_cast<int>(P.size());
    if (n < 4) return std::nullopt;
    for (const Vec3& p : P)
        if (!is_finite(p)) return std::nullopt;
    SorShape shape;
    shape.m_open = sor.open;
    auto pieces = std::make_shared<std::vector<Piece>>();
    for (int i = 0; i + 3 < n; ++i) {
        if (std::fabs(P[i + 2].y - P[i].y) < kEpsilon || std::fabs(P[i + 3].y - P[i + 1].y) < kEpsilon)
            return std::nullopt;
        // The cubic through the squared radii of points i+1 and i+2, with the slopes of the secants around them.
        double b[4] = {P[i + 1].x * P[i + 1].x, P[i + 2].x * P[i + 2].x,
                       2.0 * P[i + 1].x * (P[i + 2].x - P[i].x) / (P[i + 2].y - P[i].y),
                       2.0 * P[i + 2].x * (P[i + 3].x - P[i + 1].x) / (P[i + 3].y - P[i + 1].y)};
        const double w1 = P[i + 1].y, w2 = P[i + 2].y;
        double m[4][4] = {{w1 * w1 * w1, w1 * w1, w1, 1.0},
                          {w2 * w2 * w2, w2 * w2, w2, 1.0},
                          {3.0 * w1 * w1, 2.0 * w1, 1.0, 0.0},
                          {3.0 * w2 * w2, 2.0 * w2, 1.0, 0.0}};
        double abcd[4];
        if (!solve4(m, b, abcd)) return std::nullopt;
        Piece piece;
        // POV-Ray compat: tiny coefficients are set to zero.
        for (int k = 0; k < 4; ++k) piece.c[3 - k] = std::fabs(abcd[k]) < kEpsilon ? 0.0 : abcd[k];
        piece.y_min = std::fmin(w1, w2);
        piece.y_max = std::fmax(w1, w2);
        double f_max = std::fmax(cubic(piece.c, w1), cubic(piece.c, w2));
        const double d[3] = {piece.c[1], 2.0 * piece.c[2], 3.0 * piece.c[3]};
        double roots[2];
        const int nr = polynomial_roots(d, 2, piece.y_min, piece.y_max, roots);
        for (int k = 0; k < nr; ++k) f_max = std::fmax(f_max, cubic(piece.c, roots[k]));
        piece.r_max = std::sqrt(std::fmax(0.0, f_max));
        piece.hidden = pov_bound_is_nan(piece.c, w1, w2, P[i + 1].x, P[i + 2].x);
        shape.m_r_max = std::fmax(shape.m_r_max, piece.r_max);
        pieces->push_back(piece);
    }
    const Piece& first = pieces->front();
    const Piece& last = pieces->back();
    shape.m_base_r2 = std::fmax(0.0, cubic(first.c, first.y_min));
    shape.m_cap_r2 = std::fmax(0.0, cubic(last.c, last.y_max));
    const double r = shape.m_r_max;
    shape.m_bounds = {{-r, first.y_min, -r}, {r, last.y_max, r}};
    if (!is_finite(shape.m_bounds.lower) || !is_finite(shape.m_bounds.upper)) return std::nullopt;
    shape.m_pieces = std::move(pieces);
    return shape;
}

const SorShape::Piece* SorShape::piece_at(double y) const {
    for (const Piece& p : *m_pieces)
        if (y >= p.y_min && y <= p.y_max) return &p;
    return nullptr;
}

bool SorShape::inside(const Vec3& p) const {
    const double rho2 = p.x * p.x + p.z * p.z;
    if (rho2 > m_r_max * m_r_max) return false;
    // POV-Ray compat: the first piece whose height range holds the point decides.
    const Piece* piece = piece_at(p.y);
    return piece != nullptr && rho2 <= cubic(piece->c, p.y);
}

SurfaceHits SorShape::intersect_all(const LocalRay& ray, double t_min, double t_max) const {
    SurfaceHits hits;
    const auto line = centre_line(ray);
    if (!line) return hits;
    const auto& [u, o, s0, len] = *line;
    double b0, b1;
    if (!slab_interval(m_bounds.lower, m_bounds.upper, o, u, b0, b1)) return hits;
    // Structured bindings copied into the lambda by name: clang 14 cannot capture them by reference.
    auto push = [&, s0 = s0, len = len](double s, const Vec3& normal) {
        const double t = (s0 + s) / len;
        if (t > t_min && t < t_max) hits.push({t, normal, dot(normal, ray.direction) < 0.0});
    };
    if (!m_open && std::fabs(u.y) > kEpsilon) {
        for (const auto& [y, r2, ny] : {std::tuple{m_bounds.lower.y, m_base_r2, -1.0},
                                        std::tuple{m_bounds.upper.y, m_cap_r2, 1.0}}) {
            if (!(r2 > kDiscTolerance)) continue;
            const double s = (y - o.y) / u.y;
            const double px = o.x + s * u.x, pz = o.z + s * u.z;
            if (px * px + pz * pz <= r2) push(s, {0.0, ny, 0.0});
        }
    }
    const double rho2 = o.x * o.x + o.z * o.z;
    const double m = o.x * u.x + o.z * u.z;
    const double rr = u.x * u.x + u.z * u.z;
    for (const Piece& piece : *m_pieces) {
        if (piece.hidden) continue;
        double p0, p1;
        const Vec3 lo{-piece.r_max, piece.y_min, -piece.r_max}, hi{piece.r_max, piece.y_max, piece.r_max};
        if (!slab_interval(lo, hi, o, u, p0, p1)) continue;
        const double pad = 1e-9 * (1.0 + std::fabs(p0) + std::fabs(p1));
        // f(oy + s uy) - (rho² + 2 m s + rr s²), expanded about oy.
        const auto& c = piece.c;
        const double f0 = cubic(c, o.y), f1 = dcubic(c, o.y), f2 = c[2] + 3.0 * c[3] * o.y;
        const double g[4] = {f0 - rho2, f1 * u.y - 2.0 * m, f2 * u.y * u.y - rr, c[3] * u.y * u.y * u.y};
        double roots[3];
        const int nr = polynomial_roots(g, 3, p0 - pad, p1 + pad, roots);
        for (int k = 0; k < nr; ++k) {
            const Vec3 p = o + roots[k] * u;
            if (p.y < piece.y_min || p.y > piece.y_max) continue;
            // The gradient of rho² - f(y), halved: outward.
            push(roots[k], {p.x, -0.5 * dcubic(c, p.y), p.z});
        }
    }
    hits.sort_by_t();
    return hits;
}

double SorShape::implicit(const Vec3& p) const {
    const double rho = std::hypot(p.x, p.z);
    const double y_low = m_bounds.lower.y, y_high = m_bounds.upper.y;
    if (p.y < y_low || p.y > y_high) {
        const double r2 = p.y < y_low ? m_base_r2 : m_cap_r2;
        const double dy = p.y < y_low ? y_low - p.y : p.y - y_high;
        return std::hypot(dy, std::fmax(0.0, rho - std::sqrt(r2)));
    }
    const Piece* piece = piece_at(p.y);
    const double side = std::fabs(rho - std::sqrt(std::fmax(0.0, cubic(piece->c, p.y))));
    if (!inside(p)) return side;
    const double caps = m_open ? inf : std::fmin(p.y - y_low, y_high - p.y);
    return -std::fmin(side, caps);
}

}  // namespace wardray::geometry
