// Projections: one function per camera of WARDRAY_CAMERAS, the direction through an image position.
#pragma once

#include "core/vec3.h"
#include "scene/camera.h"

namespace wardray::camera {

class MeshCamera;

/// The camera as every projection reads it: its final vectors, their unit versions and the image size.
struct Frame {
    const scene::Camera* camera = nullptr;
    Vec3 location, direction, right, up;  ///< as the camera block resolved them
    Vec3 unit_direction, unit_right, unit_up;
    double right_length = 1.0;
    double up_length = 1.0;
    double width = 1.0;   ///< image width in pixels
    double height = 1.0;  ///< image height in pixels
    const MeshCamera* mesh = nullptr;  ///< mesh_camera: its meshes
};

/// A projection's ray before focal blur and camera normal: its origin, its (unnormalised) direction, and the
/// image coordinates POV-Ray hands the camera normal (each projection's own x0, y0).
struct ProjectedRay {
    Vec3 origin;
    Vec3 direction;
    double x0 = 0.0;
    double y0 = 0.0;
};

/// The ray of a projection through image position (px, py) (pixel units, origin top-left, y down); false where
/// the projection traces no ray (outside a fisheye's circle).
using ProjectFn = bool (*)(const Frame& frame, double px, double py, ProjectedRay& out);

#define WARDRAY_PROJECT_DECLARE(keyword, Enumerator) \
    bool keyword##_ray(const Frame& frame, double px, double py, ProjectedRay& out);
WARDRAY_CAMERAS(WARDRAY_PROJECT_DECLARE)
#undef WARDRAY_PROJECT_DECLARE

/// The projection of each camera of WARDRAY_CAMERAS, in its order.
#define WARDRAY_PROJECT_ENTRY(keyword, Enumerator) &keyword##_ray,
inline constexpr ProjectFn k_projections[] = {WARDRAY_CAMERAS(WARDRAY_PROJECT_ENTRY)};
#undef WARDRAY_PROJECT_ENTRY

}  // namespace wardray::camera
