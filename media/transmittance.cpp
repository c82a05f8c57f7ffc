// Transmittance: POV-Ray 3.7's interior fade (the same formula for surface and shadow rays).
#include "media/transmittance.h"

#include <cmath>

namespace wardray::media {

Vec3 interior_fade(const scene::Interior& interior, double distance) {
    const double d = distance / interior.fade_distance;
    const Vec3 fc = interior.fade_color.rgb();
    const Vec3 one{1.0, 1.0, 1.0};
    if (interior.fade_power >= 1000.0) {
        // POV-Ray compat: fade_power 1000 and above means exponential absorption by 1 − fade_color.
        const Vec3 k = (one - fc) * -d;
        return Vec3{std::exp(k.x), std::exp(k.y), std::exp(k.z)};
    }
    return fc + (one - fc) / (1.0 + std::pow(d, interior.fade_power));
}

}  // namespace wardray::media
