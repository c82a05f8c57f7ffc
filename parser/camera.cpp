// Camera resolution: from the camera block as written to POV-Ray 3.7's final location, direction, right and up.
#include <cmath>
#include <numbers>

#include "core/constants.h"
#include "parser/value.h"

namespace wardray::parser {

namespace {

// POV-Ray compat (VNormalize): scaled by the reciprocal of the length, not divided by it, which rounds differently;
// the camera's vectors then come out as POV-Ray's to the bit and so do its rays.
Vec3 pov_normalize(const Vec3& v) {
    const double len = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    if (!(len > 0.0)) return v;
    const double inv = 1.0 / len;
    return {v.x * inv, v.y * inv, v.z * inv};
}

}  // namespace

Camera resolve_camera(const CameraSpec& spec, std::string& error, std::string& warning) {
    Camera cam;
    cam.type = spec.type;
    cam.loc = spec.loc;
    cam.location = spec.location;
    cam.direction = spec.direction;
    cam.right = spec.right;
    cam.up = spec.up;
    cam.cylinder = spec.cylinder;
    cam.mesh_camera = spec.mesh_camera;
    cam.normal = spec.normal;
    cam.aperture = spec.aperture;
    cam.blur_samples = spec.blur_samples;
    cam.blur_samples_min = spec.blur_samples_min;
    cam.confidence = spec.confidence;
    cam.variance = spec.variance;
    // POV-Ray compat: without look_at and angle, the focal distance defaults to 1 whatever the direction's length.
    double direction_length = 1.0;

    // POV-Ray compat: the 3.5+ camera applies its items in a fixed order whatever order they were written in:
    // angle, then look_at, then the orthographic sizing, then the transformations.
    if (spec.angle) {
        const double angle = *spec.angle;
        // POV-Ray compat: angle 0 leaves the direction as it is; only a negative angle or 180 and more are errors.
        const bool planar = !spec.other_projection &&
                            (spec.type == Camera::Type::Perspective || spec.type == Camera::Type::Orthographic);
        if (spec.type == Camera::Type::Spherical) {
            cam.h_angle = angle;
            cam.v_angle = spec.v_angle.value_or(0.5 * angle);
            if (angle < 0.0) error = "Negative horizontal angle not allowed.";
            else if (cam.v_angle < 0.0) error = "Negative vertical angle not allowed.";
        } else if (angle < 0.0) {
            error = "Negative viewing angle.";
        } else if (planar && angle >= 180.0) {
            error = "Viewing angle has to be smaller than 180 degrees.";
        } else if (planar && angle > 0.0) {
            // direction_length = 0.5 * right_length / tan(angle / 2), in POV-Ray's order (M_PI_360 is pi / 360).
            const double half = angle * (std::numbers::pi / 360.0);
            direction_length = length(cam.right) / std::tan(half) / 2.0;
            cam.direction = pov_normalize(cam.direction) * direction_length;
        }
        if (!planar) cam.angle = angle;
    }

    // POV-Ray compat: a camera's look_at defaults to <0, 0, 1> wherever its location is (the orthographic sizing
    // below measures from it).
    const Vec3 look_at = spec.look_at.value_or(Vec3{0.0, 0.0, 1.0});
    if (spec.look_at) {
        direction_length = length(cam.direction);
        const double up_length = length(cam.up);
        const double right_length = length(cam.right);
        // The sign of (up x direction) . right tells the handedness the user chose with `right`.
        const double handedness = dot(cross(cam.up, cam.direction), cam.right);
        const Vec3 d = *spec.look_at - cam.location;
        if (length(d) == 0.0) {
            error = "camera look_at must differ from its location";
        } else {
            const Vec3 dir = pov_normalize(d);
            Vec3 right = cross(spec.sky, dir);
            if (length(right) < 1e-10 * length(spec.sky)) {
                warning = "camera looks along its sky vector; keeping the given right vector";
                right = cam.right;
            }
            right = pov_normalize(right);
            const Vec3 up = cross(dir, right);
            cam.direction = dir * direction_length;
            cam.right = right * (handedness > 0.0 ? right_length : -right_length);
            cam.up = up * up_length;
        }
    }

    if (spec.type == Camera::Type::Orthographic && (spec.angle || !(spec.had_up || spec.had_right))) {
        // POV-Ray compat: without up/right (or with angle) the orthographic view covers the same area at the
        // look_at distance as the perspective camera would.
        const double dir_length = length(cam.direction);
        const double distance = length(look_at - spec.location);
        if (dir_length > kPovEpsilon && distance > kPovEpsilon) {
            const double k = distance / dir_length;
            cam.right = cam.right * k;
            cam.up = cam.up * k;
        }
    }

    // POV-Ray compat: the focal distance is measured before the camera's transformations, from its location.
    cam.focal_distance = spec.focal_point ? length(*spec.focal_point - spec.location) : direction_length;
    if (cam.focal_distance == 0.0) cam.focal_distance = 1.0;

    cam.location = spec.transform.point(cam.location);
    cam.direction = spec.transform.vector(cam.direction);
    cam.right = spec.transform.vector(cam.right);
    cam.up = spec.transform.vector(cam.up);
    return cam;
}

}  // namespace wardray::parser
