// Scene description, interiors: what is inside an object (index of refraction, fade, media).
#pragma once

#include <vector>

#include "core/color.h"
#include "scene/media.h"

namespace wardray::scene {

/// The inside of an object: index of refraction and POV-Ray's fade of light passing through.
struct Interior {
    double ior = 1.0;
    double fade_distance = 0.0;
    double fade_power = 0.0;
    Color fade_color;
    /// `hollow`: fog (and media) fill the object's inside; POV-Ray's default is not hollow.
    bool hollow = false;
    /// `media { }` blocks inside the object, in their order (all of them act together).
    std::vector<Media> media;
    bool operator==(const Interior&) const = default;
};

}  // namespace wardray::scene
