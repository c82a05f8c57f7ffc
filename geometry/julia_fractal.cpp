// JuliaFractalShape: the orbit iterations of each algebra and function, POV-Ray 3.7's stepping and bisection along
// the ray, and its orbit-derivative normals.
#include "geometry/julia_fractal.h"

#include <cmath>
#include <vector>

#include "geometry/julia_complex.h"

namespace wardray::geometry {

namespace {

using Algebra = scene::JuliaFractal::Algebra;
using Function = scene::JuliaFractal::Function;

// POV-Ray's Fractal_Tolerance (fractal.cpp): the bisection's end and the start's offset.
constexpr double k_tolerance = 1e-7;
// POV-Ray's EPSILON, as its sphere test uses it for the bounding sphere.
constexpr double k_epsilon = 1e-10;

// The hypercomplex product (commutative: x y z w with i j = k, i² = j² = -1, k² = 1).
Quad hmul(const Quad& a, const Quad& b) {
    return {a.x * b.x - a.y * b.y - a.z * b.z + a.w * b.w, a.y * b.x + a.x * b.y - a.w * b.z - a.z * b.w,
            a.z * b.x - a.w * b.y + a.x * b.z - a.y * b.w, a.w * b.x + a.z * b.y + a.y * b.z + a.x * b.w};
}

Quad hsqr(const Quad& q) {
    return {q.x * q.x - q.y * q.y - q.z * q.z + q.w * q.w, 2.0 * (q.x * q.y - q.z * q.w),
            2.0 * (q.z * q.x - q.w * q.y), 2.0 * (q.w * q.x + q.z * q.y)};
}

// The hypercomplex reciprocal; `previous` when the number has none (POV-Ray leaves the result as it was).
Quad hreciprocal(const Quad& q, const Quad& previous) {
    const double det = ((q.x - q.w) * (q.x - q.w) + (q.y + q.z) * (q.y + q.z)) *
                       ((q.x + q.w) * (q.x + q.w) + (q.y - q.z) * (q.y - q.z));
    if (det == 0.0) return previous;
    const double mod = q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w;
    const double k = q.x * q.w - q.y * q.z;
    return {(q.x * mod - 2.0 * q.w * k) / det, (-q.y * mod - 2.0 * q.z * k) / det,
            (-q.z * mod - 2.0 * q.y * k) / det, (q.w * mod - 2.0 * q.x * k) / det};
}

// A complex function applied to a hypercomplex number through its two complex (duplex) parts.
Quad hfunc(const Quad& q, Function f, const Complex& exponent) {
    const Complex a = julia_complex_function(f, {q.x - q.w, q.y + q.z}, exponent);
    const Complex b = julia_complex_function(f, {q.x + q.w, q.y - q.z}, exponent);
    return {0.5 * (a.re + b.re), 0.5 * (a.im + b.im), 0.5 * (a.im - b.im), 0.5 * (b.re - a.re)};
}

double norm2(const Quad& q) { return q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w; }

}  // namespace

JuliaFractalShape::JuliaFractalShape(const scene::JuliaFractal& fractal) : m_f(fractal) {
    if (m_f.algebra == Algebra::Quaternion) {
        // POV-Ray compat (Compute_BBox): the radius 1 + |c| (plus the tolerance), at most 2.
        const double c2 = m_f.c[0] * m_f.c[0] + m_f.c[1] * m_f.c[1] + m_f.c[2] * m_f.c[2] + m_f.c[3] * m_f.c[3];
        m_radius = std::fmin(2.0, 1.0 + std::sqrt(c2) + k_tolerance);
        m_exit = m_radius * m_radius + k_tolerance;
    } else {
        m_radius = 4.0;
        m_exit = 16.0;
    }
}

std::optional<JuliaFractalShape> JuliaFractalShape::create(const scene::JuliaFractal& f) {
    for (int i = 0; i < 4; ++i)
        if (!std::isfinite(f.c[i]) || !std::isfinite(f.slice[i])) return std::nullopt;
    if (!std::isfinite(f.step) || !(f.step > 0.0) || !std::isfinite(f.slice_distance) || f.slice[3] == 0.0 ||
        f.max_iteration < 1 || !std::isfinite(f.exponent_re) || !std::isfinite(f.exponent_im))
        return std::nullopt;
    return JuliaFractalShape(f);
}

Quad JuliaFractalShape::apply(const Quad& q) const {
    Quad r;
    if (m_f.algebra == Algebra::Quaternion) {
        const double d = q.y * q.y + q.z * q.z + q.w * q.w;
        const double x2 = q.x * q.x;
        if (m_f.function == Function::Cube) {
            const double k = 3.0 * x2 - d;
            r = {q.x * (x2 - 3.0 * d), q.y * k, q.z * k, q.w * k};
        } else {
            r = {x2 - d, 2.0 * q.x * q.y, 2.0 * q.x * q.z, 2.0 * q.x * q.w};
        }
    } else {
        switch (m_f.function) {
            // POV-Ray compat: its hypercomplex `cube` squares, as `sqr` does.
            case Function::Sqr:
            case Function::Cube: r = hsqr(q); break;
            case Function::Reciprocal: r = hreciprocal(q, Quad{}); break;
            default: r = hfunc(q, m_f.function, {m_f.exponent_re, m_f.exponent_im}); break;
        }
    }
    return {r.x + m_f.c[0], r.y + m_f.c[1], r.z + m_f.c[2], r.w + m_f.c[3]};
}

bool JuliaFractalShape::iterate(const Vec3& p, Quad* orbit, double* step, const Vec3& u) const {
    // POV-Ray compat (Iteration_HCompl_Func): the inside test of the function fractals starts from (x, y, y).
    const double z = (step == nullptr && m_f.algebra == Algebra::Hypercomplex && m_f.function != Function::Sqr &&
                      m_f.function != Function::Cube && m_f.function != Function::Reciprocal)
                         ? p.y
                         : p.z;
    // The fourth coordinate from the slice hyperplane n·(x, y, z, w) = d.
    const double w = (m_f.slice_distance - m_f.slice[0] * p.x - m_f.slice[1] * p.y - m_f.slice[2] * z) / m_f.slice[3];
    orbit[0] = {p.x, p.y, z, w};
    for (int i = 1; i <= m_f.max_iteration; ++i) {
        // POV-Ray compat: the last iterate is not tested.
        if (norm2(orbit[i - 1]) > m_exit) {
            if (step) *step = escape_step(orbit, i, u);
            return false;
        }
        orbit[i] = apply(orbit[i - 1]);
    }
    if (step) *step = m_f.step;
    return true;
}

double JuliaFractalShape::escape_step(const Quad* orbit, int i, const Vec3& u) const {
    const double norm = norm2(orbit[i - 1]);
    if (m_f.algebra == Algebra::Quaternion) {
        // The distance estimate |z| log|z|² / |z'| (up to POV-Ray's constant 1 / p^i), z' the product of the orbit.
        const double power = m_f.function == Function::Cube ? 3.0 : 2.0;
        Quad d = orbit[0];
        double scale = 1.0 / power;
        for (int j = 1; j < i; ++j) {
            const Quad& q = orbit[j];
            d = {d.x * q.x - d.y * q.y - d.z * q.z - d.w * q.w, d.x * q.y + d.y * q.x + d.w * q.z - d.z * q.w,
                 d.x * q.z + d.z * q.x + d.y * q.w - d.w * q.y, d.x * q.w + d.w * q.x + d.z * q.y - d.y * q.z};
            scale /= power;
        }
        return scale * std::sqrt(norm / norm2(d)) * std::log(norm);
    }
    // Hypercomplex: the value over twice its slope towards the surface, when that lies within 1 to 30 steps.
    const Vec3 g = orbit_normal(orbit, i - 1);
    double slope = dot(g, u);
    if (slope < -1e-8) {
        slope *= -2.0;
        if (norm > m_f.step * slope && norm < 30.0 * m_f.step * slope) return norm / slope;
    }
    return m_f.step;
}

bool JuliaFractalShape::inside(const Vec3& p) const {
    std::vector<Quad> orbit(static_cast<std::size_t>(m_f.max_iteration) + 1);
    return iterate(p, orbit.data());
}

Vec3 JuliaFractalShape::orbit_normal(const Quad* orbit, int n) const {
    const Quad& last = orbit[n];
    if (m_f.algebra == Algebra::Quaternion) {
        // The gradient of |z_n|² / 2 in x, y, z: the rows of the orbit's Jacobian (w held fixed) dotted with z_n.
        double rows[3][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}};
        for (int i = 1; i <= n; ++i) {
            const Quad& q = orbit[i - 1];
            for (auto& r : rows) {
                if (m_f.function == Function::Cube) {
                    const double d = q.y * q.y + q.z * q.z + q.w * q.w;
                    const double x2 = q.x * q.x;
                    const double a = 2.0 * (r[1] * q.y + r[2] * q.z + r[3] * q.w);
                    const double b = 6.0 * q.x * r[0] - a;
                    const double k = 3.0 * x2 - d;
                    r[0] = (r[0] * (x2 - d) - q.x * a) * 3.0;
                    r[1] = r[1] * k + q.y * b;
                    r[2] = r[2] * k + q.z * b;
                    r[3] = r[3] * k + q.w * b;
                } else {
                    const double r0 = r[0] * q.x - r[1] * q.y - r[2] * q.z - r[3] * q.w;
                    r[1] = r[0] * q.y + q.x * r[1];
                    r[2] = r[0] * q.z + q.x * r[2];
                    r[3] = r[0] * q.w + q.x * r[3];
                    r[0] = r0;
                }
            }
        }
        Vec3 g;
        for (int k = 0; k < 3; ++k)
            g[k] = rows[k][0] * last.x + rows[k][1] * last.y + rows[k][2] * last.z + rows[k][3] * last.w;
        return g;
    }
    // Hypercomplex numbers commute: the derivative of the orbit is one product along it, up to a constant.
    Quad d = orbit[0];
    double scale = 1.0;
    for (int i = 1; i < n; ++i) {
        switch (m_f.function) {
            case Function::Sqr:
                d = hmul(orbit[i], d);
                scale *= 2.0;
                break;
            case Function::Cube: d = hmul(orbit[i], d); break;
            case Function::Reciprocal: {
                const Quad s = hsqr(hreciprocal(orbit[i], Quad{}));
                d = hmul(d, {-s.x, -s.y, -s.z, -s.w});
                break;
            }
            // POV-Ray compat (Normal_Calc_HCompl_Func): the function itself stands in for its derivative.
            default: d = hmul(hfunc(orbit[i], m_f.function, {m_f.exponent_re, m_f.exponent_im}), d); break;
        }
    }
    if (m_f.function == Function::Sqr) scale *= 2.0;
    const Quad m{last.x * scale, last.y * scale, last.z * scale, last.w * scale};
    return {d.x * m.x + d.y * m.y + d.z * m.z + d.w * m.w, -d.y * m.x + d.x * m.y - d.w * m.z + d.z * m.w,
            -d.z * m.x - d.w * m.y + d.x * m.z + d.y * m.w};
}

Vec3 JuliaFractalShape::normal_at(const Vec3& p) const {
    std::vector<Quad> orbit(static_cast<std::size_t>(m_f.max_iteration) + 1);
    iterate(p, orbit.data());
    return orbit_normal(orbit.data(), m_f.max_iteration);
}

SurfaceHits JuliaFractalShape::intersect_all(const LocalRay& ray, double t_min, double t_max,
                                             double t_min_depth) const {
    SurfaceHits hits;
    const double len = length(ray.direction);
    if (!(len > 0.0) || !std::isfinite(len)) return hits;
    const Vec3 u = ray.direction / len;
    // POV-Ray compat: a ray asked about beyond MIN_ISECT_DEPTH is a new ray from there (as POV-Ray starts shadow
    // rays again at each transparent surface); the march, its bound and its depth floor start at its origin.
    const double t_start = t_min > t_min_depth ? t_min : 0.0;
    const Vec3 origin = t_start > 0.0 ? ray.origin + t_start * ray.direction : ray.origin;
    const double t_floor = std::fmax(t_min, t_start + t_min_depth);
    // Depths are distances along u from the origin; the ray parameter is t_start + depth / len.
    const double depth_limit = (t_max - t_start) * len;
    // The bounding sphere, as POV-Ray's Sphere::Intersect tests it.
    const double oc2 = dot(origin, origin);
    const double closest = -dot(origin, u);
    const double r2 = m_radius * m_radius;
    if (oc2 >= r2 && closest < k_epsilon) return hits;
    const double half2 = r2 - oc2 + closest * closest;
    if (!(half2 > k_epsilon)) return hits;
    double depth = closest - std::sqrt(half2);
    const double depth_max = std::fmin(closest + std::sqrt(half2), depth_limit);
    if (depth_max < k_tolerance) return hits;
    depth = std::fmax(depth, k_tolerance);

    std::vector<Quad> orbit(static_cast<std::size_t>(m_f.max_iteration) + 1);
    Vec3 next_point = origin + depth * u;
    double dist = m_f.step, dist_next = m_f.step;
    bool current = iterate(next_point, orbit.data(), &dist, u);
    // A ray starting inside steps off its start first.
    if (current) {
        next_point = next_point + 2.0 * k_tolerance * u;
        depth += 2.0 * k_tolerance;
        if (depth > depth_max) return hits;
        current = iterate(next_point, orbit.data(), &dist, u);
    }
    while (depth < depth_max) {
        // March by the distance estimate (at least the precision's step) until the state changes, keeping the last
        // point before the change.
        Vec3 point;
        bool next = current;
        for (;;) {
            dist = std::fmax(dist, m_f.step);
            depth += dist;
            if (depth > depth_max) return hits;
            point = next_point;
            next_point = next_point + dist * u;
            next = iterate(next_point, orbit.data(), &dist_next, u);
            if (next != current) {
                depth -= dist;
                break;
            }
            dist = dist_next;
        }
        // Bisect down to the tolerance, keeping `point` on the side of the state before the change.
        bool last = current;
        while (dist > k_tolerance) {
            dist *= 0.5;
            const Vec3 mid = point + dist * u;
            last = iterate(mid, orbit.data());
            if (last == current) {
                point = mid;
                depth += dist;
                if (depth > depth_max) return hits;
            }
        }
        // The normal comes from the orbit of the point just inside.
        if (!current) {
            point = point + dist * u;
            depth += dist;
            iterate(point, orbit.data());
        } else if (last != current) {
            iterate(point, orbit.data());
        }
        const double t = t_start + depth / len;
        const Vec3 normal = orbit_normal(orbit.data(), m_f.max_iteration);
        if (t > t_floor && t < t_max && length(normal) > 0.0) hits.push({t, normal, !current});
        if (m_first_only) return hits;
        // POV-Ray compat: the march goes on from the point past the change, while the depth stays at the crossing.
        dist = dist_next;
        current = next;
    }
    return hits;
}

}  // namespace wardray::geometry
