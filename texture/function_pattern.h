// The `function { ... }` pattern: a user function of the point, evaluated by the function VM.
#pragma once

#include "scene/texture.h"

namespace wardray::texture {

/// POV-Ray's function pattern: f(x, y, z), values above 1 reduced modulo 1 (frequency and the wave follow).
double function_pattern(const scene::Pattern& pattern, const Vec3& p, int generator);

}  // namespace wardray::texture
