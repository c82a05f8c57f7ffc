// POV-Ray's `finish { crand }` graininess: a random amount taken off each light's diffuse intensity.
#pragma once

#include <cstdint>

#include "cache/hemisphere_sampler.h"
#include "core/render_seed.h"
#include "core/vec3.h"

namespace wardray::lighting {

/// The amount `crand` takes off the diffuse intensity of the light at `light_position` reaching the surface point
/// `p`: crand · ξ with ξ uniform in [0, 1) (POV-Ray's ComputeDiffuseColour subtracts POV_rand() · Crand after the
/// Lambert term, so the surface darkens by crand/2 on average and can go below black). POV-Ray draws ξ from a
/// per-thread sequence, so its grain changes from one render to the next; here ξ is a hash of the point and the
/// light (and the render seed, --seed), so a render repeats exactly for any thread count.
inline double graininess(double crand, const Vec3& p, const Vec3& light_position, std::uint64_t seed) {
    constexpr std::uint64_t kSalt = 0xC2A4D0000000000Dull;  // keeps ξ apart from the area-light jitter's draws
    cache::SplitMix64 rng(cache::seed_from(p, light_position, reseed(kSalt, seed)));
    return crand * rng.uniform();
}

}  // namespace wardray::lighting
