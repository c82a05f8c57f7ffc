// LatheShape: POV-Ray 3.7's spline pieces (lathe.cpp, Compute_Lathe) and the ray-profile polynomial in the piece
// parameter, solved on a ray recentred at its point nearest the origin.
#include "geometry/lathe.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/polynomial.h"

namespace wardray::geometry {

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

double poly(const std::array<double, 4>& c, double w) { return ((c[3] * w + c[2]) * w + c[1]) * w + c[0]; }
double dpoly(const std::array<double, 4>& c, double w) { return (3.0 * c[3] * w + 2.0 * c[2]) * w + c[1]; }

// Product of two polynomials given low-order first.
template <std::size_t N, std::size_t M>
std::array<double, N + M - 1> multiply(const std::array<double, N>& a, const std::array<double, M>& b) {
    std::array<double, N + M - 1> out{};
    for (std::size_t i = 0; i < N; ++i)
        for (std::size_t j = 0; j < M; ++j) out[i + j] += a[i] * b[j];
    return out;
}

// Minimum and maximum of a cubic on [0, 1]: its ends and the roots of its derivative.
void extent(const std::array<double, 4>& c, double& lo, double& hi) {
    lo = std::fmin(poly(c, 0.0), poly(c, 1.0));
    hi = std::fmax(poly(c, 0.0), poly(c, 1.0));
    const double d[3] = {c[1], 2.0 * c[2], 3.0 * c[3]};
    double roots[2];
    const int n = polynomial_roots(d, 2, 0.0, 1.0, roots);
    for (int i = 0; i < n; ++i) {
        lo = std::fmin(lo, poly(c, roots[i]));
        hi = std::fmax(hi, poly(c, roots[i]));
    }
}

}  // namespace

std::optional<LatheShape> LatheShape::create(const scene::Lathe& lathe) {
    using Spline = scene::Lathe::Spline;
    const auto& P = lathe.points;
    const int n = static_cast<int>(P.size());
    for (const Vec3& p : P)
        if (!is_finite(p)) return std::nullopt;
    LatheShape shape;
    auto pieces = std::make_shared<std::vector<Piece>>();
    int count = 0;
    switch (lathe.spline) {
        case Spline::Linear: count = n - 1; shape.m_degree = 1; break;
        case Spline::Quadratic: count = n - 2; shape.m_degree = 2; break;
        case Spline::Cubic: count = n - 3; shape.m_degree = 3; break;
        case Spline::Bezier: count = n / 4; shape.m_degree = 3; break;
    }
    if (count < 1) return std::nullopt;
    for (int k = 0; k < count; ++k) {
        Piece piece;
        // POV-Ray compat: the coefficients of Compute_Lathe (Catmull-Rom for cubic, and its quadratic form).
        for (int axis = 0; axis < 2; ++axis) {
            auto& c = axis == 0 ? piece.r : piece.y;
            auto p = [&](int i) { return axis == 0 ? P[i].x : P[i].y; };
            switch (lathe.spline) {
                case Spline::Linear: c = {p(k), p(k + 1) - p(k), 0.0, 0.0}; break;
                case Spline::Quadratic:
                    c = {p(k + 1), -0.5 * p(k) + 0.5 * p(k + 2), 0.5 * p(k) - p(k + 1) + 0.5 * p(k + 2), 0.0};
                    break;
                case Spline::Cubic:
                    c = {p(k + 1), -0.5 * p(k) + 0.5 * p(k + 2),
                         p(k) - 2.5 * p(k + 1) + 2.0 * p(k + 2) - 0.5 * p(k + 3),
                         -0.5 * p(k) + 1.5 * p(k + 1) - 1.5 * p(k + 2) + 0.5 * p(k + 3)};
                    break;
                case Spline::Bezier: {
                    const int i = 4 * k;
                    c = {p(i), 3.0 * p(i + 1) - 3.0 * p(i), 3.0 * p(i + 2) - 6.0 * p(i + 1) + 3.0 * p(i),
                         p(i + 3) - 3.0 * p(i + 2) + 3.0 * p(i + 1) - p(i)};
                    break;
                }
            }
        }
        const int last = lathe.spline == Spline::Linear ? k + 1 : lathe.spline == Spline::Bezier ? 4 * k + 3 : k + 2;
        piece.r_end = P[last].x;
        piece.y_end = P[last].y;
        double r_lo, r_hi;
        extent(piece.r, r_lo, r_hi);
        extent(piece.y, piece.y_min, piece.y_max);
        piece.r_max = std::fmax(std::fabs(r_lo), std::fabs(r_hi));
        piece.r_min = r_lo <= 0.0 && r_hi >= 0.0 ? 0.0 : std::fmin(std::fabs(r_lo), std::fabs(r_hi));
        // The ranges the inside test checks first. POV-Ray compat: a Bézier piece counts with its control
        // points (Compute_Lathe), which reach beyond the curve.
        double in_r_lo = r_lo, in_r_hi = r_hi, in_y_lo = piece.y_min, in_y_hi = piece.y_max;
        if (lathe.spline == Spline::Bezier)
            for (int j = 4 * k; j < 4 * k + 4; ++j) {
                in_r_lo = std::fmin(in_r_lo, P[j].x);
                in_r_hi = std::fmax(in_r_hi, P[j].x);
                in_y_lo = std::fmin(in_y_lo, P[j].y);
                in_y_hi = std::fmax(in_y_hi, P[j].y);
            }
        if (k == 0) {
            shape.m_r_min = in_r_lo;
            shape.m_r_max = in_r_hi;
            shape.m_y_min = in_y_lo;
            shape.m_y_max = in_y_hi;
        }
        shape.m_r_min = std::fmin(shape.m_r_min, in_r_lo);
        shape.m_r_max = std::fmax(shape.m_r_max, in_r_hi);
        shape.m_y_min = std::fmin(shape.m_y_min, in_y_lo);
        shape.m_y_max = std::fmax(shape.m_y_max, in_y_hi);
        pieces->push_back(piece);
    }
    double reach = 0.0;
    for (const Piece& p : *pieces) reach = std::fmax(reach, p.r_max);
    shape.m_bounds = {{-reach, shape.m_y_min, -reach}, {reach, shape.m_y_max, reach}};
    if (!is_finite(shape.m_bounds.lower) || !is_finite(shape.m_bounds.upper)) return std::nullopt;
    shape.m_pieces = std::move(pieces);
    return shape;
}

bool LatheShape::inside_profile(double radius, double height) const {
    // POV-Ray compat: nothing outside the profile's radius and height range is inside.
    if (height < m_y_min || height > m_y_max || radius < m_r_min || radius > m_r_max) return false;
    int crossings = 0;
    for (const Piece& piece : *m_pieces) {
        if (height < piece.y_min || height > piece.y_max) continue;
        // Monotone pieces of y(w), each counted by the half-open rule "above the height" so ends count once.
        double cuts[4] = {0.0};
        int n_cuts = 1;
        const double d[3] = {piece.y[1], 2.0 * piece.y[2], 3.0 * piece.y[3]};
        double roots[2];
        const int nr = polynomial_roots(d, 2, 0.0, 1.0, roots);
        for (int i = 0; i < nr; ++i)
            if (roots[i] > 0.0 && roots[i] < 1.0) cuts[n_cuts++] = roots[i];
        cuts[n_cuts++] = 1.0;
        // Ends exactly as given, so the piece before and the piece after agree about them.
        auto y_at = [&](double w) { return w == 1.0 ? piece.y_end : poly(piece.y, w); };
        auto r_at = [&](double w) { return w == 1.0 ? piece.r_end : poly(piece.r, w); };
        for (int k = 0; k + 1 < n_cuts; ++k) {
            const double ya = y_at(cuts[k]), yb = y_at(cuts[k + 1]);
            if ((ya > height) == (yb > height)) continue;
            std::array<double, 4> c = piece.y;
            c[0] -= height;
            double w[3];
            const int nw = polynomial_roots(c.data(), 3, cuts[k], cuts[k + 1], w);
            const double wk = nw > 0 ? w[0] : (std::fabs(ya - height) < std::fabs(yb - height) ? cuts[k] : cuts[k + 1]);
            crossings += r_at(wk) >= radius;
        }
    }
    return (crossings & 1) != 0;
}

bool LatheShape::inside(const Vec3& p) const { return inside_profile(std::hypot(p.x, p.z), p.y); }

SurfaceHits LatheShape::intersect_all(const LocalRay& ray, double t_min, double t_max) const {
    SurfaceHits hits;
    const auto line = centre_line(ray);
    if (!line) return hits;
    const auto& [u, o, s0, len] = *line;
    double b0, b1;
    if (!slab_interval(m_bounds.lower, m_bounds.upper, o, u, b0, b1)) return hits;
    const double rho2 = o.x * o.x + o.z * o.z;  // squared distance from the axis at s = 0
    const double m = o.x * u.x + o.z * u.z;
    const double rr = u.x * u.x + u.z * u.z;
    const double scale = std::fmax(max_abs_component(m_bounds.lower), max_abs_component(m_bounds.upper));
    // A ray this close to horizontal makes the polynomial's roots pair up too closely to separate: it is solved
    // at its height at s = 0, then polished for its tilt (POV-Ray switches at 1e-10 and misses such hits).
    const bool level = std::fabs(u.y) <= 1e-6;
    for (std::size_t k = 0; k < m_pieces->size(); ++k) {
        const Piece& piece = (*m_pieces)[k];
        double p0, p1;
        const Vec3 reach{piece.r_max, 0.0, piece.r_max};
        if (!slab_interval(Vec3{-reach.x, piece.y_min, -reach.z}, Vec3{reach.x, piece.y_max, reach.z}, o, u, p0, p1)) continue;
        // The ray's squared distance from the axis over that stretch must reach the piece's ring of radii.
        {
            auto rho2_at = [&](double s) { return rho2 + 2.0 * m * s + rr * s * s; };
            const double s_near = rr > 0.0 ? std::clamp(-m / rr, p0, p1) : p0;
            const double lo = rho2_at(s_near), hi = std::fmax(rho2_at(p0), rho2_at(p1));
            const double tol = 1e-9 * (scale * scale + hi);
            if (lo > piece.r_max * piece.r_max + tol || hi < piece.r_min * piece.r_min - tol) continue;
        }
        // Hits as (w, s) pairs: the piece parameter and the distance along the unit ray.
        double ws[12], ss[12];
        int nh = 0;
        if (!level) {
            // rr Y² + 2 m uy Y + uy² (rho² - r²) = 0 with Y = y(w) - oy: the height's distance along the ray is Y/uy.
            std::array<double, 4> Y = piece.y;
            Y[0] -= o.y;
            const auto YY = multiply(Y, Y);
            const auto RR = multiply(piece.r, piece.r);
            double c[7];
            for (int i = 0; i < 7; ++i)
                c[i] = rr * YY[i] + (i < 4 ? 2.0 * m * u.y * Y[i] : 0.0) - u.y * u.y * RR[i] + (i == 0 ? u.y * u.y * rho2 : 0.0);
            double w[6];
            const int n = polynomial_roots(c, 2 * m_degree, 0.0, 1.0, w);
            for (int i = 0; i < n; ++i) {
                ws[nh] = w[i];
                ss[nh++] = (poly(piece.y, w[i]) - o.y) / u.y;
            }
        } else {
            std::array<double, 4> Y = piece.y;
            Y[0] -= o.y;
            double w[3];
            const int n = polynomial_roots(Y.data(), m_degree, 0.0, 1.0, w);
            for (int i = 0; i < n; ++i) {
                const double r = poly(piece.r, w[i]);
                // rr s² + 2 m s + rho² - r² = 0.
                const double disc = m * m - rr * (rho2 - r * r);
                if (disc < 0.0 || rr == 0.0) continue;
                const double q = -(m + std::copysign(std::sqrt(disc), m));
                for (double s : {q / rr, q != 0.0 ? (rho2 - r * r) / q : q / rr}) {
                    // Newton on y(w) = oy + s uy and r(w)² = rho² + 2 m s + rr s² from the level solution.
                    double wk = w[i];
                    bool ok = true;
                    for (int iter = 0; iter < 8 && u.y != 0.0; ++iter) {
                        const double rk = poly(piece.r, wk);
                        const double f1 = poly(piece.y, wk) - o.y - s * u.y;
                        const double f2 = rk * rk - (rho2 + 2.0 * m * s + rr * s * s);
                        const double a = dpoly(piece.y, wk), b = -u.y;
                        const double c = 2.0 * rk * dpoly(piece.r, wk), d = -2.0 * (m + rr * s);
                        const double det = a * d - b * c;
                        if (det == 0.0 || !std::isfinite(det)) {
                            ok = false;
                            break;
                        }
                        const double dw = (f1 * d - b * f2) / det, ds = (a * f2 - c * f1) / det;
                        wk -= dw;
                        s -= ds;
                        if (std::fabs(dw) <= 1e-15 && std::fabs(ds) <= 1e-15 * (1.0 + std::fabs(s))) break;
                    }
                    if (!ok || !(wk >= -1e-9 && wk <= 1.0 + 1e-9)) continue;
                    ws[nh] = std::clamp(wk, 0.0, 1.0);
                    ss[nh++] = s;
                }
            }
        }
        for (int i = 0; i < nh; ++i) {
            const double t = (s0 + ss[i]) / len;
            if (!(t > t_min && t < t_max)) continue;
            const double w = ws[i];
            const Vec3 p = o + ss[i] * u;
            const double radius = std::hypot(p.x, p.z);
            const double r = poly(piece.r, w);
            // The profile's normal (dy, -dr) in the half-plane of |r| (mirrored where r < 0), turned about the axis;
            // on the axis it points along y.
            const double dr = dpoly(piece.r, w), dy = (r < 0.0 ? -1.0 : 1.0) * dpoly(piece.y, w);
            const double nlen = std::hypot(dr, dy);
            if (!(nlen > 0.0)) continue;
            Vec3 normal = radius > 1e-12 * scale ? Vec3{dy * p.x / radius, -dr, dy * p.z / radius} : Vec3{0, 1, 0};
            // Outward: the side of the profile where the inside test fails.
            const double step = 1e-7 * scale;
            if (inside_profile(std::fabs(r) + step * dy / nlen, poly(piece.y, w) - step * dr / nlen)) normal = -normal;
            hits.push({t, normal, dot(normal, ray.direction) < 0.0});
        }
    }
    hits.sort_by_t();
    return hits;
}

double LatheShape::implicit(const Vec3& p) const {
    const double radius = std::hypot(p.x, p.z);
    double best = inf;
    for (const Piece& piece : *m_pieces) {
        // The profile point nearest (radius, height), mirrored where the profile runs left of the axis.
        auto dist2 = [&](double w) {
            const double dr = std::fabs(poly(piece.r, w)) - radius, dy = poly(piece.y, w) - p.y;
            return dr * dr + dy * dy;
        };
        best = std::fmin(best, minimum_on_unit_interval(dist2));
    }
    const double dist = std::sqrt(best);
    return inside(p) ? -dist : dist;
}

}  // namespace wardray::geometry
