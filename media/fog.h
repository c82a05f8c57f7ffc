// ConstantFog: POV-Ray's fog_type 1, the same density everywhere.
#pragma once

#include <utility>
#include <vector>

#include "media/medium.h"
#include "scene/atmosphere.h"

namespace wardray::media {

/// POV-Ray's constant fogs, all of the scene's together (POV-Ray combines them in one step, not one after another).
class ConstantFog final : public Medium {
public:
    /// Takes the scene's fog blocks in their order.
    explicit ConstantFog(std::vector<scene::Fog> fogs) : m_fogs(std::move(fogs)) {}

    /// Attenuation exp(−length/distance) (at least each fog's transmit), filtered by its colour where it has
    /// filter; the rest of the light is the fog colour.
    Vec3 along_segment(const Vec3& colour, const Segment& segment) const override;
    /// The same attenuation with no fog colour added (POV-Ray's ComputeFog on a shadow test ray).
    Vec3 transmittance(const Segment& segment) const override;

private:
    std::vector<scene::Fog> m_fogs;
};

}  // namespace wardray::media
