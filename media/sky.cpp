// Sky: POV-Ray 3.7's ComputeSky, sky_sphere pigments layered over the background.
#include "media/sky.h"

#include "media/transmittance.h"
#include "texture/pigment.h"

namespace wardray::media {

Sky::Sky(const scene::Scene& scene)
    : m_sphere(scene.sky_sphere ? &*scene.sky_sphere : nullptr),
      m_background(scene.background),
      m_noise_generator(scene.global.noise_generator) {}

Vec3 Sky::radiance(const Vec3& direction) const {
    Vec3 colour;
    Vec3 filter{1.0, 1.0, 1.0};
    if (m_sphere) {
        // POV-Ray 3.7's ComputeSky: pigments from the last to the first, each seen through those before it.
        const scene::SkySphere& sky = *m_sphere;
        const Vec3 p = sky.transform.is_identity() ? direction : sky.transform.inverse_point(direction);
        for (auto it = sky.pigments.rbegin(); it != sky.pigments.rend(); ++it) {
            const Color c = texture::evaluate_pigment(*it, p, m_noise_generator);
            colour += c.rgb() * (1.0 - c.filter - c.transmit) * filter * sky.emission.rgb();
            filter = filter * filter_colour(c);
        }
    }
    // POV-Ray compat: the background's own filter and transmit are ignored.
    return colour + m_background.rgb() * filter;
}

}  // namespace wardray::media
