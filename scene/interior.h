// Scene description, interiors: what is inside an object (index of refraction, fade).
#pragma once

#include "core/color.h"

namespace wardray::scene {

/// The inside of an object: index of refraction and POV-Ray's fade of light passing through.
struct Interior {
    double ior = 1.0;
    double fade_distance = 0.0;
    double fade_power = 0.0;
    Color fade_color;
    /// `hollow`: fog (and media) fill the object's inside; POV-Ray's default is not hollow.
    bool hollow = false;
    bool operator==(const Interior&) const = default;
};

}  // namespace wardray::scene
