// TextShape: glyph outlines as lines and quadratic arcs; walls by solving each arc against the ray's x-y projection,
// caps by the even-odd inside test (POV-Ray 3.7's TrueType object, with half-open crossing rules of our own).
#include "geometry/text.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace wardray::geometry {

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();
// Arc parameters this far outside [0, 1] still count, so that no crack opens where two arcs meet.
constexpr double kSlack = 1e-9;
// Step off the outline (em units) to decide which side of a wall is inside the glyph.
constexpr double kSideStep = 1e-7;

using Segment = TextShape::Segment;

// Point and tangent of a segment at parameter s.
void evaluate(const Segment& g, double s, double& x, double& y, double& tx, double& ty) {
    if (!g.quadratic) {
        x = g.x0 + s * (g.x2 - g.x0);
        y = g.y0 + s * (g.y2 - g.y0);
        tx = g.x2 - g.x0;
        ty = g.y2 - g.y0;
        return;
    }
    const double ax = g.x0 - 2.0 * g.x1 + g.x2, ay = g.y0 - 2.0 * g.y1 + g.y2;
    const double bx = 2.0 * (g.x1 - g.x0), by = 2.0 * (g.y1 - g.y0);
    x = (ax * s + bx) * s + g.x0;
    y = (ay * s + by) * s + g.y0;
    tx = 2.0 * ax * s + bx;
    ty = 2.0 * ay * s + by;
    // A control point on an end point leaves no tangent there: the chord's direction is the limit.
    if (tx == 0.0 && ty == 0.0) {
        tx = g.x2 - g.x0;
        ty = g.y2 - g.y0;
    }
}

// Real roots of a2 s² + a1 s + a0 = 0 by the cancellation-free formula; returns their count (0 to 2).
int solve_quadratic(double a2, double a1, double a0, double roots[2]) {
    if (a2 == 0.0) {
        if (a1 == 0.0) return 0;
        roots[0] = -a0 / a1;
        return 1;
    }
    const double disc = a1 * a1 - 4.0 * a2 * a0;
    if (disc < 0.0) return 0;
    const double q = -0.5 * (a1 + std::copysign(std::sqrt(disc), a1));
    roots[0] = q / a2;
    if (q == 0.0) return 1;
    roots[1] = a0 / q;
    return 2;
}

// The parameter in [sa, sb] where the monotone arc y(s) = yt2 s² + yt1 s + y0 reaches y.
double solve_monotone(double yt2, double yt1, double y0, double y, double sa, double sb) {
    double roots[2];
    const int n = solve_quadratic(yt2, yt1, y0 - y, roots);
    double best = 0.5 * (sa + sb);
    double best_gap = inf;
    for (int i = 0; i < n; ++i) {
        const double gap = std::fmax(sa - roots[i], roots[i] - sb);
        if (gap < best_gap) {
            best_gap = gap;
            best = roots[i];
        }
    }
    return std::clamp(best, sa, sb);
}

// Distance from (x, y) to a segment: exact for lines, sampled then refined by Newton steps for arcs.
double segment_distance(const Segment& g, double x, double y) {
    auto dist2 = [&](double s) {
        double px, py, tx, ty;
        evaluate(g, s, px, py, tx, ty);
        return (px - x) * (px - x) + (py - y) * (py - y);
    };
    if (!g.quadratic) {
        const double ex = g.x2 - g.x0, ey = g.y2 - g.y0;
        const double len2 = ex * ex + ey * ey;
        const double s = len2 > 0.0 ? std::clamp(((x - g.x0) * ex + (y - g.y0) * ey) / len2, 0.0, 1.0) : 0.0;
        return std::sqrt(dist2(s));
    }
    double s = 0.0;
    double best = dist2(0.0);
    for (int k = 1; k <= 16; ++k) {
        const double d = dist2(k / 16.0);
        if (d < best) {
            best = d;
            s = k / 16.0;
        }
    }
    const double ax = g.x0 - 2.0 * g.x1 + g.x2, ay = g.y0 - 2.0 * g.y1 + g.y2;
    for (int iter = 0; iter < 8; ++iter) {
        double px, py, tx, ty;
        evaluate(g, s, px, py, tx, ty);
        // Newton on the derivative of the squared distance: (Q - p)·Q' = 0.
        const double f = (px - x) * tx + (py - y) * ty;
        const double df = tx * tx + ty * ty + (px - x) * 2.0 * ax + (py - y) * 2.0 * ay;
        if (!(df > 0.0)) break;
        s = std::clamp(s - f / df, 0.0, 1.0);
    }
    return std::sqrt(std::fmin(best, dist2(s)));
}

}  // namespace

std::optional<TextShape> TextShape::create(const scene::Text& text) {
    if (!std::isfinite(text.thickness)) return std::nullopt;
    TextShape shape;
    shape.m_z_low = std::fmin(0.0, text.thickness);
    shape.m_z_high = std::fmax(0.0, text.thickness);
    auto glyphs = std::make_shared<std::vector<Glyph>>();
    Bounds all{{inf, inf, shape.m_z_low}, {-inf, -inf, shape.m_z_high}};
    for (const scene::TextGlyph& tg : text.glyphs) {
        Glyph glyph{{}, inf, inf, -inf, -inf};
        for (const auto& contour : tg.contours) {
            const std::size_t n = contour.size();
            if (n == 0) continue;
            auto at = [&](std::size_t k) -> const scene::TextGlyph::Point& { return contour[k % n]; };
            auto add = [&](Segment s) {
                for (double v : {s.x0, s.y0, s.x1, s.y1, s.x2, s.y2})
                    if (!std::isfinite(v)) return;
                if (s.x0 == s.x2 && s.y0 == s.y2 && (!s.quadratic || (s.x1 == s.x0 && s.y1 == s.y0))) return;
                glyph.x_min = std::fmin(glyph.x_min, std::fmin(s.x0, s.x2));
                glyph.x_max = std::fmax(glyph.x_max, std::fmax(s.x0, s.x2));
                glyph.y_min = std::fmin(glyph.y_min, std::fmin(s.y0, s.y2));
                glyph.y_max = std::fmax(glyph.y_max, std::fmax(s.y0, s.y2));
                if (s.quadratic) {
                    glyph.x_min = std::fmin(glyph.x_min, s.x1);
                    glyph.x_max = std::fmax(glyph.x_max, s.x1);
                    glyph.y_min = std::fmin(glyph.y_min, s.y1);
                    glyph.y_max = std::fmax(glyph.y_max, s.y1);
                }
                glyph.segments.push_back(s);
            };
            const double ox = tg.offset.x, oy = tg.offset.y;
            // POV-Ray compat: its walk of a TrueType contour. The first point starts the outline (on the curve or
            // not); an off-curve point makes an arc to the next point, or to the midpoint when that one is off the
            // curve too; the contour closes back on its first point.
            double x0 = at(0).x + ox, y0 = at(0).y + oy;
            for (std::size_t j = 1; j <= n; ++j) {
                const auto& p1 = at(j);
                if (p1.on_curve) {
                    add({x0, y0, 0.0, 0.0, p1.x + ox, p1.y + oy, false});
                    x0 = p1.x + ox;
                    y0 = p1.y + oy;
                    continue;
                }
                double x2 = at(0).x, y2 = at(0).y;
                if (j < n) {
                    const auto& next = at(j + 1);
                    x2 = next.on_curve ? next.x : 0.5 * (p1.x + next.x);
                    y2 = next.on_curve ? next.y : 0.5 * (p1.y + next.y);
                }
                add({x0, y0, p1.x + ox, p1.y + oy, x2 + ox, y2 + oy, true});
                x0 = x2 + ox;
                y0 = y2 + oy;
            }
        }
        if (glyph.segments.empty()) continue;
        all.lower = min(all.lower, Vec3{glyph.x_min, glyph.y_min, shape.m_z_low});
        all.upper = max(all.upper, Vec3{glyph.x_max, glyph.y_max, shape.m_z_high});
        glyphs->push_back(std::move(glyph));
    }
    if (glyphs->empty()) return std::nullopt;
    shape.m_glyphs = std::move(glyphs);
    shape.m_bounds = all;
    return shape;
}

bool TextShape::inside_outline(const Glyph& glyph, double x, double y) const {
    if (x < glyph.x_min || x > glyph.x_max || y < glyph.y_min || y > glyph.y_max) return false;
    // Even-odd count of crossings on the ray from (x, y) toward +x; a piece counts when its ends lie on either
    // side of the half-open split "above y" / "not above y", so shared end points count once.
    int crossings = 0;
    for (const Segment& g : glyph.segments) {
        if (!g.quadratic) {
            if ((g.y0 > y) == (g.y2 > y)) continue;
            const double xc = g.x0 + (y - g.y0) * (g.x2 - g.x0) / (g.y2 - g.y0);
            crossings += xc > x;
            continue;
        }
        const bool a0 = g.y0 > y, a1 = g.y1 > y, a2 = g.y2 > y;
        if (a0 == a1 && a1 == a2) continue;
        if (g.x0 <= x && g.x1 <= x && g.x2 <= x) continue;
        const double yt2 = g.y0 - 2.0 * g.y1 + g.y2;
        const double yt1 = 2.0 * (g.y1 - g.y0);
        // Split at the arc's extreme in y so each piece is monotone.
        double cuts[3] = {0.0, 1.0, 1.0};
        int n_cuts = 2;
        if (yt2 != 0.0) {
            const double s_star = -yt1 / (2.0 * yt2);
            if (s_star > 0.0 && s_star < 1.0) {
                cuts[1] = s_star;
                n_cuts = 3;
            }
        }
        auto y_at = [&](double s) { return s == 0.0 ? g.y0 : s == 1.0 ? g.y2 : (yt2 * s + yt1) * s + g.y0; };
        for (int k = 0; k + 1 < n_cuts; ++k) {
            const double sa = cuts[k], sb = cuts[k + 1];
            if ((y_at(sa) > y) == (y_at(sb) > y)) continue;
            const double s = solve_monotone(yt2, yt1, g.y0, y, sa, sb);
            double px, py, tx, ty;
            evaluate(g, s, px, py, tx, ty);
            crossings += px > x;
        }
    }
    return (crossings & 1) != 0;
}

SurfaceHits TextShape::intersect_all(const LocalRay& ray, double t_min, double t_max) const {
    SurfaceHits hits;
    const Vec3& P = ray.origin;
    const Vec3& D = ray.direction;
    // The part of the ray inside the slab between the caps.
    double tz0 = -inf, tz1 = inf;
    if (D.z != 0.0) {
        tz0 = (m_z_low - P.z) / D.z;
        tz1 = (m_z_high - P.z) / D.z;
        if (tz0 > tz1) std::swap(tz0, tz1);
    } else if (P.z < m_z_low || P.z > m_z_high) {
        return hits;
    }
    const double pad = 1e-9 * (1.0 + std::fabs(tz0) + std::fabs(tz1));
    const double lo = std::fmax(t_min, tz0 - pad);
    const double hi = std::fmin(t_max, tz1 + pad);
    if (!(lo <= hi)) return hits;
    const bool walls = D.x != 0.0 || D.y != 0.0;
    for (const Glyph& glyph : *m_glyphs) {
        // The glyph's box in x and y, slightly grown, cuts the range further.
        double g0 = lo, g1 = hi;
        const double box_pad = 1e-9 * (1.0 + std::fmax(std::fabs(glyph.x_max - glyph.x_min), std::fabs(glyph.y_max - glyph.y_min)));
        const double bl[2] = {glyph.x_min - box_pad, glyph.y_min - box_pad};
        const double bu[2] = {glyph.x_max + box_pad, glyph.y_max + box_pad};
        for (int k = 0; k < 2 && g0 <= g1; ++k) {
            const double o = k == 0 ? P.x : P.y;
            const double d = k == 0 ? D.x : D.y;
            if (d == 0.0) {
                if (o < bl[k] || o > bu[k]) g1 = -inf;
                continue;
            }
            double a = (bl[k] - o) / d, b = (bu[k] - o) / d;
            if (a > b) std::swap(a, b);
            g0 = std::fmax(g0, a);
            g1 = std::fmin(g1, b);
        }
        if (!(g0 <= g1)) continue;
        // Caps: where the ray meets z = low and z = high inside the outline.
        if (D.z != 0.0) {
            for (const auto& [z, nz] : {std::pair{m_z_low, -1.0}, std::pair{m_z_high, 1.0}}) {
                const double t = (z - P.z) / D.z;
                if (!(t > t_min && t < t_max)) continue;
                if (!inside_outline(glyph, P.x + t * D.x, P.y + t * D.y)) continue;
                hits.push({t, {0.0, 0.0, nz}, nz * D.z < 0.0});
            }
        }
        if (!walls) continue;
        for (const Segment& g : glyph.segments) {
            double roots[2];
            int n = 0;
            if (!g.quadratic) {
                const double ex = g.x2 - g.x0, ey = g.y2 - g.y0;
                const double denom = D.x * ey - D.y * ex;
                if (denom == 0.0) continue;
                const double ax = g.x0 - P.x, ay = g.y0 - P.y;
                roots[0] = (ax * D.y - ay * D.x) / denom;
                n = 1;
            } else {
                // cross(Q(s) - P, D) = 0 with Q(s) = A s² + B s + p0.
                const double ax = g.x0 - 2.0 * g.x1 + g.x2, ay = g.y0 - 2.0 * g.y1 + g.y2;
                const double bx = 2.0 * (g.x1 - g.x0), by = 2.0 * (g.y1 - g.y0);
                const double cx = g.x0 - P.x, cy = g.y0 - P.y;
                n = solve_quadratic(ax * D.y - ay * D.x, bx * D.y - by * D.x, cx * D.y - cy * D.x, roots);
            }
            for (int i = 0; i < n; ++i) {
                if (!(roots[i] >= -kSlack && roots[i] <= 1.0 + kSlack)) continue;
                const double s = std::clamp(roots[i], 0.0, 1.0);
                double qx, qy, tx, ty;
                evaluate(g, s, qx, qy, tx, ty);
                const double t = std::fabs(D.x) >= std::fabs(D.y) ? (qx - P.x) / D.x : (qy - P.y) / D.y;
                if (!(t > t_min && t < t_max)) continue;
                const double z = P.z + t * D.z;
                if (z < m_z_low || z > m_z_high) continue;
                // The wall's normal turned away from the glyph's inside.
                Vec3 normal{ty, -tx, 0.0};
                const double len = std::hypot(tx, ty);
                if (!(len > 0.0)) continue;
                if (inside_outline(glyph, qx + kSideStep * ty / len, qy - kSideStep * tx / len)) normal = -normal;
                hits.push({t, normal, dot(normal, D) < 0.0});
            }
        }
    }
    hits.sort_by_t();
    return without_repeated_crossings(hits);
}

bool TextShape::inside(const Vec3& p) const {
    // POV-Ray compat: the slab includes both caps.
    if (!(p.z >= m_z_low && p.z <= m_z_high)) return false;
    for (const Glyph& g : *m_glyphs)
        if (inside_outline(g, p.x, p.y)) return true;
    return false;
}

double TextShape::outline_distance(const Glyph& glyph, double x, double y) const {
    double best = inf;
    for (const Segment& g : glyph.segments) best = std::fmin(best, segment_distance(g, x, y));
    return best;
}

double TextShape::implicit(const Vec3& p) const {
    double d_xy = inf;
    bool in_xy = false;
    for (const Glyph& g : *m_glyphs) {
        d_xy = std::fmin(d_xy, outline_distance(g, p.x, p.y));
        in_xy = in_xy || inside_outline(g, p.x, p.y);
    }
    const bool in_z = p.z >= m_z_low && p.z <= m_z_high;
    if (in_xy && in_z) return -std::fmin(d_xy, std::fmin(p.z - m_z_low, m_z_high - p.z));
    const double dz = std::fmax(0.0, std::fmax(m_z_low - p.z, p.z - m_z_high));
    if (in_z) return d_xy;
    if (in_xy) return dz;
    return std::hypot(d_xy, dz);
}

}  // namespace wardray::geometry
