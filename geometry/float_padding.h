// Float padding: how much the boxes Embree traverses in float grow, so that a float ray meets every box its double ray
// meets.
#pragma once

#include <vector>

#include "geometry/shape.h"

namespace wardray::geometry {

/// Each box grown for rays from anywhere in a scene of magnitude `scene_magnitude`: by 1e-6 of that, more than the
/// float ray's rounding (relative ~1e-7 of the scene's coordinates), plus 1e-6 of the box's size.
std::vector<Bounds> padded_for_scene(const std::vector<Bounds>& boxes, double scene_magnitude);

/// Each box grown for rays whose float origin is within `origin_magnitude` on every axis: a float ray from o meets
/// box B within ~1e-7 (|o| + |B|) of the double ray, so 1e-6 of that plus 1e-6 of the box's size, and never more
/// than `loose` (padded_for_scene's boxes, which hold for any origin).
std::vector<Bounds> padded_for_origins(const std::vector<Bounds>& boxes, const std::vector<Bounds>& loose,
                                       double origin_magnitude);

/// The origin magnitude worth a BVH of its own (padded_for_origins) beside the scene-wide one: the largest
/// magnitude of the boxes within 1000 times the median box's (all but a sky sphere of radius 1e6 around a scene of a
/// few units); +infinity when the scene is not 16 times larger than that, so that one BVH does.
double near_origin_magnitude(const std::vector<Bounds>& boxes, double scene_magnitude);

}  // namespace wardray::geometry
