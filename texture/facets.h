// The facets normal pattern: POV-Ray 3.7's facets (normal.cpp there), a normal replaced by the nearest of random
// points scattered one per unit cube.
#pragma once

#include "scene/texture.h"
#include "core/vec3.h"

namespace wardray::texture {

/// `facets [coords C] [size S] [metric M]`: the pattern-space normal `n` after facets at the pattern-space point
/// `p` (not unit; the caller's unwarp makes it so).
Vec3 facets_normal(const scene::Pattern& pat, const Vec3& p, const Vec3& n);

/// POV-Ray has no value for facets (its Evaluate_TPat refuses it): the parser takes it only in normals, where
/// facets_normal replaces the normal instead.
double facets_pattern(const scene::Pattern& pat, const Vec3& p, int generator);

}  // namespace wardray::texture
