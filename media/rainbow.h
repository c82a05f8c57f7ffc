// Rainbows: POV-Ray's rainbow blocks, a colour map spread over a cone around the antisolar direction.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "core/vec3.h"
#include "scene/atmosphere.h"

namespace wardray::media {

/// All of the scene's rainbows (POV-Ray's ComputeRainbow averages the ones a ray sees).
class Rainbows {
public:
    /// Takes the scene's rainbow blocks and its noise_generator (for patterned colour maps).
    Rainbows(std::vector<scene::Rainbow> rainbows, int noise_generator)
        : m_rainbows(std::move(rainbows)), m_noise_generator(noise_generator) {}

    /// The colour arriving along the unit `direction` when `colour` comes from `depth` away (POV-Ray's
    /// BOUND_HUGE for the sky): each rainbow the ray sees blends its colour in by 1 − exp(−depth/distance).
    /// `seed` draws the jitter of the ray's colour-map index, so the same ray always jitters alike.
    Vec3 apply(const Vec3& colour, const Vec3& direction, double depth, std::uint64_t seed) const;

private:
    std::vector<scene::Rainbow> m_rainbows;
    int m_noise_generator = 2;
};

}  // namespace wardray::media
