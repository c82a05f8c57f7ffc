// SurfacePoint: what POV-Ray's surface-dependent patterns (slope, aoi) read of the intersection being shaded.
#pragma once

#include "core/vec3.h"

namespace wardray::texture {

/// POV-Ray's Intersection and Ray as its pattern functions see them; patterns evaluated away from a surface
/// (the sky, media, functions at parse time) get none and slope and aoi are 0 there, as in POV-Ray.
struct SurfacePoint {
    Vec3 point;      ///< the hit point, world space (IPoint)
    Vec3 normal;     ///< unit, world space, facing the ray, tilted by the normals shaded so far (PNormal)
    Vec3 direction;  ///< the ray's direction
    /// POV-Ray's Q_QUICKC quality flag (+Q0 to +Q5): pigments with a quick_color show it instead.
    bool quick_colors = false;
};

}  // namespace wardray::texture
