// density_file: a df3 voxel grid as a pattern, as POV-Ray 3.7's density_pattern reads it.
#pragma once

#include "scene/texture.h"
#include "core/vec3.h"

namespace wardray::texture {

/// `density_file df3 "file" interpolate N`: the voxel value at p inside the unit cube, 0 outside; nearest voxel
/// (interpolate 0) or trilinear (1, wrapping at the far faces as POV-Ray does).
double density_file_pattern(const scene::Pattern& pat, const Vec3& p, int generator);

}  // namespace wardray::texture
