// Light choice on gather paths: a light picked by its unshadowed light stands for all of them, so a gather ray's hit
// costs one shadow ray instead of one per light.
#pragma once

#include <cstddef>
#include <span>

#include "scene/scene.h"

namespace wardray::lighting {

/// The light a uniform number picked and the chance it had of being picked.
struct LightPick {
    std::size_t index = 0;
    double probability = 0.0;
};

/// Picks one of the lights with chance proportional to `importance` (each ≥ 0, `total` their sum, > 0) by inverting
/// the discrete distribution at the uniform `u` in [0, 1). Dividing the picked light's contribution by the chance
/// keeps the expectation the sum over all lights (Shirley, Wang & Zimmerman 1996, "Monte Carlo techniques for direct
/// lighting calculations", sec. 4: lights chosen by their estimated unoccluded contribution).
LightPick pick_light(std::span<const double> importance, double total, double u);

/// POV-Ray's ComputeDiffuseLight: `light` lights `object` when it is a global light the object does not turn off, or
/// a light of one of the object's light groups.
bool lights_object(const scene::Light& light, const scene::Object& object);

}  // namespace wardray::lighting
