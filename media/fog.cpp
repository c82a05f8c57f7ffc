// ConstantFog: POV-Ray 3.7's constant fog (fog.cpp's constant_fog) over one ray segment.
#include "media/fog.h"

#include <algorithm>
#include <cmath>

#include "core/constants.h"

namespace wardray::media {

Vec3 ConstantFog::transmittance(const Segment& segment) const {
    Vec3 attenuation{1.0, 1.0, 1.0};
    for (const scene::Fog& fog : m_fogs) {
        if (std::fabs(fog.distance) <= kPovEpsilon) continue;
        const Color& c = fog.color;
        const double att = std::max(std::exp(-segment.length / fog.distance), c.transmit);
        attenuation = attenuation * (Vec3{1.0 - c.filter, 1.0 - c.filter, 1.0 - c.filter} + c.rgb() * c.filter) * att;
    }
    return attenuation;
}

Vec3 ConstantFog::along_segment(const Vec3& colour, const Segment& segment) const {
    // POV-Ray's constant fog: attenuation exp(−depth/distance) (at least the fog's transmit), filtered by its
    // colour where it has filter; the rest of the ray sees the fog colour.
    Vec3 attenuation{1.0, 1.0, 1.0};
    Vec3 added;
    for (const scene::Fog& fog : m_fogs) {
        if (std::fabs(fog.distance) <= kPovEpsilon) continue;
        const Color& c = fog.color;
        double att = std::exp(-segment.length / fog.distance);
        att = std::max(att, c.transmit);
        attenuation = attenuation * (Vec3{1.0 - c.filter, 1.0 - c.filter, 1.0 - c.filter} + c.rgb() * c.filter) * att;
        added += c.rgb() * (1.0 - att);
    }
    return added + attenuation * colour;
}

}  // namespace wardray::media
