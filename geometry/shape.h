// Shape interface pieces shared by the analytic primitives: object-space rays, surface crossings and bounds.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/vec3.h"

namespace wardray::scene {
struct Object;
}

namespace wardray::geometry {

/// A ray in a shape's object space; t is the same parameter as on the world ray it came from.
struct LocalRay {
    Vec3 origin;
    Vec3 direction;
};

/// A ray's line seen from its point nearest the object-space origin, so polynomial coefficients take the shape's
/// scale rather than the ray origin's: unit direction `u`, that point `o` (o·u = 0), the distance `s0` from the
/// ray's origin to it along u, and the direction's `length`; a distance s from `o` is t = (s0 + s) / length.
struct CentredLine {
    Vec3 u;
    Vec3 o;
    double s0 = 0.0;
    double length = 0.0;
};

/// Nothing for a zero, infinite or NaN direction.
inline std::optional<CentredLine> centre_line(const LocalRay& ray) {
    const double len = wardray::length(ray.direction);
    if (!(len > 0.0) || !std::isfinite(len)) return std::nullopt;
    const Vec3 u = ray.direction / len;
    const double s0 = -dot(ray.origin, u);
    return CentredLine{u, ray.origin + s0 * u, s0, len};
}

/// One place where a ray crosses a shape's surface.
struct SurfaceHit {
    double t = 0.0;
    Vec3 normal;           ///< object-space normal out of the shape (a triangle: POV-Ray's side), not necessarily unit
    bool entering = true;  ///< the ray passes from outside to inside here
    const scene::Object* leaf = nullptr;  ///< the primitive whose surface this is (set by ShapeInstance)
};

static_assert(std::is_trivially_copyable_v<SurfaceHit> && std::is_trivially_destructible_v<SurfaceHit>);

/// The surface crossings of a ray with one shape inside (t_min, t_max), sorted by t.
/// Small-vector storage: a few crossings inline (convex primitives, tori), more on the heap (CSG, meshes). The
/// inline slots are left unwritten until used: every shape test makes one of these, most with no crossing.
class SurfaceHits {
public:
    static constexpr std::size_t inline_capacity = 6;

    SurfaceHits() {}
    SurfaceHits(const SurfaceHits& o) { *this = o; }
    SurfaceHits& operator=(const SurfaceHits& o) {
        if (this == &o) return *this;
        m_count = o.m_count;
        m_heap = o.m_heap;
        if (m_heap.empty()) std::copy(o.m_inline.items, o.m_inline.items + m_count, m_inline.items);
        return *this;
    }

    /// Appends a crossing; callers add them in increasing t or call sort_by_t() afterwards.
    void push(const SurfaceHit& hit) {
        if (m_heap.empty() && m_count < inline_capacity) {
            m_inline.items[m_count++] = hit;
            return;
        }
        if (m_heap.empty()) m_heap.assign(m_inline.items, m_inline.items + m_count);
        m_heap.push_back(hit);
        ++m_count;
    }
    /// Orders the crossings by t (stable, so equal t keep their insertion order).
    void sort_by_t() {
        SurfaceHit* h = data();
        if (m_count > inline_capacity) {
            std::stable_sort(h, h + m_count, [](const SurfaceHit& a, const SurfaceHit& b) { return a.t < b.t; });
            return;
        }
        // A few crossings: insertion sort, as stable as std::stable_sort and without its temporary buffer.
        for (std::size_t i = 1; i < m_count; ++i) {
            const SurfaceHit x = h[i];
            std::size_t j = i;
            for (; j > 0 && x.t < h[j - 1].t; --j) h[j] = h[j - 1];
            h[j] = x;
        }
    }
    /// Number of crossings held.
    std::size_t size() const { return m_count; }
    /// True when the ray crosses nothing.
    bool empty() const { return m_count == 0; }
    /// The i-th crossing in order of t.
    const SurfaceHit& operator[](std::size_t i) const { return data()[i]; }
    /// Range access over the crossings.
    const SurfaceHit* begin() const { return data(); }
    const SurfaceHit* end() const { return data() + m_count; }

private:
    SurfaceHit* data() { return m_heap.empty() ? m_inline.items : m_heap.data(); }
    const SurfaceHit* data() const { return m_heap.empty() ? m_inline.items : m_heap.data(); }

    /// The inline crossings, left uninitialised beyond m_count: every shape returns a SurfaceHits per ray and
    /// child, and filling all six slots each time cost more than the intersection of a plane.
    union InlineHits {
        InlineHits() {}
        SurfaceHit items[inline_capacity];
    };
    InlineHits m_inline;
    std::vector<SurfaceHit> m_heap;
    std::size_t m_count = 0;
};

/// std::fmax and std::fmin with the same result for every pair (a NaN loses, a tie gives x, so fmax(-0, +0) is -0 as
/// glibc's), inline: without -ffast-math the compiler calls the library for them, which cost a few per cent of a
/// trace (several calls per ray in the box and BVH tests).
inline double max_of(double x, double y) { return (y > x || x != x) ? y : x; }
inline double min_of(double x, double y) { return (y < x || x != x) ? y : x; }

/// The parameters s0 ≤ s1 where the line o + s·u enters and leaves the box [lo, hi]; false when it misses.
inline bool slab_interval(const Vec3& lo, const Vec3& hi, const Vec3& o, const Vec3& u, double& s0, double& s1) {
    s0 = -INFINITY;
    s1 = INFINITY;
    for (int k = 0; k < 3; ++k) {
        if (u[k] == 0.0) {
            if (o[k] < lo[k] || o[k] > hi[k]) return false;
            continue;
        }
        double a = (lo[k] - o[k]) / u[k], b = (hi[k] - o[k]) / u[k];
        if (a > b) std::swap(a, b);
        s0 = max_of(s0, a);
        s1 = min_of(s1, b);
    }
    return s0 <= s1;
}

/// Sorted crossings without repeats: a ray through the point where two pieces of an outline meet finds it on both,
/// and the second (same direction, same t to rounding) is dropped.
inline SurfaceHits without_repeated_crossings(const SurfaceHits& hits) {
    SurfaceHits unique;
    for (const SurfaceHit& h : hits) {
        if (!unique.empty()) {
            const SurfaceHit& last = unique[unique.size() - 1];
            if (last.entering == h.entering && h.t - last.t <= 1e-12 * (std::fabs(h.t) + std::fabs(last.t))) continue;
        }
        unique.push(h);
    }
    return unique;
}

/// The least value of `f` on [0, 1] (a squared distance along a curve piece): 33 samples, then a golden-section
/// search around the best of them.
template <typename F>
double minimum_on_unit_interval(const F& f) {
    double w = 0.0, d = f(0.0);
    for (int k = 1; k <= 32; ++k)
        if (const double dk = f(k / 32.0); dk < d) {
            d = dk;
            w = k / 32.0;
        }
    double a = std::fmax(0.0, w - 1.0 / 32.0), b = std::fmin(1.0, w + 1.0 / 32.0);
    const double g = 0.5 * (std::sqrt(5.0) - 1.0);
    for (int iter = 0; iter < 80; ++iter) {
        const double c1 = b - g * (b - a), c2 = a + g * (b - a);
        if (f(c1) < f(c2)) b = c2;
        else a = c1;
    }
    return std::fmin(d, f(0.5 * (a + b)));
}

/// An axis-aligned box [lower, upper].
struct Bounds {
    Vec3 lower;
    Vec3 upper;

    /// Largest absolute coordinate of either corner: the magnitude that rounding errors scale with.
    double magnitude() const { return std::fmax(max_abs_component(lower), max_abs_component(upper)); }
    /// The smallest box holding both.
    Bounds merged(const Bounds& o) const { return {min(lower, o.lower), max(upper, o.upper)}; }
    /// The common part of both (may be empty: see empty()).
    Bounds intersected(const Bounds& o) const { return {max(lower, o.lower), min(upper, o.upper)}; }
    /// True when some lower coordinate exceeds the upper one.
    bool empty() const { return lower.x > upper.x || lower.y > upper.y || lower.z > upper.z; }
};

/// Bounds that may be unbounded (nothing): the merge of anything with the unbounded is unbounded.
inline std::optional<Bounds> merge_bounds(const std::optional<Bounds>& a, const std::optional<Bounds>& b) {
    if (!a || !b) return std::nullopt;
    return a->merged(*b);
}

/// The common part of two possibly unbounded boxes.
inline std::optional<Bounds> intersect_bounds(const std::optional<Bounds>& a, const std::optional<Bounds>& b) {
    if (!a) return b;
    if (!b) return a;
    return a->intersected(*b);
}

}  // namespace wardray::geometry
