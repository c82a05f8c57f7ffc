// The scene's atmosphere: the one medium every ray outside an object passes through.
#pragma once

#include <memory>

#include "media/medium.h"
#include "scene/scene.h"

namespace wardray::media {

/// The scene's atmosphere as one medium (its fogs), or null when it has none, so clear scenes pay nothing.
std::unique_ptr<const Medium> make_atmosphere(const scene::Scene& scene);

}  // namespace wardray::media
