// The tiling pattern: POV-Ray 3.7's 27 tilings of the x-z plane (`tiling N`), each tile's value rising from its
// middle towards its edges, in the band of values its kind of tile owns.
#pragma once

#include "core/vec3.h"
#include "scene/texture.h"

namespace wardray::texture {

/// `tiling N`: the value at the pattern-space point `p` (only x and z count).
double tiling_pattern(const scene::Pattern& pat, const Vec3& p, int generator);

/// The value of POV-Ray's tiling `type` (1..27; the parser refuses others, taken here as 1) at (x, z).
double tiling_value(int type, double x, double z);

}  // namespace wardray::texture
