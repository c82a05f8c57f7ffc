// A medium's density at a point: the product of its `density` blocks, stopping early where it is black.
#include "media/media_density.h"

#include <array>
#include <cstdint>

#include "texture/pigment.h"

namespace wardray::media {

namespace {

// A density whose value costs a few operations: a plain colour, or a geometric pattern without turbulence, warps
// or a pigment map.
bool cheap_density(const scene::Pigment& d) {
    using T = scene::Pattern::Type;
    if (d.image_map || d.pattern.params->turbulence || !d.pattern.warps.empty() || !d.pigment_map.empty()) return false;
    switch (d.pattern.type) {
        case T::None: case T::Gradient: case T::Radial: case T::Onion: case T::Boxed: case T::Spherical:
        case T::Planar: case T::Cylindrical: return true;
        default: return false;
    }
}

}  // namespace

Vec3 media_density(const scene::Media& m, const Vec3& p, int noise) {
    const std::vector<scene::Pigment>& densities = m.densities;
    constexpr std::size_t kMaxEarly = 8;
    std::array<Vec3, kMaxEarly> early;
    std::uint32_t have = 0;
    if (densities.size() > 1 && densities.size() <= kMaxEarly) {
        for (std::size_t i = 0; i < densities.size(); ++i) {
            if (!cheap_density(densities[i])) continue;
            early[i] = texture::evaluate_pigment(densities[i], p, noise).rgb();
            if (early[i] == Vec3{}) return {};
            have |= 1u << i;
        }
    }
    Vec3 density{1.0, 1.0, 1.0};
    for (std::size_t i = 0; i < densities.size(); ++i) {
        density = density * ((have >> i) & 1u ? early[i] : texture::evaluate_pigment(densities[i], p, noise).rgb());
        if (density == Vec3{}) return density;
    }
    return density;
}

}  // namespace wardray::media
