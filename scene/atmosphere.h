// Scene description, the atmosphere: sky_sphere and fog.
#pragma once

#include <vector>

#include "core/color.h"
#include "core/diagnostics.h"
#include "core/transform.h"
#include "scene/texture.h"

namespace wardray::scene {

/// `sky_sphere { pigment {...} ... }`: pigments looked up by ray direction, each later one layered over the
/// earlier ones through its filter and transmit.
struct SkySphere {
    std::vector<Pigment> pigments;
    Transform transform;  ///< sky space to world (rotates the directions)
    Color emission{1.0, 1.0, 1.0};
    bool operator==(const SkySphere&) const = default;
};

/// `fog { distance D color C }`: POV-Ray's constant fog (fog_type 1), exp(−depth/D) of the scene left.
struct Fog {
    double distance = 0.0;
    Color color;
    SourceLoc loc;
    bool operator==(const Fog&) const = default;
};

}  // namespace wardray::scene
