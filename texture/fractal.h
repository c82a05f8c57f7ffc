// Fractal patterns: mandel, julia and magnet, as POV-Ray 3.7 iterates them (the `<keyword>_pattern` functions of
// WARDRAY_PATTERNS that live in fractal.cpp).
#pragma once

#include "scene/texture.h"
#include "core/vec3.h"

namespace wardray::texture {

/// `mandel N`: z ← z^e + p from z = p, p in the x-y plane; exterior/interior colourings as POV-Ray's.
double mandel_pattern(const scene::Pattern& pat, const Vec3& p, int generator);
/// `julia <re, im>, N`: z ← z^e + c from z = p.
double julia_pattern(const scene::Pattern& pat, const Vec3& p, int generator);
/// `magnet 1|2 mandel N` or `magnet 1|2 julia <re, im>, N`: POV-Ray's magnet formulas.
double magnet_pattern(const scene::Pattern& pat, const Vec3& p, int generator);

}  // namespace wardray::texture
