// A medium's density at a point: the product of its `density` blocks, stopping early where it is black.
#pragma once

#include "core/vec3.h"
#include "scene/media.h"

namespace wardray::media {

/// The product of the densities of `m` at `p` (1 without any), multiplied in their order. Density colours have
/// finite components, so one that is black makes the product black: the cheap ones (plain colours and geometric
/// patterns without turbulence, warps or a pigment map) are looked at first, and a black one, or a black running
/// product, ends the evaluation; where none is black the product is the same, operation for operation, as
/// multiplying them all in order. So crackle under a spherical fall-off (the micro example) costs nothing where
/// the fall-off is zero.
Vec3 media_density(const scene::Media& m, const Vec3& p, int noise_generator);

}  // namespace wardray::media
