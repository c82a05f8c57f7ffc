// BlobShape: elements from components, their support along a ray, and the piecewise quartic swept in order.
#include "geometry/blob.h"

#include <algorithm>
#include <cmath>

#include "geometry/polynomial.h"

namespace wardray::geometry {

namespace {

// POV-Ray's EPSILON: interval ends closer than this (in the normalised ray parameter) are one boundary.
constexpr double k_epsilon = 1e-10;

// Narrows [s0, s1] to where lo <= o + s d <= hi (one coordinate); false when nothing is left.
bool clip_to_slab(double o, double d, double lo, double hi, double& s0, double& s1) {
    if (d == 0.0) return o >= lo && o <= hi;
    double a = (lo - o) / d, b = (hi - o) / d;
    if (a > b) std::swap(a, b);
    s0 = std::fmax(s0, a);
    s1 = std::fmin(s1, b);
    return s0 < s1;
}

// The roots of a s² + 2 b s + c = 0 (a > 0) when they are distinct, stably.
bool quadratic_interval(double a, double b, double c, double& s0, double& s1) {
    const double disc = b * b - a * c;
    if (!(a > 0.0) || !(disc > 0.0)) return false;
    const double q = -(b + std::copysign(std::sqrt(disc), b));
    s0 = q / a;
    s1 = q != 0.0 ? c / q : -s0;
    if (s0 > s1) std::swap(s0, s1);
    return true;
}

// The orthonormal frame that takes z to the unit axis and the origin to base, as a transform.
Transform axis_frame(const Vec3& base, const Vec3& axis) {
    const Vec3 helper = std::fabs(axis.x) < 0.9 ? Vec3{1.0, 0.0, 0.0} : Vec3{0.0, 1.0, 0.0};
    const Vec3 e1 = normalize(cross(helper, axis));
    const Vec3 e2 = cross(axis, e1);
    const std::array<double, 12> m = {e1.x, e1.y, e1.z, e2.x, e2.y, e2.z, axis.x, axis.y, axis.z, base.x, base.y, base.z};
    return *Transform::from_pov_matrix(m);
}

// The hull of a box's eight corners mapped by xf.
Bounds mapped_box(const Vec3& lo, const Vec3& hi, const Transform& xf) {
    Bounds out{xf.point(lo), xf.point(lo)};
    for (int i = 1; i < 8; ++i) {
        const Vec3 p = xf.point({(i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z});
        out.lower = min(out.lower, p);
        out.upper = max(out.upper, p);
    }
    return out;
}

}  // namespace

std::optional<BlobShape> BlobShape::create(const scene::Blob& blob) {
    BlobShape shape;
    shape.m_threshold = blob.threshold;
    if (!std::isfinite(blob.threshold)) return std::nullopt;
    std::optional<Bounds> positive, all;
    shape.m_components = blob.components.size();
    for (std::size_t index = 0; index < blob.components.size(); ++index) {
        const scene::Blob::Component& comp = blob.components[index];
        const double r2 = comp.radius * comp.radius, s = comp.strength;
        if (!std::isfinite(r2) || !std::isfinite(s) || !is_finite(comp.a) || !is_finite(comp.b)) return std::nullopt;
        if (!comp.transform.is_invertible()) return std::nullopt;
        // A zero radius or strength adds nothing (POV-Ray would divide by zero).
        if (r2 < k_epsilon || s == 0.0) continue;
        Element e;
        e.component = index;
        e.rad2 = r2;
        e.c[0] = s / (r2 * r2);
        e.c[1] = -2.0 * s / r2;
        e.c[2] = s;
        const double r = std::sqrt(r2);
        std::vector<std::pair<Element, Bounds>> made;
        if (!comp.cylinder) {
            e.to_blob = Transform::translation(comp.a).then(comp.transform);
            made.push_back({e, mapped_box({-r, -r, -r}, {r, r, r}, e.to_blob)});
        } else {
            e.len = length(comp.b - comp.a);
            e.to_blob = axis_frame(comp.a, (comp.b - comp.a) / e.len).then(comp.transform);
            e.kind = Kind::Cylinder;
            made.push_back({e, mapped_box({-r, -r, 0.0}, {r, r, e.len}, e.to_blob)});
            e.kind = Kind::BaseCap;
            made.push_back({e, mapped_box({-r, -r, -r}, {r, r, 0.0}, e.to_blob)});
            e.kind = Kind::ApexCap;
            made.push_back({e, mapped_box({-r, -r, e.len}, {r, r, e.len + r}, e.to_blob)});
        }
        for (auto& [element, box] : made) {
            shape.m_elements.push_back(element);
            all = all ? all->merged(box) : box;
            if (s > 0.0) positive = positive ? positive->merged(box) : box;
        }
    }
    if (shape.m_elements.empty()) return std::nullopt;
    // POV-Ray compat: only the elements of positive strength bound the blob (when there are any).
    shape.m_bounds = positive ? positive : all;
    if (!is_finite(shape.m_bounds->lower) || !is_finite(shape.m_bounds->upper)) return std::nullopt;
    return shape;
}

std::optional<Bounds> BlobShape::region_bounds() const {
    if (!(m_threshold > 0.0)) return std::nullopt;
    return m_bounds;
}

Vec3 BlobShape::centred(const Element& e, const Vec3& local) {
    switch (e.kind) {
        case Kind::Cylinder: return {local.x, local.y, 0.0};
        case Kind::ApexCap: return {local.x, local.y, local.z - e.len};
        default: return local;
    }
}

double BlobShape::element_density(const Element& e, const Vec3& p) {
    const Vec3 local = e.to_blob.inverse_point(p);
    if (e.kind == Kind::Cylinder && (local.z < 0.0 || local.z > e.len)) return 0.0;
    if (e.kind == Kind::BaseCap && local.z > 0.0) return 0.0;
    if (e.kind == Kind::ApexCap && local.z < e.len) return 0.0;
    const Vec3 v = centred(e, local);
    const double d2 = dot(v, v);
    // POV-Ray compat: a sphere's support is open, the other elements' closed.
    if (e.kind == Kind::Sphere ? !(d2 < e.rad2) : !(d2 <= e.rad2)) return 0.0;
    return d2 * (d2 * e.c[0] + e.c[1]) + e.c[2];
}

double BlobShape::density(const Vec3& p) const {
    double sum = 0.0;
    for (const Element& e : m_elements) sum += element_density(e, p);
    return sum;
}

void BlobShape::component_densities(const Vec3& p, std::vector<double>& out) const {
    out.assign(m_components, 0.0);
    for (const Element& e : m_elements) out[e.component] += std::fabs(element_density(e, p));
}

Vec3 BlobShape::normal(const Vec3& p) const {
    Vec3 n;
    for (const Element& e : m_elements) {
        const Vec3 local = e.to_blob.inverse_point(p);
        if (e.kind == Kind::Cylinder && (local.z < 0.0 || local.z > e.len)) continue;
        if (e.kind == Kind::BaseCap && local.z > 0.0) continue;
        if (e.kind == Kind::ApexCap && local.z < e.len) continue;
        const Vec3 v = centred(e, local);
        const double d2 = dot(v, v);
        if (d2 > e.rad2) continue;
        // Minus half the gradient of c0 d⁴ + c1 d², carried to blob space by the inverse transpose.
        n += (-2.0 * e.c[0] * d2 - e.c[1]) * e.to_blob.normal(v);
    }
    return dot(n, n) > 0.0 ? n : Vec3{1.0, 0.0, 0.0};
}

bool BlobShape::support_interval(const Element& e, const Vec3& o, const Vec3& d, double& s0, double& s1) {
    if (e.kind == Kind::Cylinder) {
        const double a = d.x * d.x + d.y * d.y, b = o.x * d.x + o.y * d.y, c = o.x * o.x + o.y * o.y - e.rad2;
        if (a > 0.0) {
            if (!quadratic_interval(a, b, c, s0, s1)) return false;
        } else {
            if (c > 0.0) return false;
            s0 = -INFINITY;
            s1 = INFINITY;
        }
        return clip_to_slab(o.z, d.z, 0.0, e.len, s0, s1);
    }
    const Vec3 v = e.kind == Kind::ApexCap ? Vec3{o.x, o.y, o.z - e.len} : o;
    if (!quadratic_interval(dot(d, d), dot(v, d), dot(v, v) - e.rad2, s0, s1)) return false;
    if (e.kind == Kind::BaseCap) return clip_to_slab(v.z, d.z, -INFINITY, 0.0, s0, s1);
    if (e.kind == Kind::ApexCap) return clip_to_slab(v.z, d.z, 0.0, INFINITY, s0, s1);
    return true;
}

SurfaceHits BlobShape::intersect_all(const LocalRay& ray, double t_min, double t_max) const {
    SurfaceHits hits;
    const auto line = centre_line(ray);
    if (!line) return hits;
    const auto& [u, o, s_origin, len] = *line;
    const double s_lo = t_min * len - s_origin, s_hi = t_max * len - s_origin;
    // Each element met: its support [a, b] along the line (distance s from o) and the line in its own space.
    struct Active {
        double a, b;
        Vec3 o, d;
        const Element* e;
    };
    std::vector<Active> met;
    met.reserve(m_elements.size());
    double start = INFINITY, end = -INFINITY;
    for (const Element& e : m_elements) {
        const Vec3 eo = e.to_blob.inverse_point(o), ed = e.to_blob.inverse_vector(u);
        double a = 0.0, b = 0.0;
        if (!support_interval(e, eo, ed, a, b)) continue;
        a = std::fmax(a, s_lo);
        b = std::fmin(b, s_hi);
        if (!(a < b)) continue;
        met.push_back({a, b, eo, ed, &e});
        start = std::fmin(start, a);
        end = std::fmax(end, b);
    }
    if (met.empty() || !(end > start) || !std::isfinite(end - start)) return hits;
    // Like POV-Ray, the parameter w in [0, 1] runs from the first support's start to the last one's end, so the
    // quartics keep the blob's scale whatever the ray origin.
    const double span = end - start;
    struct Event {
        double w;
        int delta;
        double c[5];
    };
    std::vector<Event> events;
    events.reserve(2 * met.size());
    for (const Active& m : met) {
        Vec3 p = m.o + start * m.d, d = span * m.d;
        p = centred(*m.e, p);
        if (m.e->kind == Kind::Cylinder) d.z = 0.0;
        const double t0 = dot(p, p), t1 = dot(p, d), t2 = dot(d, d);
        const double* c = m.e->c;
        // c0 r⁴ + c1 r² + c2 with r² = t0 + 2 t1 w + t2 w², in ascending powers of w.
        Event in{(m.a - start) / span, +1,
                 {t0 * (c[0] * t0 + c[1]) + c[2], 2.0 * t1 * (2.0 * c[0] * t0 + c[1]),
                  2.0 * c[0] * (2.0 * t1 * t1 + t0 * t2) + c[1] * t2, 4.0 * c[0] * t1 * t2, c[0] * t2 * t2}};
        Event out = in;
        out.w = (m.b - start) / span;
        out.delta = -1;
        events.push_back(in);
        events.push_back(out);
    }
    std::sort(events.begin(), events.end(), [](const Event& x, const Event& y) { return x.w < y.w; });
    double coeffs[5] = {-m_threshold, 0.0, 0.0, 0.0, 0.0};
    int active = 0;
    SurfaceHits found;
    for (std::size_t i = 0; i + 1 < events.size(); ++i) {
        const Event& ev = events[i];
        for (int k = 0; k < 5; ++k) coeffs[k] += ev.delta * ev.c[k];
        active += ev.delta;
        if (active == 0) {
            // Nothing acts here: the sum is exactly the threshold's again (no drift from adding and removing).
            coeffs[0] = -m_threshold;
            for (int k = 1; k < 5; ++k) coeffs[k] = 0.0;
            continue;
        }
        const double w0 = ev.w, w1 = events[i + 1].w;
        if (w1 - w0 < k_epsilon) continue;
        double roots[4];
        const int n = polynomial_roots(coeffs, 4, w0, w1, roots);
        for (int r = 0; r < n; ++r) {
            const double t = (s_origin + start + roots[r] * span) / len;
            if (!(t > t_min && t < t_max)) continue;
            const Vec3 normal_at = normal(ray.origin + t * ray.direction);
            found.push({t, normal_at, dot(normal_at, ray.direction) < 0.0});
        }
    }
    found.sort_by_t();
    return without_repeated_crossings(found);
}

}  // namespace wardray::geometry
