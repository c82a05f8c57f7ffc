// The scene's atmosphere, built from its fog blocks.
#include "media/atmosphere.h"

#include "media/fog.h"

namespace wardray::media {

std::unique_ptr<const Medium> make_atmosphere(const scene::Scene& scene) {
    if (scene.fogs.empty()) return nullptr;
    return std::make_unique<Fogs>(scene.fogs, scene.global.noise_generator);
}

}  // namespace wardray::media
