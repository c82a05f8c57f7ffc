// Image maps: the colour an image_map pigment gives a point, as POV-Ray 3.7's imageutil.cpp maps it.
#pragma once

#include "core/color.h"
#include "core/vec3.h"
#include "scene/image_map.h"
#include "scene/texture.h"

namespace wardray::texture {

/// The colour of `map` at `p` (in the pigment's own space, after its transform and warps): the image's texel,
/// interpolated as asked, with filter all and transmit all added; clear white where `once` leaves no image.
Color image_map_color(const scene::ImageMap& map, const Vec3& p);

/// The image position (texels, y from the top, wrapped into the image) of `p` under the map's projection, offset
/// and `once`; false where the map leaves no image (POV-Ray's map_pos).
bool image_position(const scene::ImageMap& map, const Vec3& p, double& x, double& y);

/// The colour (with filter and transmit) at an image position, interpolated as the map asks; `index` is the
/// palette index there (interpolated and truncated), -1 for an image without a palette (POV-Ray's
/// image_colour_at).
Color image_color_at(const scene::ImageMap& map, double x, double y, int& index);

/// `image_pattern`: the image's grey level at `p` (its red channel with use_alpha), 0 off the image.
double image_pattern_pattern(const scene::Pattern& pat, const Vec3& p, int generator);

/// material_map: which of `count` materials the map picks at `p` (POV-Ray's material_map).
int material_map_index(const scene::ImageMap& map, const Vec3& p, int count);

/// bump_map: the normal `n` (pattern space) replaced by the image's bumps at `p`, heights `amount` times the
/// grey level (or the palette index with use_index), as POV-Ray's bump_map computes it; unchanged off the image.
Vec3 bump_map_normal(const scene::ImageMap& map, double amount, const Vec3& p, const Vec3& n);

}  // namespace wardray::texture
