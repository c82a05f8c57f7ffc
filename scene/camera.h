// Scene description, the camera.
#pragma once

#include <memory>
#include <string_view>

#include "core/diagnostics.h"
#include "core/vec3.h"
#include "scene/kind_list.h"
#include "scene/shapes.h"
#include "scene/texture.h"

namespace wardray::scene {

/// The camera projections the renderer draws, listed once: X(keyword, Enumerator). Camera::Type, the parser's
/// camera keywords and reserved words come from this list.
#define WARDRAY_CAMERAS(X)              \
    X(perspective, Perspective)         \
    X(orthographic, Orthographic)       \
    X(fisheye, Fisheye)                 \
    X(ultra_wide_angle, UltraWideAngle) \
    X(omnimax, Omnimax)                 \
    X(panoramic, Panoramic)             \
    X(cylinder, Cylinder)               \
    X(spherical, Spherical)             \
    X(mesh_camera, MeshCamera)

/// POV-Ray's `mesh_camera { rays_per_pixel, distribution [, max_distance] mesh { } ... [smooth] }`: rays leave
/// the faces of meshes along their normals.
struct MeshCameraSpec {
    /// One mesh of the camera with the transform its object statement gave it.
    struct PlacedMesh {
        Mesh mesh;
        Transform transform;
        bool operator==(const PlacedMesh&) const = default;
    };
    int rays_per_pixel = 1;
    int distribution = 0;        ///< 0-3: how pixels pick faces (POV-Ray's Face_Distribution_Method)
    double max_distance = 0.0;   ///< the optional maximum ray length (0: none)
    bool smooth = false;         ///< distribution 3: interpolate the vertex normals
    /// Shared, never null: a camera is copied (by the parser, by each camera model) and its meshes can hold
    /// millions of faces (a mesh per sample, a face per pixel).
    std::shared_ptr<const std::vector<PlacedMesh>> meshes = std::make_shared<const std::vector<PlacedMesh>>();
    bool operator==(const MeshCameraSpec& o) const {
        return rays_per_pixel == o.rays_per_pixel && distribution == o.distribution &&
               max_distance == o.max_distance && smooth == o.smooth && *meshes == *o.meshes;
    }
};

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
    double angle = 90.0;            ///< `angle`: the field of view of fisheye, ultra_wide_angle and cylinder
    double h_angle = 360.0;         ///< spherical: `angle H, V`, the horizontal field of view
    double v_angle = 180.0;         ///< spherical: the vertical field of view (H / 2 when not given)
    int cylinder = 1;               ///< `cylinder N`: which of POV-Ray's four cylindrical projections
    MeshCameraSpec mesh_camera;     ///< mesh_camera: its meshes and how rays leave them
    std::optional<Normal> normal;   ///< camera `normal { ... }`: perturbs every camera ray's direction
    /// Focal blur: `aperture`, `blur_samples [min,] max`, `confidence`, `variance`, `focal_point`.
    double aperture = 0.0;
    int blur_samples = 0;
    int blur_samples_min = 0;
    double confidence = 0.9;
    double variance = 1.0 / 10000.0;
    double focal_distance = 1.0;    ///< from location to the plane in focus, along direction
    SourceLoc loc;
    /// True when POV-Ray blurs: an aperture and a number of samples.
    bool focal_blur() const { return aperture != 0.0 && blur_samples > 0; }
    bool operator==(const Camera&) const = default;
};

#define WARDRAY_CAMERA_KEYWORD(keyword, Enumerator) {#keyword, Camera::Type::Enumerator},
/// The keyword of each projection of WARDRAY_CAMERAS, in its order.
inline constexpr KindKeyword<Camera::Type> k_camera_keywords[] = {WARDRAY_CAMERAS(WARDRAY_CAMERA_KEYWORD)};
#undef WARDRAY_CAMERA_KEYWORD

/// The keyword of a projection: "perspective" or "orthographic".
constexpr std::string_view camera_type_name(Camera::Type type) { return kind_keyword(k_camera_keywords, type); }

}  // namespace wardray::scene
