// Surface patterns: slope (the surface's steepness, with altitude) and aoi (the angle of incidence), POV-Ray 3.7's
// patterns that read the intersection rather than only the point.
#pragma once

#include "scene/texture.h"
#include "core/vec3.h"
#include "texture/surface_point.h"

namespace wardray::texture {

/// `slope`: asin(n · slope) mapped to [0, 1], with its range, blended with the altitude along its vector.
double slope_pattern(const scene::Pattern& pat, const Vec3& p, int generator, const SurfacePoint* surface);
/// `aoi`: the angle between the normal and the ray, over π.
double aoi_pattern(const scene::Pattern& pat, const Vec3& p, int generator, const SurfacePoint* surface);

}  // namespace wardray::texture
