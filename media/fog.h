// Fogs: POV-Ray's fog blocks, constant (fog_type 1) and ground (fog_type 2), with or without turbulence.
#pragma once

#include <utility>
#include <vector>

#include "media/medium.h"
#include "scene/atmosphere.h"

namespace wardray::media {

/// POV-Ray's depth of a ray that hits nothing (BOUND_HUGE, an Intersection's initial depth): what fog sees of a
/// ray to the sky.
inline constexpr double kSkyDepth = 2.0e10;

/// The fraction of light one fog lets through along `segment` before its transmit bound (POV-Ray's
/// ComputeConstantFogColour and ComputeGroundFogColour): exp(−length · density / distance), the length shortened
/// by turbulence where the fog has it.
double fog_attenuation(const scene::Fog& fog, const Segment& segment, int noise_generator);

/// All of the scene's fogs together (POV-Ray's ComputeFog combines them in one step, not one after another).
class Fogs final : public Medium {
public:
    /// Takes the scene's fog blocks and its noise_generator (for turbulence).
    Fogs(std::vector<scene::Fog> fogs, int noise_generator)
        : m_fogs(std::move(fogs)), m_noise_generator(noise_generator) {}

    /// Each fog's attenuation (at least its transmit) filtered by its colour where it has filter; the rest of the
    /// light is the fog colour, summed over the fogs.
    Vec3 along_segment(const Vec3& colour, const Segment& segment) const override;
    /// The same attenuation with no fog colour added (POV-Ray's ComputeFog on a shadow test ray).
    Vec3 transmittance(const Segment& segment) const override;

private:
    /// The product of the fogs' filtered attenuations; `added` (when given) receives Σ (1 − att) · colour.
    Vec3 attenuate(const Segment& segment, Vec3* added) const;

    std::vector<scene::Fog> m_fogs;
    int m_noise_generator = 2;
};

}  // namespace wardray::media
