// Scene description, image maps: a picture wrapped around an object as its pigment.
#pragma once

#include <memory>
#include <vector>

#include "core/vec3.h"

namespace wardray::scene {

/// An image's texels in the scene's working gamma, rows from the top.
struct ImageData {
    int width = 0;
    int height = 0;
    std::vector<float> rgb;  ///< width * height * 3
    bool has_alpha = false;  ///< the file has an alpha channel, which is not read
};

/// `image_map { png "file" map_type M interpolate I once filter all F transmit all T }` (POV-Ray 3.7).
struct ImageMap {
    std::shared_ptr<const ImageData> image;
    int map_type = 0;     ///< 0 planar, 1 spherical, 2 cylindrical, 5 torus
    int interpolate = 0;  ///< 0 none, 2 bilinear, 4 normalized distance
    bool once = false;    ///< no repetition: clear outside the unit square
    double filter_all = 0.0;
    double transmit_all = 0.0;
    bool operator==(const ImageMap&) const = default;
};

}  // namespace wardray::scene
