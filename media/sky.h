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
    /// The same for a ray that sees the background as transparent (Output_Alpha, +UA: camera rays and the rays
    /// they refract or transmit): the colour with the background behind it counted as black, and in `transmit`
    /// how much of the background shows through (POV-Ray's associated alpha, ComputeSky).
    Vec3 radiance_with_alpha(const Vec3& direction, double& transmit) const;

private:
    const scene::SkySphere* m_sphere = nullptr;  ///< null when the scene has no sky_sphere
    Color m_background;  ///< POV-Ray compat: a 3.7 background is precomposed over black, rgb · (1 − transmit)
    Color m_alpha_background;  ///< the background as +UA sees it: <0,0,0,0,1> unless a 3.7 scene gave one
    bool m_legacy = false;     ///< the scene's effective version is below 3.7
    int m_noise_generator = 2;
};

}  // namespace wardray::media
