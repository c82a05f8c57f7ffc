// object: a pattern that is 1 inside an object and 0 outside, as POV-Ray 3.7's object_pattern tests it.
#pragma once

#include "scene/texture.h"
#include "core/vec3.h"

namespace wardray::texture {

/// `object { OBJECT a, b }`: 1 where p (pattern space) is inside the object, else 0.
double object_pattern(const scene::Pattern& pat, const Vec3& p, int generator);

}  // namespace wardray::texture
