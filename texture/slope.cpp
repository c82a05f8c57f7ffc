// Surface patterns: slope and aoi as POV-Ray 3.7's slope_pattern and aoi_pattern compute them.
#include "texture/slope.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/constants.h"

namespace wardray::texture {

namespace {

// POV-Ray compat: a value of exactly 1 stays just below 1 instead of wrapping to the bottom of the map; others
// wrap into [0, 1) (a negative one as 1 + fmod).
double wrap_unit(double v) {
    if (v == 1.0) return v - kPovEpsilon;
    return v < 0.0 ? 1.0 + std::fmod(v, 1.0) : std::fmod(v, 1.0);
}

}  // namespace

double slope_pattern(const scene::Pattern& pat, const Vec3& p, int, const SurfacePoint* surface) {
    if (surface == nullptr) return 0.0;
    const scene::SlopeParams& s = pat.params->slope;
    // The cosine of the angle between the normal and the slope vector (or the direction to the point_at point).
    const double cos_n = s.point_at ? dot(surface->normal, normalize(s.slope_vector - surface->point))
                                    : dot(surface->normal, s.slope_vector);
    // asin maps it to [-1, 1] by angle, then to [0, 1].
    double slope = std::asin(std::clamp(cos_n, -1.0, 1.0)) / std::numbers::pi * 2.0;
    slope = (slope + 1.0) * 0.5;
    if (s.slope_range != 0.0) slope = (slope - s.slope_lo) / s.slope_range;
    if (s.altitude_len == 0.0) return wrap_unit(slope);
    // The altitude: the pattern-space point along the altitude vector, in its range.
    double altitude = dot(p, s.altitude_vector);
    if (s.altitude_range != 0.0) altitude = (altitude - s.altitude_lo) / s.altitude_range;
    const double value = s.slope_len * slope + s.altitude_len * altitude;
    // POV-Ray compat: a value in [1, 1 + EPSILON) is taken just below 1; other values wrap.
    if (value - 1.0 < kPovEpsilon && value >= 1.0) return value - kPovEpsilon;
    return value < 0.0 ? 1.0 + std::fmod(value, 1.0) : std::fmod(value, 1.0);
}

double aoi_pattern(const scene::Pattern&, const Vec3&, int, const SurfacePoint* surface) {
    if (surface == nullptr) return 0.0;
    const double cos_angle = dot(normalize(surface->normal), normalize(surface->direction));
    return std::acos(std::clamp(cos_angle, -1.0, 1.0)) / std::numbers::pi;
}

}  // namespace wardray::texture
