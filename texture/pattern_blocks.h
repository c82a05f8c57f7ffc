// Block patterns and pigment_pattern: square, triangular, cubic (POV-Ray 3.7's numbered-cell patterns) and the
// grey level of a pigment (the `<keyword>_pattern` functions of WARDRAY_PATTERNS that live in pattern_blocks.cpp).
#pragma once

#include "scene/texture.h"
#include "core/vec3.h"
#include "texture/surface_point.h"

namespace wardray::texture {

/// `square`: cells 0..3 of the unit squares in the x-z plane.
double square_pattern(const scene::Pattern& pat, const Vec3& p, int generator);
/// `triangular`: cells 0..5 of equilateral triangles (side 1) in the x-z plane.
double triangular_pattern(const scene::Pattern& pat, const Vec3& p, int generator);
/// `cubic`: 0..5 for the six pyramids around the axes (+x, +y, +z, −x, −y, −z).
double cubic_pattern(const scene::Pattern& pat, const Vec3& p, int generator);
/// `pigment_pattern { pigment }`: the pigment's grey level at the point (on `surface`, when shading one).
double pigment_pattern_pattern(const scene::Pattern& pat, const Vec3& p, int generator, const SurfacePoint* surface);

}  // namespace wardray::texture
