// Shape interface pieces shared by the analytic primitives: object-space rays, surface crossings and bounds.
#pragma once

#include <array>
#include <cstddef>

#include "parser/vec3.h"

namespace wardray::geometry {

/// A ray in a shape's object space; t is the same parameter as on the world ray it came from.
struct LocalRay {
    Vec3 origin;
    Vec3 direction;
};

/// One place where a ray crosses a shape's surface.
struct SurfaceHit {
    double t = 0.0;
    Vec3 normal;           ///< object-space normal pointing out of the shape, not necessarily unit length
    bool entering = true;  ///< the ray passes from outside to inside here
};

/// The surface crossings of a ray with one shape inside (t_min, t_max), sorted by t.
/// Fixed capacity: every primitive so far is convex (at most two crossings); CSG merges these as intervals.
class SurfaceHits {
public:
    static constexpr std::size_t capacity = 4;

    /// Appends a crossing; callers add them in increasing t. Crossings beyond the capacity are dropped.
    void push(const SurfaceHit& hit) {
        if (m_count < capacity) m_hits[m_count++] = hit;
    }
    /// Number of crossings held.
    std::size_t size() const { return m_count; }
    /// True when the ray crosses nothing.
    bool empty() const { return m_count == 0; }
    /// The i-th crossing in order of t.
    const SurfaceHit& operator[](std::size_t i) const { return m_hits[i]; }
    /// Range access over the crossings.
    const SurfaceHit* begin() const { return m_hits.data(); }
    const SurfaceHit* end() const { return m_hits.data() + m_count; }

private:
    std::array<SurfaceHit, capacity> m_hits{};
    std::size_t m_count = 0;
};

/// An axis-aligned box [lower, upper].
struct Bounds {
    Vec3 lower;
    Vec3 upper;

    /// Largest absolute coordinate of either corner: the magnitude that rounding errors scale with.
    double magnitude() const { return std::fmax(max_abs_component(lower), max_abs_component(upper)); }
    /// The smallest box holding both.
    Bounds merged(const Bounds& o) const { return {min(lower, o.lower), max(upper, o.upper)}; }
};

}  // namespace wardray::geometry
