// Projections: POV-Ray 3.7's camera types, each placing its ray as tracepixel.cpp's CreateCameraRay does.
#include "camera/projections.h"

#include "camera/mesh_camera.h"

#include <cmath>
#include <numbers>

namespace wardray::camera {

namespace {

constexpr double k_pi = std::numbers::pi;
constexpr double k_degrees = k_pi / 180.0;  // POV-Ray's M_PI_180, to the bit
constexpr double k_half_degrees = k_pi / 360.0;  // POV-Ray's M_PI_360, to the bit

// POV-Ray compat (CreateCameraRay): every projection computes its image coordinates from the pixel's x + 0.5 and
// y - 0.5, where our pixel centre is (x + 0.5, y + 0.5), in POV-Ray's own expressions, so that a pixel centre's ray is
// POV-Ray's to the bit and ties at pixel centres fall as in POV-Ray.

/// POV-Ray's y argument after its y -= 0.5: our image position less one pixel.
double pov_y(double py) { return py - 1.0; }
/// POV-Ray's x0 from -0.5 (left edge) to 0.5 (right edge).
double centred_x(const Frame& f, double px) { return px / f.width - 0.5; }
/// POV-Ray's y0 from -0.5 (bottom edge) to 0.5 (top edge).
double centred_y(const Frame& f, double py) { return ((f.height - 1) - pov_y(py)) / f.height - 0.5; }
/// POV-Ray's x0 from -1 to 1 (fisheye, omnimax).
double unit_x(const Frame& f, double px) { return 2.0 * px / f.width - 1.0; }
/// POV-Ray's y0 from -1 to 1 (fisheye, omnimax, panoramic).
double unit_y(const Frame& f, double py) { return 2.0 * ((f.height - 1) - pov_y(py)) / f.height - 1.0; }

/// `p` rotated by `angle` radians about the unit axis `a`, right-handed (POV-Ray's axis rotation transform).
Vec3 rotate_about(const Vec3& p, const Vec3& a, double angle) {
    const double c = std::cos(angle), s = std::sin(angle);
    const Vec3 along = a * dot(a, p);
    return along + (p - along) * c + cross(a, p) * s;
}

/// The angle of (x, y) around the origin as POV-Ray's fisheye and omnimax measure it.
double polar_angle(double x, double y, double rad) {
    if (rad == 0.0) return 0.0;
    return x < 0.0 ? k_pi - std::asin(y / rad) : std::asin(y / rad);
}

}  // namespace

bool perspective_ray(const Frame& f, double px, double py, ProjectedRay& out) {
    out.x0 = centred_x(f, px);
    out.y0 = centred_y(f, py);
    out.origin = f.location;
    out.direction = f.direction + out.x0 * f.right + out.y0 * f.up;
    return true;
}

bool orthographic_ray(const Frame& f, double px, double py, ProjectedRay& out) {
    out.x0 = centred_x(f, px);
    out.y0 = centred_y(f, py);
    out.origin = f.location + out.x0 * f.right + out.y0 * f.up;
    out.direction = f.direction;
    return true;
}

bool fisheye_ray(const Frame& f, double px, double py, ProjectedRay& out) {
    // Image coordinates from -1 to 1, scaled by the lengths of right and up; no ray outside the unit circle.
    const double x = unit_x(f, px) * f.right_length;
    const double y = unit_y(f, py) * f.up_length;
    const double rad = std::sqrt(x * x + y * y);
    if (rad > 1.0) return false;
    out.x0 = polar_angle(x, y, rad);
    out.y0 = rad * f.camera->angle * k_half_degrees;  // the angle from the axis: half the field of view at the rim
    const double sy = std::sin(out.y0);
    out.origin = f.location;
    out.direction = std::cos(out.x0) * sy * f.unit_right + std::sin(out.x0) * sy * f.unit_up +
                    std::cos(out.y0) * f.unit_direction;
    return true;
}

bool omnimax_ray(const Frame& f, double px, double py, ProjectedRay& out) {
    double x = unit_x(f, px);
    double y = unit_y(f, py);
    // POV-Ray compat: the dome's frame sits at the bottom of wide images, with 1.283458 its own aspect ratio.
    const double aspect = f.right_length / f.up_length;
    if (aspect > 1.0) {
        if (aspect > 1.283458) {
            x *= aspect / 1.283458;
            y = (y - 1.0) / 1.283458 + 1.0;
        } else {
            y = (y - 1.0) / aspect + 1.0;
        }
    } else {
        y /= aspect;
    }
    const double rad = std::sqrt(x * x + y * y);
    if (rad > 1.0) return false;
    out.x0 = polar_angle(x, y, rad);
    out.y0 = 1.411269 * rad - 0.09439 * rad * rad * rad + 0.25674 * rad * rad * rad * rad * rad;
    const double cx = std::cos(out.x0), sx = std::sin(out.x0);
    const double cy = std::cos(out.y0), sy = std::sin(out.y0);
    // Nothing below 45 degrees under the projection axis.
    if (sx * sy < std::tan(135.0 * k_degrees) * cy) return false;
    out.origin = f.location;
    out.direction = cx * sy * f.unit_right + sx * sy * f.unit_up + cy * f.unit_direction;
    return true;
}

bool panoramic_ray(const Frame& f, double px, double py, ProjectedRay& out) {
    // Graphics Gems III's panorama: x from 0 to 1 sweeps half a turn, y from -1 to 1 the tangent up to the poles.
    out.x0 = (1.0 - px / f.width) * k_pi;
    out.y0 = 0.5 * k_pi * unit_y(f, py);
    double ty;
    if (std::fabs(0.5 * k_pi - std::fabs(out.y0)) < 1e-10) ty = out.y0 > 0.0 ? 2e10 : -2e10;
    else ty = std::tan(out.y0);
    out.origin = f.location;
    out.direction = std::cos(out.x0) * f.right + ty * f.up + std::sin(out.x0) * f.direction;
    return true;
}

bool ultra_wide_angle_ray(const Frame& f, double px, double py, ProjectedRay& out) {
    const double aspect = f.up_length / f.right_length;
    out.x0 = centred_x(f, px) * (f.camera->angle * k_degrees);
    out.y0 = centred_y(f, py) * (f.camera->angle * aspect * k_degrees);
    out.origin = f.location;
    out.direction = std::sin(out.x0) * f.unit_right + std::sin(out.y0) * f.unit_up +
                    std::cos(out.x0) * std::cos(out.y0) * f.unit_direction;
    return true;
}

bool cylinder_ray(const Frame& f, double px, double py, ProjectedRay& out) {
    // Types 1 and 3 curve around the up axis, 2 and 4 around the right axis; 3 and 4 move the origin along the
    // straight axis instead of tilting the ray (POV-Ray's CYL_1..4_CAMERA).
    const int type = f.camera->cylinder;
    const bool around_up = type == 1 || type == 3;
    const bool parallel = type == 3 || type == 4;
    const double turn = f.camera->angle * k_degrees;
    out.x0 = centred_x(f, px) * (around_up ? turn : f.right_length);
    out.y0 = centred_y(f, py) * (around_up ? f.up_length : turn);
    out.origin = f.location;
    // POV-Ray compat: the three terms summed in POV-Ray's order (VLinComb3), the tilt among them.
    if (around_up) {
        const double s = std::sin(out.x0), c = std::cos(out.x0);
        if (parallel) {
            out.direction = s * f.unit_right + c * f.unit_direction;
            out.origin = f.location + out.y0 * f.unit_up;
        } else {
            out.direction = s * f.unit_right + out.y0 * f.unit_up + c * f.unit_direction;
        }
    } else {
        const double s = std::sin(out.y0), c = std::cos(out.y0);
        if (parallel) {
            out.direction = s * f.unit_up + c * f.unit_direction;
            out.origin = f.location + out.x0 * f.unit_right;
        } else {
            out.direction = out.x0 * f.unit_right + s * f.unit_up + c * f.unit_direction;
        }
    }
    return true;
}

bool spherical_ray(const Frame& f, double px, double py, ProjectedRay& out) {
    // Latitude about the right vector, then longitude about the up vector.
    out.x0 = centred_x(f, px) * f.camera->h_angle * k_degrees;
    out.y0 = centred_y(f, py) * f.camera->v_angle * k_degrees;
    const Vec3 latitude = rotate_about(f.direction, f.unit_right, -out.y0);
    out.origin = f.location;
    out.direction = rotate_about(latitude, f.unit_up, out.x0);
    return true;
}

bool mesh_camera_ray(const Frame& f, double px, double py, ProjectedRay& out) {
    return f.mesh != nullptr && f.mesh->ray(f, px, py, 0, out);
}

}  // namespace wardray::camera
