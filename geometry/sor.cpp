// SorShape: POV-Ray 3.7's pieces of squared radius (sor.cpp, Compute_Sor), their bounding shells (bcyl.cpp) and
// the cubic in the distance along a ray, in the arithmetic POV-Ray uses, so that ill-conditioned pieces render alike.
#include "geometry/sor.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>
#include <vector>

#include "core/constants.h"
#include "geometry/polynomial.h"

namespace wardray::geometry {

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();
// POV-Ray compat: its EPSILON, and the DEPTH_TOLERANCE below which a closing disc is left out.
constexpr double kEpsilon = kPovEpsilon;
constexpr double kDiscTolerance = 1e-4;

double cubic(const std::array<double, 4>& c, double y) { return y * (y * (y * c[3] + c[2]) + c[1]) + c[0]; }

// POV-Ray compat: std::min and std::max as POV-Ray's bounds use them, NaN kept or dropped by argument order.
double first_min(double a, double b) { return b < a ? b : a; }
double first_max(double a, double b) { return a < b ? b : a; }

// A piece whose shell the ray meets, and the distance where it enters.
struct Entry {
    double entry;
    int piece;
};

// The 3x3 minor of m without row `row` and column `col`, by the rule of Sarrus: the three products along the
// diagonals, then the three along the anti-diagonals taken from the bottom row up, summed left to right (POV-Ray
// compat: MInvers's order of operations, which decides the rounding of nearly singular systems).
double minor3(const double m[4][4], int row, int col) {
    int r[3], c[3];
    for (int i = 0, nr = 0, nc = 0; i < 4; ++i) {
        if (i != row) r[nr++] = i;
        if (i != col) c[nc++] = i;
    }
    const double* a = m[r[0]];
    const double* b = m[r[1]];
    const double* z = m[r[2]];
    return a[c[0]] * b[c[1]] * z[c[2]] + a[c[1]] * b[c[2]] * z[c[0]] + a[c[2]] * b[c[0]] * z[c[1]] -
           z[c[0]] * b[c[1]] * a[c[2]] - z[c[1]] * b[c[2]] * a[c[0]] - z[c[2]] * b[c[0]] * a[c[1]];
}

// The inverse of m by cofactors, the determinant expanded along the first row; false when it is exactly zero.
bool cofactor_inverse(const double m[4][4], double inv[4][4]) {
    double minors[4][4];
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) minors[i][j] = minor3(m, i, j);
    const double det = m[0][0] * minors[0][0] - m[0][1] * minors[0][1] + m[0][2] * minors[0][2] -
                       m[0][3] * minors[0][3];
    if (det == 0.0) return false;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            const double v = minors[j][i] / det;
            inv[i][j] = (i + j) % 2 == 0 ? v : -v;
        }
    return true;
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
    double r_max = -inf, y_low = inf, y_high = -inf;
    for (int i = 0; i + 3 < n; ++i) {
        if (std::fabs(P[i + 2].y - P[i].y) < kEpsilon || std::fabs(P[i + 3].y - P[i + 1].y) < kEpsilon)
            return std::nullopt;
        // The cubic through the squared radii of points i+1 and i+2, with the slopes of the secants around them.
        double k[4] = {P[i + 1].x * P[i + 1].x, P[i + 2].x * P[i + 2].x,
                       (P[i + 2].x - P[i].x) / (P[i + 2].y - P[i].y),
                       (P[i + 3].x - P[i + 1].x) / (P[i + 3].y - P[i + 1].y)};
        k[2] *= 2.0 * P[i + 1].x;
        k[3] *= 2.0 * P[i + 2].x;
        const double w1 = P[i + 1].y, w2 = P[i + 2].y;
        const double m[4][4] = {{w1 * w1 * w1, w1 * w1, w1, 1.0},
                                {w2 * w2 * w2, w2 * w2, w2, 1.0},
                                {3.0 * w1 * w1, 2.0 * w1, 1.0, 0.0},
                                {3.0 * w2 * w2, 2.0 * w2, 1.0, 0.0}};
        // POV-Ray compat: the system is solved by its inverse, not by elimination; nearly singular pieces (inner
        // points a hair apart) take their shape from this rounding.
        double inv[4][4];
        if (!cofactor_inverse(m, inv)) return std::nullopt;
        Piece piece;
        for (int row = 0; row < 4; ++row) {
            const double v = k[0] * inv[row][0] + k[1] * inv[row][1] + k[2] * inv[row][2] + k[3] * inv[row][3];
            // POV-Ray compat: tiny coefficients are set to zero.
            piece.c[3 - row] = std::fabs(v) < kEpsilon ? 0.0 : v;
        }
        const auto& c = piece.c;
        piece.y_min = w1;
        piece.y_max = w2;
        // POV-Ray compat: the shell's radii are the least and the greatest of the two points' radii and sqrt(f) at the
        // extremes of f within the piece; where f dips below zero that is NaN, kept or dropped as std::min and
        // std::max meet it (a NaN radius fails every comparison, so the ray never enters that shell's wall).
        double x[4] = {P[i + 1].x, P[i + 2].x, P[i + 1].x, P[i + 2].x};
        const double slope[3] = {3.0 * c[3], 2.0 * c[2], c[1]};
        double roots[2];
        for (int nr = solve_polynomial_pov(slope, 2, roots, false, 0.0); nr--;)
            if (roots[nr] >= w1 && roots[nr] <= w2) x[nr] = std::sqrt(cubic(c, roots[nr]));
        const double r_in = first_min(first_min(x[0], x[1]), first_min(x[2], x[3]));
        const double r_out = first_max(first_max(x[0], x[1]), first_max(x[2], x[3]));
        piece.r2_inner = r_in * r_in;
        piece.r2_outer = r_out * r_out;
        r_max = first_max(r_max, r_out);
        y_low = first_min(y_low, w1);
        y_high = first_max(y_high, w2);
        pieces->push_back(piece);
    }
    const Piece& first = pieces->front();
    const Piece& last = pieces->back();
    shape.m_base_r2 = std::fmax(0.0, cubic(first.c, first.y_min));
    shape.m_cap_r2 = std::fmax(0.0, cubic(last.c, last.y_max));
    shape.m_r_max = r_max;
    shape.m_bounds = {{-r_max, y_low, -r_max}, {r_max, y_high, r_max}};
    if (!(r_max >= 0.0) || !is_finite(shape.m_bounds.lower) || !is_finite(shape.m_bounds.upper))
        return std::nullopt;
    shape.m_pieces = std::move(pieces);
    return shape;
}

const SorShape::Piece* SorShape::piece_at(double y) const {
    for (const Piece& p : *m_pieces)
        if (y >= p.y_min && y <= p.y_max) return &p;
    return nullptr;
}

bool SorShape::inside(const Vec3& p) const {
    if (p.y < m_bounds.lower.y || p.y > m_bounds.upper.y) return false;
    const double rho2 = p.x * p.x + p.z * p.z;
    if (rho2 > m_r_max * m_r_max) return false;
    // POV-Ray compat: the first piece whose height range holds the point decides.
    const Piece* piece = piece_at(p.y);
    return piece != nullptr && rho2 <= cubic(piece->c, p.y);
}

SurfaceHits SorShape::intersect_all(const LocalRay& ray, double t_min, double t_max) const {
    SurfaceHits hits;
    // POV-Ray compat: the cubic is in the distance k along the unit direction from the ray's own origin.
    const double len = std::sqrt(ray.direction.x * ray.direction.x + ray.direction.y * ray.direction.y +
                                 ray.direction.z * ray.direction.z);
    if (!(len > 0.0) || !std::isfinite(len)) return hits;
    const Vec3& P = ray.origin;
    const double inv_len = 1.0 / len;
    const Vec3 D{ray.direction.x * inv_len, ray.direction.y * inv_len, ray.direction.z * inv_len};
    const double y_low = m_bounds.lower.y, y_high = m_bounds.upper.y, r_max = m_r_max;
    // A query reaching behind its origin (t_min < 0) wants the whole line: none of the one-way culls then.
    const bool forward = t_min >= 0.0;
    if (forward && ((D.y >= 0.0 && P.y > y_high) || (D.y <= 0.0 && P.y < y_low) || (D.x >= 0.0 && P.x > r_max) ||
                    (D.x <= 0.0 && P.x < -r_max)))
        return hits;
    // The ray's distance from the axis (signed, as POV-Ray tests it).
    const double a = D.x * D.x + D.z * D.z;
    double r0 = P.x * D.z - P.z * D.x;
    if (a > 0.0) r0 /= std::sqrt(a);
    if (r0 > r_max) return hits;
    // The nearest crossing kept so far, in k.
    double best = inf;
    auto push = [&](double k, const Vec3& normal) {
        const double t = k / len;
        if (!(t > t_min && t < t_max)) return;
        hits.push({t, normal, dot(normal, ray.direction) < 0.0});
        best = std::fmin(best, k);
    };
    if (!m_open && std::fabs(D.y) > kEpsilon) {
        for (const auto& [y, r2, ny] : {std::tuple{y_low, m_base_r2, -1.0}, std::tuple{y_high, m_cap_r2, 1.0}}) {
            if (!(r2 > kDiscTolerance)) continue;
            const double k = (y - P.y) / D.y;
            const double u = P.x + k * D.x, v = P.z + k * D.z;
            if (u * u + v * v <= r2) push(k, {0.0, ny, 0.0});
        }
    }
    const double b = P.x * D.x + P.z * D.z;
    const double c = P.x * P.x + P.z * P.z;
    const bool crosses_planes = D.y < -kEpsilon || D.y > kEpsilon;
    // POV-Ray compat (Intersect_BCyl): a piece is solved only when the ray crosses the walls of its shell (the ring
    // between its two radii, its two heights) two or four times, not all behind; the pieces are visited in the
    // order of where the ray enters their shells (0 when it starts inside).
    thread_local std::vector<Entry> order_buffer;
    order_buffer.resize(std::max(order_buffer.size(), m_pieces->size()));
    Entry* order = order_buffer.data();
    int count = 0;
    for (int i = 0; i < static_cast<int>(m_pieces->size()); ++i) {
        const Piece& piece = (*m_pieces)[i];
        double dist[6];
        int nd = 0;
        if (crosses_planes) {
            for (const double h : {piece.y_max, piece.y_min}) {
                const double k = (h - P.y) / D.y;
                const double w = k * (a * k + 2.0 * b) + c;
                if (w >= piece.r2_inner && w <= piece.r2_outer) dist[nd++] = k;
            }
        }
        for (const double r2 : {piece.r2_inner, piece.r2_outer}) {
            if (!(r2 > kEpsilon)) continue;
            double d = b * b - a * (c - r2);
            if (!(d > 0.0)) continue;
            d = std::sqrt(d);
            for (const double k : {(-b + d) / a, (-b - d) / a}) {
                const double h = P.y + k * D.y;
                if (h >= piece.y_min && h <= piece.y_max) dist[nd++] = k;
            }
        }
        if (nd != 2 && nd != 4) continue;
        std::sort(dist, dist + nd);
        double entry;
        if (dist[0] > kEpsilon) entry = dist[0];
        else if (dist[1] > kEpsilon) entry = 0.0;
        else if (nd == 4 && dist[2] > kEpsilon) entry = dist[2];
        else if (nd == 4 && dist[3] > kEpsilon) entry = 0.0;
        else if (forward) continue;
        else entry = dist[0];
        // Inserted before the first entry at least as near, as POV-Ray's insert_hit does.
        int at = 0;
        while (at < count && entry > order[at].entry) ++at;
        for (int j = count; j > at; --j) order[j] = order[j - 1];
        order[at] = {entry, i};
        ++count;
    }
    for (int j = 0; j < count; ++j) {
        // POV-Ray compat: on its own (not a CSG child) the shape stops at the first shell entered beyond its
        // nearest crossing so far.
        if (m_first_only && forward && order[j].entry > best) break;
        const Piece& piece = (*m_pieces)[order[j].piece];
        // (P + k D)² across the axis = f(Py + k Dy), in POV-Ray's expansion.
        const double A = piece.c[3], B = piece.c[2], C = piece.c[1], Dc = piece.c[0];
        const double x[4] = {A * D.y * D.y * D.y, D.y * D.y * (3.0 * A * P.y + B) - a,
                             D.y * (P.y * (3.0 * A * P.y + 2.0 * B) + C) - 2.0 * (P.x * D.x + P.z * D.z),
                             P.y * (P.y * (A * P.y + B) + C) + Dc - P.x * P.x - P.z * P.z};
        double roots[3];
        for (int nr = solve_polynomial_pov(x, 3, roots, false, 0.0); nr--;) {
            const double k = roots[nr];
            const double h = P.y + k * D.y;
            if (!(h >= piece.y_min && h <= piece.y_max)) continue;
            const Vec3 p{P.x + k * D.x, h, P.z + k * D.z};
            // The gradient of rho² - f(y), halved: outward.
            push(k, {p.x, -0.5 * (p.y * (3.0 * A * p.y + 2.0 * B) + C), p.z});
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
