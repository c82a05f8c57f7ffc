// OvusShape: the two spheres' crossings beyond their joins and the spindle torus's quartic between them.
#include "geometry/ovus.h"

#include <algorithm>
#include <cmath>

#include "geometry/polynomial.h"

namespace wardray::geometry {

namespace {

// POV-Ray's ROOT_TOLERANCE in ovus.cpp: a torus root belongs to the band ("lemon") when its squared distance from
// the tube's circle on the far side of the axis is the tube radius squared to within this (object units squared).
constexpr double k_root_tolerance = 1e-4;

// The distances s along the unit line o + s u where it crosses the sphere (c, r); false when it misses.
bool sphere_roots(const Vec3& o, const Vec3& u, const Vec3& c, double r, double& s1, double& s2) {
    const Vec3 w = o - c;
    const double b = dot(w, u);
    const Vec3 f = w - b * u;
    const double h2 = r * r - dot(f, f);
    if (!(h2 >= 0.0)) return false;
    const double h = std::sqrt(h2);
    s1 = -b - h;
    s2 = -b + h;
    return true;
}

}  // namespace

std::optional<OvusShape> OvusShape::create(const scene::Ovus& ovus) {
    const double b = ovus.bottom_radius, t = ovus.top_radius;
    if (!std::isfinite(b) || !std::isfinite(t) || b < 0.0 || t < 0.0) return std::nullopt;
    OvusShape s;
    s.m_bottom = b;
    s.m_top = t;
    // POV-Ray compat (Parse_Ovus): the top sphere replaces the ovus when it would swallow the bottom one.
    if (!(t < 2.0 * b)) {
        if (t == 0.0) return std::nullopt;
        s.m_sphere_only = true;
        return s;
    }
    // The band's circle (in a half-plane through the axis) is tangent inside both spheres' circles: its centre at
    // distance R - b from the bottom sphere's centre and R - t from the top one's, R twice the larger radius.
    if (b > t) {
        s.m_connecting = 2.0 * b;
        s.m_vertical = 2.0 * t - b - t * t / (2.0 * b);
        s.m_horizontal = std::sqrt(std::fmax(0.0, b * b - s.m_vertical * s.m_vertical));
        s.m_bottom_join = -s.m_vertical;
        s.m_top_join = (b - s.m_vertical) * t / (s.m_connecting - t) + b;
    } else {
        s.m_connecting = 2.0 * t;
        s.m_vertical = -2.0 * t + b + 1.5 * t * t / b;
        const double dv = s.m_vertical - b;
        s.m_horizontal = std::sqrt(std::fmax(0.0, t * t - dv * dv));
        s.m_top_join = 2.0 * b - s.m_vertical;
        s.m_bottom_join = -s.m_vertical * b / (s.m_connecting - b);
    }
    return s;
}

SurfaceHits OvusShape::intersect_all(const LocalRay& ray, double t_min, double t_max) const {
    SurfaceHits hits;
    const auto line = centre_line(ray);
    if (!line) return hits;
    const Vec3& u = line->u;
    const Vec3& o = line->o;
    // Plain names, not structured bindings: clang 14 (the fuzz build) cannot capture those in a lambda.
    const double s0 = line->s0;
    const double len = line->length;
    const Vec3 top_centre{0.0, m_bottom, 0.0};
    auto add = [&](double s, auto&& keep, auto&& normal_at) {
        const double t = (s0 + s) / len;
        if (!(t > t_min && t < t_max)) return;
        const Vec3 p = ray.origin + t * ray.direction;
        if (!keep(p)) return;
        const Vec3 n = normal_at(p);
        hits.push({t, n, dot(n, ray.direction) < 0.0});
    };
    double s1 = 0.0, s2 = 0.0;
    if (m_sphere_only) {
        if (sphere_roots(o, u, top_centre, m_top, s1, s2)) {
            const auto any = [](const Vec3&) { return true; };
            const auto n = [&](const Vec3& p) { return (p - top_centre) / m_top; };
            add(s1, any, n);
            add(s2, any, n);
        }
        return hits;
    }
    // The bottom sphere below its join, the top sphere above its own.
    if (sphere_roots(o, u, Vec3{}, m_bottom, s1, s2)) {
        const auto below = [&](const Vec3& p) { return p.y < m_bottom_join; };
        const auto n = [&](const Vec3& p) { return p / m_bottom; };
        add(s1, below, n);
        add(s2, below, n);
    }
    if (m_top > 0.0 && sphere_roots(o, u, top_centre, m_top, s1, s2)) {
        const auto above = [&](const Vec3& p) { return p.y > m_top_join; };
        const auto n = [&](const Vec3& p) { return (p - top_centre) / m_top; };
        add(s1, above, n);
        add(s2, above, n);
    }
    // The spindle torus around the axis, centred at height m_vertical: major radius H, tube radius R > H.
    const Vec3 centre{0.0, m_vertical, 0.0};
    const auto tline = centre_line(LocalRay{ray.origin - centre, ray.direction});
    if (tline) {
        const auto& [tu, to, ts0, tlen] = *tline;
        const double H = m_horizontal, R = m_connecting;
        const double outer = H + R;
        const double h2 = outer * outer - dot(to, to);
        if (h2 >= 0.0) {
            const double half = std::sqrt(h2) * (1.0 + 1e-9) + 1e-12 * outer;
            // (|o + s u|² + H² - R²)² - 4H²((ox + s ux)² + (oz + s uz)²) with |u| = 1 and o·u = 0.
            const double H2 = H * H;
            const double k = dot(to, to) + H2 - R * R;
            const double oxz = to.x * to.x + to.z * to.z;
            const double oduxz = to.x * tu.x + to.z * tu.z;
            const double uxz = tu.x * tu.x + tu.z * tu.z;
            const double c[5] = {k * k - 4.0 * H2 * oxz, -8.0 * H2 * oduxz, 2.0 * k - 4.0 * H2 * uxz, 0.0, 1.0};
            // Only the stretch of the chord within (t_min, t_max), as the torus searches.
            const double lo = std::fmax(-half, t_min * tlen - ts0), hi = std::fmin(half, t_max * tlen - ts0);
            double roots[4];
            const int n = polynomial_roots(c, 4, lo, hi, roots);
            for (int i = 0; i < n; ++i) {
                const double t = (ts0 + roots[i]) / tlen;
                if (!(t > t_min && t < t_max)) continue;
                const Vec3 p = ray.origin + t * ray.direction;
                if (!(p.y > m_bottom_join && p.y < m_top_join)) continue;
                // POV-Ray compat: only the band (the tube's circle on the far side of the axis), not the apple.
                const double h = std::sqrt(p.x * p.x + p.z * p.z);
                const double dy = p.y - m_vertical;
                if (!(std::fabs((h + H) * (h + H) + dy * dy - R * R) < k_root_tolerance)) continue;
                // The gradient of the band's circle swept around the axis.
                Vec3 normal{p.x, dy, p.z};
                if (h > 0.0) {
                    normal.x += p.x * H / h;
                    normal.z += p.z * H / h;
                }
                hits.push({t, normal, dot(normal, ray.direction) < 0.0});
            }
        }
    }
    hits.sort_by_t();
    return hits;
}

std::optional<Bounds> OvusShape::bounds() const {
    if (m_sphere_only) {
        const Vec3 r{m_top, m_top, m_top};
        return Bounds{Vec3{0.0, m_bottom, 0.0} - r, Vec3{0.0, m_bottom, 0.0} + r};
    }
    const double widest = std::max({m_connecting - m_horizontal, m_bottom, m_top});
    return Bounds{{-widest, -m_bottom, -widest}, {widest, m_bottom + m_top, widest}};
}

bool OvusShape::inside(const Vec3& p) const {
    const Vec3 q = p - Vec3{0.0, m_bottom, 0.0};
    if (dot(q, q) < m_top * m_top) return true;
    if (m_sphere_only) return false;
    if (dot(p, p) < m_bottom * m_bottom) return true;
    if (!(p.y > m_bottom_join && p.y < m_top_join)) return false;
    const double h = std::sqrt(p.x * p.x + p.z * p.z) + m_horizontal;
    const double dy = p.y - m_vertical;
    return h * h + dy * dy < m_connecting * m_connecting;
}

double OvusShape::implicit(const Vec3& p) const {
    double d = length(p - Vec3{0.0, m_bottom, 0.0}) - m_top;
    if (m_sphere_only) return d;
    d = std::fmin(d, length(p) - m_bottom);
    if (p.y > m_bottom_join && p.y < m_top_join) {
        const double h = std::sqrt(p.x * p.x + p.z * p.z) + m_horizontal;
        const double dy = p.y - m_vertical;
        d = std::fmin(d, std::sqrt(h * h + dy * dy) - m_connecting);
    }
    return d;
}

}  // namespace wardray::geometry
