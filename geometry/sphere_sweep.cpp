// SphereSweepShape: the segments' polynomials, POV-Ray 3.7's parts along a line (end spheres, closing discs and
// tube crossings) and its way of keeping the crossings of their union.
#include "geometry/sphere_sweep.h"

#include <algorithm>
#include <cmath>

#include "core/constants.h"
#include "geometry/polynomial.h"

namespace wardray::geometry {

namespace {

// POV-Ray compat: its EPSILON, the ZERO_TOLERANCE below which a linear tube is met through the sphere at the root,
// and MAX_DISTANCE, beyond which end spheres and discs are not met (sphsweep.cpp).
constexpr double kEpsilon = kPovEpsilon;
constexpr double kZeroTolerance = 1e-4;
constexpr double kMaxDistance = 1e7;

// A polynomial in u of degree up to 10, lowest coefficient first.
struct Poly {
    std::array<double, 11> c{};
    int degree = 0;
};

Poly operator+(const Poly& a, const Poly& b) {
    Poly r;
    r.degree = std::max(a.degree, b.degree);
    for (int i = 0; i <= r.degree; ++i) r.c[i] = a.c[i] + b.c[i];
    return r;
}

Poly operator*(double s, Poly a) {
    for (double& v : a.c) v *= s;
    return a;
}

Poly operator*(const Poly& a, const Poly& b) {
    Poly r;
    r.degree = a.degree + b.degree;
    for (int i = 0; i <= a.degree; ++i)
        for (int j = 0; j <= b.degree; ++j) r.c[i + j] += a.c[i] * b.c[j];
    return r;
}

Poly derivative(const Poly& a) {
    Poly r;
    r.degree = std::max(0, a.degree - 1);
    for (int i = 1; i <= a.degree; ++i) r.c[i - 1] = i * a.c[i];
    return r;
}

double eval(const Poly& a, double u) {
    double v = a.c[a.degree];
    for (int i = a.degree - 1; i >= 0; --i) v = v * u + a.c[i];
    return v;
}

// The segment's centre and radius, and their u derivatives, at u.
Vec3 centre_at(const SphereSweepShape::Segment& g, double u) {
    Vec3 v = g.c[g.degree];
    for (int i = g.degree - 1; i >= 0; --i) v = v * u + g.c[i];
    return v;
}
double radius_at(const SphereSweepShape::Segment& g, double u) {
    double v = g.r[g.degree];
    for (int i = g.degree - 1; i >= 0; --i) v = v * u + g.r[i];
    return v;
}
Vec3 centre_slope_at(const SphereSweepShape::Segment& g, double u) {
    Vec3 v;
    for (int i = g.degree; i >= 1; --i) v = v * u + i * g.c[i];
    return v;
}
double radius_slope_at(const SphereSweepShape::Segment& g, double u) {
    double v = 0.0;
    for (int i = g.degree; i >= 1; --i) v = v * u + i * g.r[i];
    return v;
}

// x - cn(u) for one axis of a point x in the segment's normalised coordinates.
Poly offset_poly(const SphereSweepShape::Segment& g, double x, int axis) {
    Poly p;
    p.degree = g.degree;
    for (int k = 0; k <= g.degree; ++k) p.c[k] = -g.cn[k][axis];
    p.c[0] += x;
    return p;
}

// |x - cn(u)|² - rn(u)² for a point x in normalised coordinates: negative where x is inside the sphere at u.
Poly sphere_poly(const SphereSweepShape::Segment& g, const Vec3& x, Poly* along = nullptr, const Vec3& dir = {}) {
    Poly rn;
    rn.degree = g.degree;
    for (int k = 0; k <= g.degree; ++k) rn.c[k] = g.rn[k];
    Poly sum = -1.0 * (rn * rn);
    Poly a;
    a.degree = g.degree;
    for (int axis = 0; axis < 3; ++axis) {
        const Poly w = offset_poly(g, x[axis], axis);
        sum = sum + w * w;
        if (along) a = a + dir[axis] * w;
    }
    if (along) *along = a;
    return sum;
}

// The line o + s u (u unit), with s0 the distance from the ray's origin to o along u, and POV-Ray's tolerances
// for the sweep's size: a length, a squared length, MAX_DISTANCE and ZERO_TOLERANCE.
struct Line {
    Vec3 o;
    Vec3 u;
    double s0 = 0.0;
    double eps = kEpsilon;
    double eps2 = kEpsilon;
    double far = kMaxDistance;
    double zero = kZeroTolerance;
};

// A crossing of one part: the line parameter and the part's outward normal (unit).
struct Event {
    double s = 0.0;
    Vec3 normal;
};

// POV-Ray's Intersect_Sphere: both crossings of the sphere, none when it lies wholly behind the ray's origin or the
// line passes within sqrt(EPSILON) of its rim. `limited`: crossings beyond MAX_DISTANCE are dropped. The normal
// is divided by the radius, so a negative radius turns it inward, as in POV-Ray.
void sphere_events(const Line& line, const Vec3& c, double r, bool limited, std::vector<Event>& out) {
    const Vec3 v = c - line.o;
    const double tc = dot(v, line.u);
    const Vec3 perp = v - tc * line.u;
    const double hc2 = r * r - dot(perp, perp);
    const double tc_from_origin = line.s0 + tc;
    // The origin is outside when its distance to the centre is at least r: then tc² ≥ hc².
    if (tc_from_origin * tc_from_origin >= hc2 && tc_from_origin < line.eps) return;
    if (!(hc2 > line.eps2)) return;
    const double hc = std::sqrt(hc2);
    for (const double s : {tc - hc, tc + hc}) {
        if (limited && !(std::fabs(line.s0 + s) < line.far)) continue;
        out.push_back({s, normalize(((s - tc) * line.u - perp) / r)});
    }
}

// The crossings of one segment's tube part: its closing discs and its envelope.
void segment_events(const SphereSweepShape::Segment& g, const Line& line, bool spline, std::vector<Event>& out) {
    double b0 = 0.0, b1 = 0.0;
    if (!slab_interval(g.box.lower, g.box.upper, line.o, line.u, b0, b1)) return;
    // The line seen from its point nearest the segment, so the polynomials take the segment's scale.
    const double s_ref = dot(g.ref - line.o, line.u);
    const Vec3 o_seg = line.o + s_ref * line.u;
    // The discs where the envelope meets the end spheres: the planes (p - c)·c' + r r' = 0 within those spheres.
    for (const double end : {0.0, 1.0}) {
        const Vec3 c = centre_at(g, end), dc = centre_slope_at(g, end);
        const double r = radius_at(g, end), dr = radius_slope_at(g, end);
        const double d1 = dot(line.u, dc);
        if (!(std::fabs(d1) > line.eps)) continue;
        const double s = -(dot(o_seg - c, dc) + r * dr) / d1;
        if (!(std::fabs(line.s0 + s_ref + s) < line.far)) continue;
        const Vec3 q = o_seg + s * line.u - c;
        if (dot(q, q) < r * r) out.push_back({s_ref + s, normalize(end == 0.0 ? -dc : dc)});
    }
    // On the line q + s u (normalised), the sphere at u is s² + 2 A(u) s + B(u) = 0, and the envelope also needs
    // its u derivative 2 A'(u) s + B'(u) = 0; eliminating s: B'² - 4 A A' B' + 4 A'² B = 0.
    const double scale = g.scale;
    const Vec3 q = (o_seg - g.ref) / scale;
    Poly a;
    const Poly b = sphere_poly(g, q, &a, line.u);
    const Poly da = derivative(a), db = derivative(b);
    const Poly res = db * db + -4.0 * (a * da * db) + 4.0 * (da * da * b);
    int degree = res.degree;
    double largest = 0.0;
    for (int k = 0; k <= degree; ++k) largest = std::fmax(largest, std::fabs(res.c[k]));
    if (!(largest > 0.0)) return;
    while (degree > 0 && std::fabs(res.c[degree]) <= 1e-14 * largest) --degree;
    double roots[10];
    const int n = polynomial_roots(res.c.data(), degree, 0.0, 1.0, roots);
    for (int k = 0; k < n; ++k) {
        const double x = roots[k];
        const double slope = eval(da, x);
        // POV-Ray compat: a linear tube's crossing is the line parameter of the envelope, unless the line is nearly
        // square to the axis; a spline tube's (FS#81) gives both crossings of the sphere at the root.
        if (!spline && std::fabs(2.0 * slope * scale) > line.zero) {
            const double s_n = -eval(db, x) / (2.0 * slope);
            const double s = s_ref + s_n * scale;
            if (!(std::fabs(line.s0 + s) < line.far)) continue;
            Vec3 w;
            for (int axis = 0; axis < 3; ++axis) w[axis] = eval(offset_poly(g, q[axis], axis), x);
            out.push_back({s, normalize(w + s_n * line.u)});
            continue;
        }
        sphere_events(line, centre_at(g, x), radius_at(g, x), false, out);
    }
}

}  // namespace

std::optional<SphereSweepShape> SphereSweepShape::create(const scene::SphereSweep& sweep) {
    using Spline = scene::SphereSweep::Spline;
    const auto& P = sweep.centers;
    const auto& R = sweep.radii;
    const int n = static_cast<int>(P.size());
    const bool linear = sweep.spline == Spline::Linear;
    if (R.size() != P.size() || n < (linear ? 2 : 4) || !std::isfinite(sweep.tolerance)) return std::nullopt;
    for (int i = 0; i < n; ++i)
        if (!is_finite(P[i]) || !std::isfinite(R[i])) return std::nullopt;
    SphereSweepShape shape;
    shape.m_tolerance = sweep.tolerance;
    shape.m_spline = !linear;
    auto segments = std::make_shared<std::vector<Segment>>();
    // Power-basis weights of the four control spheres: row k gives the coefficient of u^k (uniform cubic B-spline
    // and Catmull-Rom spline, the spline through the inner two with slopes (P2 - P0) / 2 and (P3 - P1) / 2).
    static constexpr double kBSpline[4][4] = {{1.0 / 6, 4.0 / 6, 1.0 / 6, 0.0},
                                               {-3.0 / 6, 0.0, 3.0 / 6, 0.0},
                                               {3.0 / 6, -6.0 / 6, 3.0 / 6, 0.0},
                                               {-1.0 / 6, 3.0 / 6, -3.0 / 6, 1.0 / 6}};
    static constexpr double kCatmullRom[4][4] = {
        {0.0, 1.0, 0.0, 0.0}, {-0.5, 0.0, 0.5, 0.0}, {1.0, -2.5, 2.0, -0.5}, {-0.5, 1.5, -1.5, 0.5}};
    const int count = linear ? n - 1 : n - 3;
    for (int i = 0; i < count; ++i) {
        Segment g;
        if (linear) {
            g.degree = 1;
            g.c = {P[i], P[i + 1] - P[i], Vec3{}, Vec3{}};
            g.r = {R[i], R[i + 1] - R[i], 0.0, 0.0};
        } else {
            g.degree = 3;
            const auto& m = sweep.spline == Spline::BSpline ? kBSpline : kCatmullRom;
            for (int k = 0; k < 4; ++k)
                for (int j = 0; j < 4; ++j) {
                    g.c[k] += m[k][j] * P[i + j];
                    g.r[k] += m[k][j] * R[i + j];
                }
        }
        // The Bézier control spheres of the segment bound every sphere of it (centres in their hull, radii below
        // the largest).
        std::array<Vec3, 4> bc{g.c[0], g.c[0] + g.c[1], g.c[0] + g.c[1], g.c[0] + g.c[1]};
        std::array<double, 4> br{g.r[0], g.r[0] + g.r[1], 0.0, 0.0};
        int points = 2;
        if (g.degree == 3) {
            bc = {g.c[0], g.c[0] + g.c[1] / 3.0, g.c[0] + (2.0 * g.c[1] + g.c[2]) / 3.0,
                  g.c[0] + g.c[1] + g.c[2] + g.c[3]};
            br = {g.r[0], g.r[0] + g.r[1] / 3.0, g.r[0] + (2.0 * g.r[1] + g.r[2]) / 3.0,
                  g.r[0] + g.r[1] + g.r[2] + g.r[3]};
            points = 4;
        }
        double r_max = 0.0;
        Vec3 lo = bc[0], hi = bc[0];
        for (int k = 0; k < points; ++k) {
            lo = min(lo, bc[k]);
            hi = max(hi, bc[k]);
            r_max = std::fmax(r_max, std::fabs(br[k]));
        }
        g.box = {lo - Vec3{r_max, r_max, r_max}, hi + Vec3{r_max, r_max, r_max}};
        g.ref = 0.5 * (g.box.lower + g.box.upper);
        g.scale = 0.5 * max_abs_component(g.box.upper - g.box.lower);
        if (!(g.scale > 0.0)) g.scale = 1.0;  // a point of radius 0: nothing to meet
        for (int k = 0; k <= g.degree; ++k) {
            g.cn[k] = (k == 0 ? g.c[0] - g.ref : g.c[k]) / g.scale;
            g.rn[k] = g.r[k] / g.scale;
        }
        if (!is_finite(g.box.lower) || !is_finite(g.box.upper)) return std::nullopt;
        shape.m_bounds = i == 0 ? g.box : shape.m_bounds.merged(g.box);
        segments->push_back(g);
    }
    shape.m_segments = std::move(segments);
    return shape;
}

SurfaceHits SphereSweepShape::intersect_all(const LocalRay& ray, double t_min, double t_max,
                                            double t_min_depth) const {
    SurfaceHits hits;
    const auto centred = centre_line(ray);
    if (!centred) return hits;
    // POV-Ray compat: its tolerances as they are for sweeps of unit size and larger, scaled down for smaller ones
    // (where POV-Ray's absolute values would cut holes), MAX_DISTANCE scaled up for larger ones.
    const double size = 0.5 * max_abs_component(m_bounds.upper - m_bounds.lower);
    const double small = std::fmin(1.0, size), large = std::fmax(1.0, size);
    const Line line{centred->o,         centred->u,         centred->s0, kEpsilon * small, kEpsilon * small * small,
                    kMaxDistance * large, kZeroTolerance * small};
    double b0 = 0.0, b1 = 0.0;
    if (!slab_interval(m_bounds.lower, m_bounds.upper, line.o, line.u, b0, b1)) return hits;
    thread_local std::vector<Event> events;
    events.clear();
    // The parts along the whole line: the sphere at each end of each segment, then each segment's tube.
    const auto& segs = *m_segments;
    for (const Segment& g : segs) sphere_events(line, g.c[0], g.r[0], true, events);
    sphere_events(line, centre_at(segs.back(), 1.0), radius_at(segs.back(), 1.0), true, events);
    for (const Segment& g : segs) segment_events(g, line, m_spline, events);
    if (events.empty()) return hits;
    std::sort(events.begin(), events.end(), [](const Event& a, const Event& b) { return a.s < b.s; });
    // POV-Ray compat: its tolerance is a distance along the parent-space ray (t_min_depth over
    // k_min_isect_depth is one over its direction's length); without a depth, along the object-space one.
    // MIN_ISECT_DEPTH itself is not applied: the roots are exact to rounding, and at small scales it would take
    // away every shadow the sweep casts nearby.
    const double per_distance = t_min_depth > 0.0 ? t_min_depth / k_min_isect_depth : 1.0 / centred->length;
    const double t_low = std::fmax(t_min, m_tolerance * per_distance);
    auto keep = [&](const Event& e) {
        const double t = (line.s0 + e.s) / centred->length;
        if (t > t_low && t < t_max) hits.push({t, e.normal, dot(e.normal, line.u) < 0.0});
    };
    // POV-Ray compat (Find_Valid_Points): the first and the last crossing stay; between them, with a count of
    // the parts the line is in that starts at 1, an entering crossing stays where the count was 0 and a leaving
    // one where it was 1.
    keep(events.front());
    int inside_parts = 1;
    for (std::size_t i = 1; i + 1 < events.size(); ++i) {
        const bool entering = dot(events[i].normal, line.u) < 0.0;
        if (entering ? inside_parts == 0 : inside_parts == 1) keep(events[i]);
        inside_parts += entering ? 1 : -1;
    }
    if (events.size() > 1) keep(events.back());
    return hits;
}

bool SphereSweepShape::inside(const Vec3& p) const {
    for (const Segment& g : *m_segments) {
        if (p.x < g.box.lower.x || p.y < g.box.lower.y || p.z < g.box.lower.z || p.x > g.box.upper.x ||
            p.y > g.box.upper.y || p.z > g.box.upper.z)
            continue;
        // POV-Ray compat: inside where |p - c(u)|² - r(u)² has a root for u in [0, 1].
        const Poly f = sphere_poly(g, (p - g.ref) / g.scale);
        if ((eval(f, 0.0) > 0.0) != (eval(f, 1.0) > 0.0)) return true;
        double roots[6];
        if (polynomial_roots(f.c.data(), f.degree, 0.0, 1.0, roots) > 0) return true;
    }
    return false;
}

double SphereSweepShape::implicit(const Vec3& p) const {
    double best = INFINITY;
    for (const Segment& g : *m_segments)
        best = std::fmin(best, minimum_on_unit_interval([&](double u) {
                             return length(p - centre_at(g, u)) - std::fabs(radius_at(g, u));
                         }));
    return best;
}

}  // namespace wardray::geometry
