// Scene description, the camera.
#pragma once

#include "core/diagnostics.h"
#include "core/vec3.h"

namespace wardray::scene {

/// The camera, resolved by the parser to POV-Ray's final vectors (after look_at, angle, sky and transforms).
struct Camera {
    enum class Type { Perspective, Orthographic };
    Type type = Type::Perspective;
    Vec3 location{0.0, 0.0, 0.0};
    Vec3 direction{0.0, 0.0, 1.0};  ///< from location to the centre of the image plane
    Vec3 right{1.33, 0.0, 0.0};     ///< full width of the image plane
    Vec3 up{0.0, 1.0, 0.0};         ///< full height of the image plane
    SourceLoc loc;
    bool operator==(const Camera&) const = default;
};

}  // namespace wardray::scene
