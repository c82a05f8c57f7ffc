// POV-Ray's ComputeReflectivity, shared by the photon pass and the integrator's reflections.
#pragma once

#include "core/vec3.h"
#include "scene/texture.h"

namespace wardray::photons {

/// POV-Ray's ComputeReflectivity: the reflected fraction at incidence cos_i for the relative index `ior`
/// (used by `fresnel` only), and the reflection ray's weight, scaled in place.
Vec3 reflectivity(const scene::Finish& f, double cos_i, double ior, double& weight);

}  // namespace wardray::photons
