// Photon light: POV-Ray 3.7's ComputePhotonDiffuseLight, the photon map's estimate of the light focused onto a
// surface (Jensen 1996, "Global Illumination using Photon Maps", eq. 6: the flux of the k nearest photons over the
// disc π r² they were gathered from), shaded by each layer's finish like a light from each photon's direction.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/constants.h"
#include "geometry/scene_geometry.h"
#include "lighting/integrator.h"
#include "photons/photon_map.h"

namespace wardray::lighting {

Vec3 Integrator::photon_light(const scene::Finish& finish, const Vec3& pigment, double opacity, const Surface& s,
                              const Vec3& n, const photons::Gathered& gathered) const {
    if (gathered.photons.empty() || !(gathered.radius > 0.0)) return {};
    Vec3 sum;
    for (const photons::Photon* ph : gathered.photons) {
        const Vec3 to_light = photons::photon_direction(*ph);
        // POV-Ray compat: the photon's flux is divided by the cosine it met the raw surface at (clamped to
        // [0.1, 1], against bright dots), so the finish's own cosine gives back the flux per area.
        const double c = std::clamp(dot(s.raw_normal, to_light), 0.1, 1.0);
        const Vec3 arriving = photons::photon_colour(*ph, gathered.exponent_offset) * (1.0 / c);
        if (!s.object->double_illuminate && dot(n, to_light) < kPovEpsilon) continue;
        sum += finish_light(finish, pigment, opacity, s, n, to_light, arriving, s.highlights, ph->point());
    }
    return sum / (std::numbers::pi * gathered.radius * gathered.radius);
}

}  // namespace wardray::lighting
