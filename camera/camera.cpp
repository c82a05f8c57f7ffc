// CameraModel: the projection of the camera's type, then focal blur's lens offset and the camera normal.
#include "camera/camera.h"

#include <cmath>

#include "texture/normal.h"

namespace wardray::camera {

CameraModel::CameraModel(const scene::Camera& camera, int width, int height, int noise_generator)
    : m_camera(camera), m_noise_generator(noise_generator) {
    Frame& f = m_frame;
    f.camera = &m_camera;
    f.location = camera.location;
    f.direction = camera.direction;
    f.right = camera.right;
    f.up = camera.up;
    f.right_length = length(camera.right);
    f.up_length = length(camera.up);
    auto unit = [](const Vec3& v) { return length(v) > 0.0 ? normalize(v) : v; };
    f.unit_direction = unit(camera.direction);
    f.unit_right = unit(camera.right);
    f.unit_up = unit(camera.up);
    f.width = width;
    f.height = height;
    m_project = k_projections[static_cast<int>(camera.type)];
    if (camera.type == scene::Camera::Type::MeshCamera) {
        m_mesh = std::make_unique<MeshCamera>(camera.mesh_camera);
        f.mesh = m_mesh.get();
    }
    // POV-Ray compat (FocalBlurData): the lens's x axis is up × direction, its y axis direction × x.
    m_x_perp = unit(cross(camera.up, camera.direction));
    m_y_perp = unit(cross(camera.direction, m_x_perp));
}

std::optional<geometry::Ray> CameraModel::ray(double px, double py) const {
    ProjectedRay r;
    if (!m_project(m_frame, px, py, r)) return std::nullopt;
    return finish(r);
}

std::optional<geometry::Ray> CameraModel::ray(double px, double py, int ray_number) const {
    if (!m_mesh || ray_number == 0) return ray(px, py);
    ProjectedRay r;
    if (!m_mesh->ray(m_frame, px, py, ray_number, r)) return std::nullopt;
    return finish(r);
}

std::optional<geometry::Ray> CameraModel::ray(double px, double py, double lens_x, double lens_y) const {
    ProjectedRay r;
    if (!m_project(m_frame, px, py, r)) return std::nullopt;
    // POV-Ray compat (JitterCameraRay): the eye moves across the aperture and the ray turns back towards the
    // point it would reach at the focal distance; the eye starts from the camera's location for every type.
    const double half = 0.5 * m_camera.aperture;
    const Vec3 deflection = m_x_perp * (half * lens_x) - m_y_perp * (half * lens_y);
    const double focal = m_camera.focal_distance / length(m_camera.direction);
    r.origin = m_camera.location + deflection;
    r.direction = normalize(r.direction * focal - deflection);
    return finish(r);
}

namespace {

// POV-Ray compat (VNormalize): scaled by the reciprocal of the length, not divided by it, which rounds differently.
Vec3 pov_normalize(const Vec3& v) {
    const double len = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    if (!(len > 0.0)) return Vec3{};
    const double inv = 1.0 / len;
    return {v.x * inv, v.y * inv, v.z * inv};
}

}  // namespace

std::optional<geometry::Ray> CameraModel::finish(ProjectedRay& r) const {
    Vec3 direction = pov_normalize(r.direction);
    // POV-Ray compat: the camera normal tilts the direction as a surface normal at (x0, y0, 0), the projection's
    // own image coordinates.
    if (m_camera.normal)
        direction = texture::perturb_normal(*m_camera.normal, direction, Vec3{r.x0, r.y0, 0.0}, m_noise_generator);
    if (!is_finite(direction)) return std::nullopt;
    geometry::Ray ray;
    ray.origin = r.origin;
    ray.direction = direction;
    ray.t_min = 0.0;
    ray.kind = geometry::RayKind::Camera;
    return ray;
}

bool CameraModel::project(const Vec3& p, double& px, double& py) const {
    const bool ortho = m_camera.type == scene::Camera::Type::Orthographic;
    if (!ortho && m_camera.type != scene::Camera::Type::Perspective) return false;
    // Solve p − location = a·right + b·up + c·direction (Cramer's rule): ray() maps (a/c, b/c) for a perspective
    // camera and (a, b) for an orthographic one to image position.
    const Vec3& r = m_camera.right;
    const Vec3& u = m_camera.up;
    const Vec3& d = m_camera.direction;
    const double det = dot(r, cross(u, d));
    if (!(std::fabs(det) > 0.0)) return false;
    const Vec3 q = p - m_camera.location;
    const double a = dot(q, cross(u, d)) / det;
    const double b = dot(r, cross(q, d)) / det;
    const double c = dot(r, cross(u, q)) / det;
    if (!(c > 0.0)) return false;
    const double x0 = ortho ? a : a / c;
    const double y0 = ortho ? b : b / c;
    px = (x0 + 0.5) * m_frame.width;
    py = (0.5 - y0) * m_frame.height;
    return std::isfinite(px) && std::isfinite(py);
}

}  // namespace wardray::camera
