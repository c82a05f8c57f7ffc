// Image maps: the colour an image_map pigment gives a point, as POV-Ray 3.7's imageutil.cpp maps it.
#pragma once

#include "core/color.h"
#include "core/vec3.h"
#include "scene/image_map.h"

namespace wardray::texture {

/// The colour of `map` at `p` (in the pigment's own space, after its transform and warps): the image's texel,
/// interpolated as asked, with filter all and transmit all added; clear white where `once` leaves no image.
Color image_map_color(const scene::ImageMap& map, const Vec3& p);

}  // namespace wardray::texture
