// Normal perturbation: POV-Ray 3.7's `normal { ... }` patterns tilting the shading normal.
#pragma once

#include "scene/scene.h"
#include "core/vec3.h"
#include "texture/surface_point.h"

namespace wardray::texture {

/// POV-Ray's Perturb_Normal: `n` (unit, world space, facing the viewer) tilted by `normal` at `p` (the point in
/// the normal's enclosing space). Returns a unit vector. `surface`, the intersection being shaded if any, is what
/// slope and aoi read.
Vec3 perturb_normal(const scene::Normal& normal, const Vec3& n, const Vec3& p, int noise_generator,
                    const SurfacePoint* surface = nullptr);

/// A unit normal carried into a pattern's space (POV-Ray's Warp_Normal: the transpose of pattern→world).
Vec3 warp_normal(const scene::Pattern& pattern, const Vec3& n);
/// A unit normal carried back out of a pattern's space (POV-Ray's UnWarp_Normal).
Vec3 unwarp_normal(const scene::Pattern& pattern, const Vec3& n);
/// As above, normalized before and after unless `keep` (no_bump_scale, the pattern's own or inherited); the
/// two-argument forms take the pattern's own flag.
Vec3 warp_normal(const scene::Pattern& pattern, const Vec3& n, bool keep);
Vec3 unwarp_normal(const scene::Pattern& pattern, const Vec3& n, bool keep);

}  // namespace wardray::texture
