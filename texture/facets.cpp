// The facets normal pattern as POV-Ray 3.7 computes it: the normal (or, with coords, the point) scaled by 1/size
// picks the nearest of one random point per unit cube among the 81 cubes within a "3D knight move".
#include "texture/facets.h"

#include <cmath>

#include "core/constants.h"
#include "texture/noise.h"

namespace wardray::texture {

namespace {

// POV-Ray's PickInCube: the random point of the unit cube holding `v` (floor, not POV-Ray's mirrored FLOOR).
Vec3 pick_in_cube(const Vec3& v) {
    const double fx = std::floor(v.x - kPovEpsilon), fy = std::floor(v.y - kPovEpsilon),
                 fz = std::floor(v.z - kPovEpsilon);
    const std::size_t seed =
        static_cast<std::size_t>(hash3d(static_cast<int>(fx), static_cast<int>(fy), static_cast<int>(fz)));
    return {fx + pattern_rand(seed), fy + pattern_rand(seed + 1), fz + pattern_rand(seed + 2)};
}

}  // namespace

Vec3 facets_normal(const scene::Pattern& pat, const Vec3& p, const Vec3& n) {
    const Vec3 normal = normalize(n);
    const double scale = pat.params->facets_size < 1e-6 ? 1e6 : 1.0 / pat.params->facets_size;
    const Vec3 tv = (pat.params->facets_coords != 0.0 ? p : normal) * scale;
    const double metric = pat.params->crackle_metric;
    // POV-Ray compat: metric 1 sums the signed differences, as POV-Ray does.
    auto distance = [&](const Vec3& d) {
        if (metric == 2.0) return dot(d, d);
        if (metric == 1.0) return d.x + d.y + d.z;
        return std::pow(std::fabs(d.x), metric) + std::pow(std::fabs(d.y), metric) + std::pow(std::fabs(d.z), metric);
    };
    // The nearest point; the first of equals wins, in POV-Ray's x, y, z order.
    bool first = true;
    double nearest_distance = 0.0;
    Vec3 nearest;
    for (int ax = -2; ax <= 2; ++ax) {
        for (int ay = -2; ay <= 2; ++ay) {
            for (int az = -2; az <= 2; ++az) {
                if ((std::abs(ax) == 2) + (std::abs(ay) == 2) + (std::abs(az) == 2) > 1) continue;
                const Vec3 point = pick_in_cube(tv + Vec3{static_cast<double>(ax), static_cast<double>(ay),
                                                          static_cast<double>(az)});
                const double d = distance(point - tv);
                if (first || d < nearest_distance) {
                    nearest_distance = d;
                    nearest = point;
                    first = false;
                }
            }
        }
    }
    if (pat.params->facets_coords == 0.0) return nearest;
    // With coords, the noise's gradient at the point, less its part along the normal, tilts the normal.
    Vec3 pert = dnoise(nearest);
    pert -= normal * dot(pert, normal);
    return normal + pert * pat.params->facets_coords;
}

double facets_pattern(const scene::Pattern&, const Vec3&, int) { return 0.0; }

}  // namespace wardray::texture
