// Pattern: POV-Ray 3.7's pattern functions, wave shaping and warps, evaluated at a point of pattern space.
#pragma once

#include "scene/scene.h"
#include "core/vec3.h"
#include "texture/surface_point.h"

namespace wardray::texture {

/// Maps a point of the enclosing space into the pattern's own space: the inverse of its transform, then the
/// classic turbulence displacement (POV-Ray's Warp_EPoint; marble and wood apply their turbulence themselves).
Vec3 warp_point(const scene::Pattern& pattern, const Vec3& p);

/// The raw pattern function at a point of pattern space (before frequency, phase and wave shaping); `surface` is
/// the intersection being shaded, if any (slope and aoi read it).
double raw_pattern_value(const scene::Pattern& pattern, const Vec3& p, int noise_generator,
                         const SurfacePoint* surface = nullptr);

/// POV-Ray's Evaluate_TPat: the raw value, then frequency and phase, then the wave type.
/// `noise_generator` is the scene's default, used when the pattern does not name its own.
double pattern_value(const scene::Pattern& pattern, const Vec3& p, int noise_generator,
                     const SurfacePoint* surface = nullptr);

/// `quilted`'s displacement in its unit cell (POV-Ray's quilted normal adds it, scaled, to the normal).
Vec3 quilted_offset(const scene::Pattern& pattern, const Vec3& p);
/// `quilted`'s value: the mean absolute component of quilted_offset.
double quilted_value(const scene::Pattern& pattern, const Vec3& p);

/// POV-Ray's `cycloidal`: sin(2π v) computed through the fractional part of v.
double cycloidal(double v);

/// The two entries of a sorted map around `value` and the blend fraction between them (POV-Ray's
/// Search_Blend_Map): `prev == cur` means no blending.
struct MapLookup {
    int prev = 0;
    int cur = 0;
    double fraction = 0.0;
};

/// Finds `value` among map entry values given by `value_of(i)` for i in [0, count).
template <typename ValueOf>
MapLookup search_map(double value, int count, ValueOf value_of) {
    MapLookup m;
    const int last = count - 1;
    if (value >= value_of(last)) {
        m.prev = m.cur = last;
    } else {
        while (value > value_of(m.cur)) m.prev = m.cur++;
    }
    if (value == value_of(m.cur)) m.prev = m.cur;
    if (m.prev != m.cur) m.fraction = (value - value_of(m.prev)) / (value_of(m.cur) - value_of(m.prev));
    return m;
}

}  // namespace wardray::texture
