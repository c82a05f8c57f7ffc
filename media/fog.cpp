// Fogs: POV-Ray 3.7's ComputeFog over one ray segment, for constant and ground fog, with turbulence.
#include "media/fog.h"

#include <algorithm>
#include <cmath>

#include "core/constants.h"
#include "media/ground_fog.h"
#include "texture/noise.h"

namespace wardray::media {

namespace {

// POV-Ray's fog turbulence: the further the segment reaches, the less its length is shortened, by
// 1 − exp(−width/distance)·min(1, turbulence(midpoint · turbulence vector) · turb_depth).
double turbulent_width(const scene::Fog& fog, const Vec3& midpoint, double width, int noise_generator) {
    const scene::Turbulence& turb = *fog.turbulence;
    const texture::TurbulenceParams params{turb.octaves, turb.omega, turb.lambda};
    const double n = texture::turbulence(midpoint * turb.amount, params, noise_generator);
    const double k = std::exp(-width / fog.distance);
    return width * (1.0 - k * std::min(1.0, n * fog.turb_depth));
}

}  // namespace

double fog_attenuation(const scene::Fog& fog, const Segment& segment, int noise_generator) {
    // POV-Ray compat: a ray to the sky is BOUND_HUGE long.
    double width = std::isinf(segment.length) ? kSkyDepth : segment.length;
    const Vec3 end = segment.origin + segment.direction * width;
    double density = 1.0;
    if (fog.type == 2) {
        const double start_h = (dot(segment.origin, fog.up) - fog.offset) / fog.alt;
        const double end_h = (dot(end, fog.up) - fog.offset) / fog.alt;
        density = ground_fog_density(start_h, end_h);
    }
    if (fog.turbulence) width = turbulent_width(fog, (segment.origin + end) * 0.5, width, noise_generator);
    return std::exp(-width * density / fog.distance);
}

Vec3 Fogs::attenuate(const Segment& segment, Vec3* added) const {
    Vec3 attenuation{1.0, 1.0, 1.0};
    for (const scene::Fog& fog : m_fogs) {
        if (std::fabs(fog.distance) <= kPovEpsilon) continue;
        const Color& c = fog.color;
        // The fog's transmit is the least light it lets through.
        const double att = std::max(fog_attenuation(fog, segment, m_noise_generator), c.transmit);
        const Vec3 unfiltered{1.0 - c.filter, 1.0 - c.filter, 1.0 - c.filter};
        attenuation = attenuation * (unfiltered + c.rgb() * c.filter) * att;
        if (added) *added += c.rgb() * (1.0 - att);
    }
    return attenuation;
}

Vec3 Fogs::transmittance(const Segment& segment) const { return attenuate(segment, nullptr); }

Vec3 Fogs::along_segment(const Vec3& colour, const Segment& segment) const {
    Vec3 added;
    const Vec3 attenuation = attenuate(segment, &added);
    return added + attenuation * colour;
}

}  // namespace wardray::media
