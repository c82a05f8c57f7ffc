// CameraModel: primary rays through pixels, as POV-Ray 3.7 places them.
#pragma once

#include <memory>
#include <optional>

#include "camera/mesh_camera.h"
#include "camera/projections.h"
#include "geometry/scene_geometry.h"
#include "scene/scene.h"

namespace wardray::camera {

/// Makes the camera ray through an image position (pixel units, origin at the top-left corner).
class CameraModel {
public:
    CameraModel(const scene::Camera& camera, int width, int height, int noise_generator = 2);
    CameraModel(const CameraModel&) = delete;  // its frame points at its own copy of the camera
    CameraModel& operator=(const CameraModel&) = delete;

    /// The ray through image position (px, py); pixel (x, y)'s centre is (x + 0.5, y + 0.5). Nothing where the
    /// projection traces no ray (POV-Ray leaves such a sample black).
    std::optional<geometry::Ray> ray(double px, double py) const;
    /// Sample `ray_number` of the camera's rays per pixel through (px, py) (mesh_camera; others have one).
    std::optional<geometry::Ray> ray(double px, double py, int ray_number) const;
    /// How many rays POV-Ray traces and averages per image position (mesh_camera's first number; else 1).
    int rays_per_pixel() const { return m_mesh ? m_mesh->rays_per_pixel() : 1; }
    /// The same through the lens point (lens_x, lens_y) of focal blur, each in [-0.5, 0.5] of the aperture's
    /// half-width (POV-Ray's sample grid).
    std::optional<geometry::Ray> ray(double px, double py, double lens_x, double lens_y) const;
    /// The image position (pixel units) where the world point `p` appears; false when it is behind the camera
    /// or the projection is not planar.
    bool project(const Vec3& p, double& px, double& py) const;
    const scene::Camera& camera() const { return m_camera; }

private:
    std::optional<geometry::Ray> finish(ProjectedRay& r) const;

    scene::Camera m_camera;
    Frame m_frame;
    ProjectFn m_project;
    std::unique_ptr<MeshCamera> m_mesh;
    int m_noise_generator;
    Vec3 m_x_perp, m_y_perp;  ///< focal blur: the lens's axes, perpendicular to the direction of view
};

}  // namespace wardray::camera
