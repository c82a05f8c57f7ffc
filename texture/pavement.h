// Pavement: POV-Ray 3.7's `pavement` pattern, the plane y = 0 paved with polyiamonds, polyominoes or polyhexes.
#pragma once

#include "core/vec3.h"
#include "scene/texture.h"

namespace wardray::texture {

/// `pavement`: 0 inside a paver, rising to 1 on its boundary, with its corners shaped by form, interior and exterior.
double pavement_pattern(const scene::Pattern& pat, const Vec3& p, int generator);

}  // namespace wardray::texture
