// Sky: POV-Ray 3.7's ComputeSky, sky_sphere pigments layered over the background.
#include "media/sky.h"

#include <algorithm>
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
      m_alpha_background(scene.background),
      m_legacy(scene.legacy_version),
      m_noise_generator(scene.global.noise_generator) {
    // POV-Ray compat (Parse_Frame, background): without an alpha channel a background read under 3.7 is composed
    // over black, and its filter and transmit dropped; one read under an older version keeps its colour.
    if (!scene.background_legacy) {
        const double opaque = 1.0 - scene.background.transmit;
        m_background = {scene.background.r * opaque, scene.background.g * opaque, scene.background.b * opaque};
    }
    m_background.filter = m_background.transmit = 0.0;
    // With an alpha channel the background is transparent black unless a 3.7 scene says otherwise; an older
    // scene's background keeps its colour with filter 0 and transmit 1.
    if (!scene.background_given) m_alpha_background = {0.0, 0.0, 0.0, 0.0, 1.0};
    else if (scene.background_legacy) m_alpha_background.filter = 0.0, m_alpha_background.transmit = 1.0;
}

Vec3 Sky::radiance_with_alpha(const Vec3& direction, double& transmit) const {
    // POV-Ray compat (ComputeSky before 3.7): with an alpha channel a legacy scene's sky is fully transparent.
    transmit = 1.0;
    if (m_legacy) return {};
    Vec3 colour;
    Vec3 filter{1.0, 1.0, 1.0};
    if (m_sphere != nullptr) {
        const scene::SkySphere& sky = *m_sphere;
        const Vec3 p = sky.transform.is_identity() ? direction : sky.transform.inverse_point(direction);
        for (auto it = sky.pigments.rbegin(); it != sky.pigments.rend(); ++it) {
            const Color c = texture::evaluate_pigment(*it, p, m_noise_generator);
            colour += c.rgb() * (1.0 - c.filter - c.transmit) * filter * sky.emission.rgb();
            filter = filter * filter_colour(c);
        }
    }
    // The background as one more uniform layer, its filter and transmit kept; what it lets through is the alpha.
    const Color& b = m_alpha_background;
    colour += b.rgb() * (1.0 - b.filter - b.transmit) * filter;
    filter = filter * filter_colour(b);
    transmit = std::min(1.0, std::fabs(texture::grey(filter)));
    return colour;
}

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
