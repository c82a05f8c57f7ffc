// Scene description, the camera.
#pragma once

#include <string_view>

#include "core/diagnostics.h"
#include "core/vec3.h"
#include "scene/kind_list.h"

namespace wardray::scene {

/// The camera projections the renderer draws, listed once: X(keyword, Enumerator). Camera::Type, the parser's
/// camera keywords and reserved words come from this list.
#define WARDRAY_CAMERAS(X)      \
    X(perspective, Perspective) \
    X(orthographic, Orthographic)

/// The camera, resolved by the parser to POV-Ray's final vectors (after look_at, angle, sky and transforms).
struct Camera {
#define WARDRAY_CAMERA_ENUMERATOR(keyword, Enumerator) Enumerator,
    /// The projections of WARDRAY_CAMERAS, in its order.
    enum class Type { WARDRAY_CAMERAS(WARDRAY_CAMERA_ENUMERATOR) };
#undef WARDRAY_CAMERA_ENUMERATOR
    Type type = Type::Perspective;
    Vec3 location{0.0, 0.0, 0.0};
    Vec3 direction{0.0, 0.0, 1.0};  ///< from location to the centre of the image plane
    Vec3 right{1.33, 0.0, 0.0};     ///< full width of the image plane
    Vec3 up{0.0, 1.0, 0.0};         ///< full height of the image plane
    SourceLoc loc;
    bool operator==(const Camera&) const = default;
};

#define WARDRAY_CAMERA_KEYWORD(keyword, Enumerator) {#keyword, Camera::Type::Enumerator},
/// The keyword of each projection of WARDRAY_CAMERAS, in its order.
inline constexpr KindKeyword<Camera::Type> k_camera_keywords[] = {WARDRAY_CAMERAS(WARDRAY_CAMERA_KEYWORD)};
#undef WARDRAY_CAMERA_KEYWORD

/// The keyword of a projection: "perspective" or "orthographic".
constexpr std::string_view camera_type_name(Camera::Type type) { return kind_keyword(k_camera_keywords, type); }

}  // namespace wardray::scene
