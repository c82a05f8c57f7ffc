// Sky: what a ray that leaves the scene sees, POV-Ray's sky_sphere over the background colour.
#pragma once

#include "scene/scene.h"

namespace wardray::media {

/// The radiance of the sky by direction (POV-Ray's ComputeSky). Refers to the scene, which must outlive it.
class Sky {
public:
    /// The scene's background and sky_sphere, its pigments evaluated with the scene's noise generator.
    explicit Sky(const scene::Scene& scene);

    /// Linear RGB radiance arriving from the unit `direction`.
    Vec3 radiance(const Vec3& direction) const;

private:
    const scene::SkySphere* m_sphere = nullptr;  ///< null when the scene has no sky_sphere
    Color m_background;
    int m_noise_generator = 2;
};

}  // namespace wardray::media
