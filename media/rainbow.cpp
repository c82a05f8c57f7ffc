// Rainbows: POV-Ray 3.7's ComputeRainbow, applied to a ray before the atmosphere and fog.
#include "media/rainbow.h"

#include <algorithm>
#include <cmath>

#include "core/constants.h"
#include "texture/pigment.h"

namespace wardray::media {

namespace {

// SplitMix64 (Steele, Lea & Flood 2014): the jitter's uniform numbers in [0, 1), one stream per ray.
double next_uniform(std::uint64_t& state) {
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    z ^= z >> 31;
    return static_cast<double>(z >> 11) * 0x1.0p-53;
}

}  // namespace

Vec3 Rainbows::apply(const Vec3& colour, const Vec3& direction, double depth, std::uint64_t seed) const {
    Vec3 sum;
    int seen = 0;
    for (const scene::Rainbow& bow : m_rainbows) {
        if (!bow.pigment || bow.distance == 0.0 || bow.width == 0.0) continue;
        // The ray's angle from the bow's up vector, in the plane of up and right.
        const double x = dot(direction, bow.right);
        double y = dot(direction, bow.up);
        const double l = x * x + y * y;
        if (l > 0.0) y /= std::sqrt(l);
        const double angle = std::fabs(std::acos(y));
        if (angle > bow.arc_angle) continue;
        const double towards = dot(direction, bow.antisolar);
        if (towards < 0.0) continue;
        // The colour map index: the angle from the antisolar point across the bow's width, jittered.
        double index = (std::acos(towards) - bow.angle) / bow.width;
        if (bow.jitter > 0.0) index += (2.0 * next_uniform(seed) - 1.0) * bow.jitter;
        if (index < 0.0 || index > 1.0 - kPovEpsilon) continue;
        const Color c = texture::evaluate_pigment(*bow.pigment, Vec3{index, 0.0, 0.0}, m_noise_generator);
        // Smoothstep fall-off toward the ends of the arc.
        double fade = 0.0;
        if (bow.falloff_width > 0.0 && angle > bow.falloff_angle) {
            fade = (angle - bow.falloff_angle) / bow.falloff_width;
            fade = (3.0 - 2.0 * fade) * fade * fade;
        }
        // The farther the surface, the more of the bow; the colour's transmit is the least that passes.
        double k = std::exp(-depth / bow.distance);
        k = std::max(k, fade * (1.0 - c.transmit) + c.transmit);
        const double ki = 1.0 - k;
        const double f = c.filter * ki;
        const Vec3 passed = colour * (Vec3{1.0 - f, 1.0 - f, 1.0 - f} + c.rgb() * f);
        sum += k * passed + ki * c.rgb();
        ++seen;
    }
    // POV-Ray compat: the rainbows a ray sees are averaged; a ray that sees none keeps its colour.
    return seen > 0 ? sum / static_cast<double>(seen) : colour;
}

}  // namespace wardray::media
