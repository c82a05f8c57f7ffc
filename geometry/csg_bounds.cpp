// IntersectionBounds: interval narrowing of a box by half-spaces and axis-aligned quadrics.
#include "geometry/csg_bounds.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace wardray::geometry {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// Coordinates beyond this count as unbounded (POV-Ray's BOUND_HUGE / 2 is 1e10).
constexpr double kUnbounded = 1e9;

struct Range {
    double lo = -kInf;
    double hi = kInf;
};

// The least of a * x² + b * x over x in r (-inf when it has none).
double least(double a, double b, const Range& r) {
    if (a == 0.0 && b == 0.0) return 0.0;
    auto f = [&](double x) { return a * x * x + b * x; };
    if (a < 0.0) return std::isinf(r.lo) || std::isinf(r.hi) ? -kInf : std::min(f(r.lo), f(r.hi));
    if (a == 0.0) {
        const double x = b > 0.0 ? r.lo : r.hi;
        return std::isinf(x) ? -kInf : f(x);
    }
    return f(std::clamp(-b / (2.0 * a), r.lo, r.hi));
}

// Narrows r to the x with a * x² + b * x <= s (kept whole where that set is not one interval).
void narrow_to(double a, double b, double s, Range& r) {
    if (std::isinf(s) || std::isnan(s)) return;
    if (a > 0.0) {
        const double disc = b * b + 4.0 * a * s;
        if (disc < 0.0) {
            r.lo = kInf;  // empty
            r.hi = -kInf;
            return;
        }
        const double root = std::sqrt(disc);
        r.lo = std::max(r.lo, (-b - root) / (2.0 * a));
        r.hi = std::min(r.hi, (-b + root) / (2.0 * a));
    } else if (a == 0.0 && b > 0.0) {
        r.hi = std::min(r.hi, s / b);
    } else if (a == 0.0 && b < 0.0) {
        r.lo = std::max(r.lo, s / b);
    }
}

}  // namespace

std::optional<Bounds> IntersectionBounds::narrow(const std::optional<Bounds>& box) const {
    Range r[3];
    if (box) {
        for (int k = 0; k < 3; ++k) {
            if (std::fabs(box->lower[k]) < kUnbounded) r[k].lo = box->lower[k];
            if (std::fabs(box->upper[k]) < kUnbounded) r[k].hi = box->upper[k];
        }
    }
    // Each constraint bounds one axis by the least the other axes' terms can be over their ranges; a few passes
    // carry what one axis learns to the others.
    for (int pass = 0; pass < 4; ++pass) {
        for (const HalfSpace& h : m_planes) {
            for (int k = 0; k < 3; ++k) {
                if (h.normal[k] == 0.0) continue;
                double rest = -h.distance;
                for (int m = 0; m < 3; ++m)
                    if (m != k) rest += least(0.0, h.normal[m], r[m]);
                narrow_to(0.0, h.normal[k], -rest, r[k]);
            }
        }
        for (const AxisQuadric& q : m_quadrics) {
            for (int k = 0; k < 3; ++k) {
                double rest = q.constant;
                for (int m = 0; m < 3; ++m)
                    if (m != k) rest += least(q.squares[m], q.linear[m], r[m]);
                narrow_to(q.squares[k], q.linear[k], -rest, r[k]);
            }
        }
    }
    Bounds out;
    double magnitude = 1.0;
    for (int k = 0; k < 3; ++k) {
        if (!(std::fabs(r[k].lo) < kUnbounded) || !(std::fabs(r[k].hi) < kUnbounded)) return std::nullopt;
        magnitude = std::max({magnitude, std::fabs(r[k].lo), std::fabs(r[k].hi)});
    }
    // Room for the rounding of the narrowing and for inside tests that count points within 1e-10 of a plane.
    const double pad = 1e-7 * magnitude;
    for (int k = 0; k < 3; ++k) {
        if (r[k].lo > r[k].hi) return std::nullopt;  // nothing inside: left to the children's own bounds
        out.lower[k] = r[k].lo - pad;
        out.upper[k] = r[k].hi + pad;
    }
    return out;
}

}  // namespace wardray::geometry
