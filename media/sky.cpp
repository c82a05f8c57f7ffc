// Sky: POV-Ray 3.7's ComputeSky, sky_sphere pigments layered over the background.
#include "media/sky.h"

#include <cmath>

#include "media/transmittance.h"
#include "texture/pigment.h"

namespace wardray::media {

namespace {

// POV-Ray compat: ComputeSky for an effective #version below 3.7. Each pigment, from the last to the first, adds
// its opaque part scaled by the summed filter and transmit of the product of those before it; the background
// shows through that product's filter colour, and emission scales the pigments only.
Vec3 legacy_sky(const scene::SkySphere& sky, const Vec3& p, const Vec3& background, int noise_generator) {
    Vec3 colour;
    Color product{1.0, 1.0, 1.0, 1.0, 1.0};
    double trans = 1.0;
    for (auto it = sky.pigments.rbegin(); it != sky.pigments.rend(); ++it) {
        const Color c = texture::evaluate_pigment(*it, p, noise_generator);
        colour += c.rgb() * (trans * (1.0 - c.filter - c.transmit));
        product = {product.r * c.r, product.g * c.g, product.b * c.b, product.filter * c.filter,
                   product.transmit * c.transmit};
        trans = std::abs(product.filter) + std::abs(product.transmit);
    }
    return colour * sky.emission.rgb() + background * filter_colour(product);
}

}  // namespace

Sky::Sky(const scene::Scene& scene)
    : m_sphere(scene.sky_sphere ? &*scene.sky_sphere : nullptr),
      m_background(scene.background),
      m_noise_generator(scene.global.noise_generator) {}

Vec3 Sky::radiance(const Vec3& direction) const {
    if (m_sphere == nullptr) return m_background.rgb();
    const scene::SkySphere& sky = *m_sphere;
    // POV-Ray compat: the direction is transformed as a point, so a translated sky_sphere shifts its pattern.
    const Vec3 p = sky.transform.is_identity() ? direction : sky.transform.inverse_point(direction);
    if (sky.legacy_layering) return legacy_sky(sky, p, m_background.rgb(), m_noise_generator);
    // POV-Ray 3.7's ComputeSky: pigments from the last to the first, each seen through those before it.
    Vec3 colour;
    Vec3 filter{1.0, 1.0, 1.0};
    for (auto it = sky.pigments.rbegin(); it != sky.pigments.rend(); ++it) {
        const Color c = texture::evaluate_pigment(*it, p, m_noise_generator);
        colour += c.rgb() * (1.0 - c.filter - c.transmit) * filter * sky.emission.rgb();
        filter = filter * filter_colour(c);
    }
    // POV-Ray compat: the background's own filter and transmit are ignored.
    return colour + m_background.rgb() * filter;
}

}  // namespace wardray::media
