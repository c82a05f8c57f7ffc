// Transmittance: how much light passes through a coloured filter and through an object's interior.
#pragma once

#include "core/color.h"
#include "scene/interior.h"

namespace wardray::media {

/// POV-Ray's filter colour of a pigment colour: what passes through it, rgb·filter + transmit.
inline Vec3 filter_colour(const Color& c) { return c.rgb() * c.filter + Vec3{c.transmit, c.transmit, c.transmit}; }

/// POV-Ray's interior fade over `distance` travelled inside: exponential for fade_power ≥ 1000, else
/// fade_color + (1 − fade_color) / (1 + (distance/fade_distance)^fade_power). fade_distance must not be 0.
Vec3 interior_fade(const scene::Interior& interior, double distance);

}  // namespace wardray::media
