// CameraModel: primary rays through pixels, as POV-Ray 3.7 places them.
#pragma once

#include "geometry/scene_geometry.h"
#include "scene/scene.h"

namespace wardray::camera {

/// Makes the camera ray through an image position (pixel units, origin at the top-left corner).
class CameraModel {
public:
    CameraModel(const scene::Camera& camera, int width, int height);

    /// The ray through image position (px, py); pixel (x, y)'s centre is (x + 0.5, y + 0.5).
    geometry::Ray ray(double px, double py) const;
    /// The image position (pixel units) where the world point `p` appears; false when it is behind the camera.
    bool project(const Vec3& p, double& px, double& py) const;

private:
    scene::Camera m_camera;
    double m_width;
    double m_height;
};

}  // namespace wardray::camera
