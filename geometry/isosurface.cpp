// IsosurfaceShape: POV-Ray 3.7's isosurface root finder, container caps, normals by forward differences.
#include "geometry/isosurface.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace wardray::geometry {

namespace {

constexpr double k_epsilon = 1e-10;       // POV-Ray's EPSILON
constexpr double k_bound_huge = 2.0e10;   // POV-Ray's BOUND_HUGE
constexpr double k_depth_tolerance = 1e-6;  // POV-Ray's DEPTH_TOLERANCE

// A crossing before sorting: its t and, for container caps, the side (0..5 box faces, 6 the sphere).
struct Crossing {
    double t = 0.0;
    int side = -1;  ///< -1: a crossing of the function's surface
};

}  // namespace

/// The state of one ray's search: the ray, and the sign that turns the field into "negative beyond a crossing".
struct IsosurfaceShape::Trace {
    Vec3 origin;
    Vec3 direction;
    double length = 1.0;  ///< |direction|: the solver's slopes are per unit of object-space distance
    double sign = 1.0;    ///< POV-Ray's Inv3: flips after each crossing, so the next one is again a sign change
    double root = 0.0;    ///< the crossing found last
    double value(const IsosurfaceShape& s, double t) const { return sign * s.field(origin + t * direction); }
};

IsosurfaceShape::IsosurfaceShape(const scene::Isosurface& iso)
    : m_iso(std::make_shared<const scene::Isosurface>(iso)), m_gradient(std::make_shared<IsosurfaceGradient>()) {
    m_context.noise_generator = iso.noise_generator;
    m_gradient->carried.store(iso.max_gradient, std::memory_order_relaxed);
}

std::optional<IsosurfaceShape> IsosurfaceShape::create(const scene::Isosurface& iso) {
    if (!iso.function) return std::nullopt;
    if (iso.sphere_container) {
        if (!(iso.radius > 0.0) || !std::isfinite(iso.radius) || !is_finite(iso.center)) return std::nullopt;
    } else if (!is_finite(iso.corner1) || !is_finite(iso.corner2)) {
        return std::nullopt;
    }
    if (!(iso.accuracy > 0.0) || !std::isfinite(iso.accuracy) || !std::isfinite(iso.max_gradient) ||
        !std::isfinite(iso.threshold))
        return std::nullopt;
    return IsosurfaceShape(iso);
}

double IsosurfaceShape::field(const Vec3& p) const {
    const std::array<double, 3> args{p.x, p.y, p.z};
    return m_iso->function->evaluate(args, m_context) - m_iso->threshold;
}

std::optional<Bounds> IsosurfaceShape::bounds() const {
    if (m_iso->sphere_container) {
        const Vec3 r{m_iso->radius, m_iso->radius, m_iso->radius};
        return Bounds{m_iso->center - r, m_iso->center + r};
    }
    return Bounds{m_iso->corner1, m_iso->corner2};
}

bool IsosurfaceShape::inside(const Vec3& p) const {
    const scene::Isosurface& iso = *m_iso;
    if (iso.sphere_container) {
        if (dot(p - iso.center, p - iso.center) > iso.radius * iso.radius) return false;
    } else {
        for (int k = 0; k < 3; ++k)
            if (p[k] < iso.corner1[k] || p[k] > iso.corner2[k]) return false;
    }
    return field(p) < 0.0;
}

double IsosurfaceShape::implicit(const Vec3& p) const {
    const scene::Isosurface& iso = *m_iso;
    double container = 0.0;
    if (iso.sphere_container) {
        container = length(p - iso.center) - iso.radius;
    } else {
        container = -INFINITY;
        for (int k = 0; k < 3; ++k)
            container = std::max({container, iso.corner1[k] - p[k], p[k] - iso.corner2[k]});
    }
    return std::max(field(p), container);
}

bool IsosurfaceShape::container_interval(const LocalRay& ray, double& t1, double& t2, int& side1, int& side2) const {
    const scene::Isosurface& iso = *m_iso;
    if (iso.sphere_container) {
        // POV-Ray compat: the sphere is met along the unit direction, the depths scaled back.
        const double len = length(ray.direction);
        if (!(len > 0.0)) return false;
        const Vec3 d = ray.direction / len;
        const Vec3 oc = iso.center - ray.origin;
        const double oc2 = dot(oc, oc);
        const double closest = dot(oc, d);
        const double r2 = iso.radius * iso.radius;
        if (oc2 >= r2 && closest < k_epsilon) return false;
        const double half2 = r2 - oc2 + closest * closest;
        if (!(half2 > k_epsilon)) return false;
        const double half = std::sqrt(half2);
        t1 = (closest - half) / len;
        t2 = (closest + half) / len;
        side1 = side2 = 6;
        return true;
    }
    // POV-Ray's Box::Intersect: the slabs from t = 0 on, remembering the face of entry and exit.
    double tmin = 0.0, tmax = k_bound_huge;
    side1 = side2 = -1;
    for (int k = 0; k < 3; ++k) {
        const double o = ray.origin[k], d = ray.direction[k];
        if (std::fabs(d) <= k_epsilon) {
            if (o < iso.corner1[k] || o > iso.corner2[k]) return false;
            continue;
        }
        const bool negative = d < 0.0;
        const double t_far = ((negative ? iso.corner1[k] : iso.corner2[k]) - o) / d;
        const double t_near = ((negative ? iso.corner2[k] : iso.corner1[k]) - o) / d;
        if (t_far < tmin) return false;
        if (t_far <= tmax) {
            tmax = t_far;
            side2 = 2 * k + (negative ? 0 : 1);
        }
        if (t_near >= tmin) {
            if (t_near > tmax) return false;
            tmin = t_near;
            side1 = 2 * k + (negative ? 1 : 0);
        }
    }
    if (tmax < k_depth_tolerance) return false;
    t1 = tmin;
    t2 = tmax;
    return true;
}

Vec3 IsosurfaceShape::container_normal(const Vec3& p, int side) const {
    if (side == 6) return p - m_iso->center;
    Vec3 n;
    if (side >= 0) n[side / 2] = (side % 2 == 0) ? -1.0 : 1.0;
    return n;
}

Vec3 IsosurfaceShape::function_normal(const Vec3& p) const {
    // POV-Ray compat: forward differences with the step `accuracy`.
    const double a = m_iso->accuracy;
    const double f0 = field(p);
    Vec3 n{field(p + Vec3{a, 0.0, 0.0}) - f0, field(p + Vec3{0.0, a, 0.0}) - f0, field(p + Vec3{0.0, 0.0, a}) - f0};
    if (n.x == 0.0 && n.y == 0.0 && n.z == 0.0) n.x = 1.0;
    return n;
}

bool IsosurfaceShape::find_root_in(Trace& tr, double t1, double f1, double t2, double f2, double dt, double t21,
                                   double len, double& maxg) const {
    const scene::Isosurface& iso = *m_iso;
    const double slope = std::fabs((f2 - f1) * len);
    m_gradient->observe(slope);
    if (iso.evaluate && maxg < slope * iso.eval[1]) {
        maxg = slope * iso.eval[1] * iso.eval[1];
        dt = maxg * tr.length * t21;
    }
    if (t21 < iso.accuracy) {
        if (f2 < 0.0) {
            tr.root = t2;  // the crossing is at the far end of the last interval
            return true;
        }
        return false;
    }
    // The end values allow a root in between only if they could meet zero under the slope bound.
    if (f1 + f2 - dt >= 0.0) return false;
    t21 *= 0.5;
    dt *= 0.5;
    const double tm = t1 + t21;
    const double fm = tr.value(*this, tm);
    if (find_root_in(tr, t1, f1, tm, fm, dt, t21, len * 2.0, maxg)) return true;
    return find_root_in(tr, tm, fm, t2, f2, dt, t21, len * 2.0, maxg);
}

bool IsosurfaceShape::find_root(Trace& tr, double& tmin, double tmax, double& maxg) const {
    const scene::Isosurface& iso = *m_iso;
    double f1 = tr.value(*this, tmin);
    // POV-Ray compat: an open isosurface takes the sign it meets at the start as "outside".
    if (iso.open && f1 < 0.0) {
        tr.sign = -tr.sign;
        f1 = -f1;
    }
    const double f2 = tr.value(*this, tmax);
    const double t21 = tmax - tmin;
    const double old = maxg;
    if (iso.evaluate && old > iso.eval[0]) maxg = old * iso.eval[2];
    const double dt = maxg * tr.length * t21;
    if (!find_root_in(tr, tmin, f1, tmax, f2, dt, t21, 1.0 / (tr.length * t21), maxg)) return false;
    tmin = tr.root;
    return true;
}

SurfaceHits IsosurfaceShape::intersect_all(const LocalRay& ray, double t_min, double t_max) const {
    // POV-Ray compat: a ray that goes on past a crossing (a shadow ray walking through the surfaces it crosses) is a
    // new ray from there in POV-Ray, and from inside the container a closed isosurface gives the container's far
    // side where the field is negative there, which the ray from its first origin does not. A continuation that
    // starts inside the container is traced from where it starts.
    double d1 = 0.0, d2 = 0.0;
    int side1 = -1, side2 = -1;
    if (t_min > m_iso->accuracy && container_interval(ray, d1, d2, side1, side2) && d1 < t_min && t_min < d2) {
        const SurfaceHits from_start = crossings({ray.origin + t_min * ray.direction, ray.direction}, 0.0, t_max - t_min);
        SurfaceHits hits;
        for (SurfaceHit h : from_start) {
            h.t += t_min;
            hits.push(h);
        }
        return hits;
    }
    return crossings(ray, t_min, t_max);
}

SurfaceHits IsosurfaceShape::crossings(const LocalRay& ray, double t_min, double t_max) const {
    SurfaceHits hits;
    double d1 = 0.0, d2 = 0.0;
    int side1 = -1, side2 = -1;
    if (!container_interval(ray, d1, d2, side1, side2)) return hits;
    const scene::Isosurface& iso = *m_iso;
    const double acc = iso.accuracy;
    // POV-Ray compat: with `evaluate`, each ray starts from the largest bound the rays before it ended with (POV-Ray
    // 3.7 stores it back into the object's max_gradient after every ray, shadow rays too), so the render order
    // matters, as it does in POV-Ray; without `evaluate` every ray starts from max_gradient.
    double maxg = iso.evaluate ? m_gradient->carried.load(std::memory_order_relaxed) : iso.max_gradient;
    struct CarryBack {
        const scene::Isosurface& iso;
        IsosurfaceGradient& gradient;
        const double& maxg;
        ~CarryBack() {
            if (iso.evaluate) IsosurfaceGradient::raise(gradient.carried, maxg);
        }
    } carry_back{iso, *m_gradient, maxg};
    Trace tr{ray.origin, ray.direction, length(ray.direction)};
    if (!(tr.length > 0.0) || !std::isfinite(tr.length)) return hits;
    d1 = std::max(d1, 0.0);
    std::array<Crossing, 12> found;
    int count = 0;
    int traced = 0;
    const auto at = [&](double t) { return ray.origin + t * ray.direction; };
    if (!iso.open) {
        // A closed isosurface is capped by the container where the field is negative.
        if (d1 > acc) {
            if (field(at(d1)) < 0.0) {
                found[count++] = {d1, side1};
                ++traced;
                tr.sign = -tr.sign;
            }
        } else {
            if (field(at(d1)) < maxg * acc * 4.0) {
                d1 = acc * 5.0;
                if (field(at(d1)) < 0.0) tr.sign = -1.0;
            }
            if (field(at(d2)) < 0.0) found[count++] = {d2, side2};
        }
    }
    double tmax = std::min(d2, k_bound_huge);
    double tmin = std::min(tmax, d1);
    if (tmax - tmin < acc) return hits;
    if (d1 < acc && tr.sign == 1.0) {
        // The ray starts on the surface: step inside it and look for the next crossing.
        if (std::fabs(field(at(tmin))) < maxg * acc * 4.0) {
            tmin = acc * 5.0;
            if (field(at(tmin)) < 0.0) tr.sign = -1.0;
        }
    }
    for (; traced < iso.max_trace; ++traced) {
        if (!find_root(tr, tmin, tmax, maxg)) break;
        found[count++] = {tmin, -1};
        tmin += acc * 5.0;
        if (tmax - tmin < acc) break;
        tr.sign = -tr.sign;
    }
    std::sort(found.begin(), found.begin() + count, [](const Crossing& a, const Crossing& b) { return a.t < b.t; });
    for (int i = 0; i < count; ++i) {
        const double t = found[i].t;
        if (!(t > t_min && t < t_max)) continue;
        const Vec3 p = at(t);
        const Vec3 n = found[i].side >= 0 ? container_normal(p, found[i].side) : function_normal(p);
        hits.push({t, n, dot(n, ray.direction) < 0.0});
    }
    return hits;
}

std::optional<Diagnostic> IsosurfaceShape::gradient_warning() const {
    const scene::Isosurface& iso = *m_iso;
    const double found = gradient_found(), set = iso.max_gradient;
    if (iso.evaluate || !(found > k_epsilon) || !(set > k_epsilon)) return std::nullopt;
    // POV-Ray compat: its thresholds for "too low" and "too high", and its wording.
    const double diff = set - found, ratio = std::fabs(set / found);
    char text[256];
    if ((ratio <= 0.9 && diff <= -0.5) || ((ratio <= 0.95 || diff <= -0.1) && set < 10.0)) {
        std::snprintf(text, sizeof text,
                      "the maximum gradient found was %0.3f, but max_gradient of the isosurface was set to %0.3f; "
                      "the isosurface may contain holes: adjust max_gradient to get a proper rendering",
                      static_cast<float>(found), static_cast<float>(set));
    } else if (diff >= 10.0 || (ratio >= 1.1 && diff >= 0.5)) {
        std::snprintf(text, sizeof text,
                      "the maximum gradient found was %0.3f, but max_gradient of the isosurface was set to %0.3f; "
                      "adjust max_gradient to get a faster rendering",
                      static_cast<float>(found), static_cast<float>(set));
    } else {
        return std::nullopt;
    }
    Diagnostic d;
    d.severity = Severity::Warning;
    d.loc = iso.function_loc;
    d.message = text;
    return d;
}

}  // namespace wardray::geometry
