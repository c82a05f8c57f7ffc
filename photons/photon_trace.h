// PhotonTracer: one photon's path through the scene as POV-Ray 3.7's PhotonTrace follows it: to the target
// (through pass_through objects), through its layers' refraction and reflection, stored where it lands.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "photons/dispersion.h"
#include "photons/photon_map.h"
#include "scene/scene.h"

namespace wardray::media {
class ParticipatingMedia;
}  // namespace wardray::media

namespace wardray::geometry {
class SceneGeometry;
struct Hit;
}  // namespace wardray::geometry

namespace wardray::photons {

/// The light and target a photon is shot for, and the spread that sizes its stored flux.
struct ShotUnit {
    const scene::Light* light = nullptr;
    const std::vector<const scene::Object*>* parts = nullptr;  ///< every object of the target's tree
    double spread = 0.0;   ///< POV-Ray's photonSpread: the angle (or, parallel, the distance) between photons
    bool parallel = false;
    /// The objects that contain the light's position (the ray starts inside them), for photons that start there.
    const std::vector<const scene::Object*>* light_interiors = nullptr;
};

/// The objects of `scene` that contain `p` (POV-Ray starts a photon's ray inside them).
std::vector<const scene::Object*> objects_containing(const scene::Scene& scene, const Vec3& p);

/// Traces photons; stateless, so one instance serves every thread.
class PhotonTracer {
public:
    /// `seed` is the render seed (--seed), which turns the jitter of media deposits; `spacing` the photons' (it
    /// sets the maps' flux_exponent_offset).
    PhotonTracer(const scene::Scene& scene, const geometry::SceneGeometry& geometry, std::uint64_t seed = 0,
                 double spacing = 1.0);

    PhotonTracer(const PhotonTracer&) = delete;
    PhotonTracer& operator=(const PhotonTracer&) = delete;
    ~PhotonTracer();

    /// Follows a photon of `colour` from `origin` along the unit `dir`, appending what it stores on surfaces to
    /// `out` and in media to `media_out`; true when it reached the unit's target (POV-Ray's hitObject, for
    /// autostop).
    bool shoot(const ShotUnit& unit, const Vec3& origin, const Vec3& dir, const Vec3& colour, std::vector<Photon>& out,
               std::vector<Photon>& media_out) const;

    /// The power of two the surface and the media photons are stored divided by (flux_exponent_offset).
    int surface_offset() const { return m_surface_offset; }
    int media_offset() const { return m_media_offset; }

private:
    struct Path;
    struct RayIn {
        Vec3 origin, dir;
        /// The interiors the ray is inside, innermost last, each named by an object that has it (as
        /// lighting::InteriorStack).
        std::vector<const scene::Object*> interiors;
        /// The photon's spectral band once a dispersive surface has split it (white light before).
        SpectralBand band;
    };
    /// POV-Ray's PhotonTrace::TraceRay.
    void trace(const RayIn& ray, Vec3 colour, double weight, Path& path) const;
    /// POV-Ray's ComputeTextureColour and ComputeOneTextureColour in the photon pass: texture maps split the photon.
    void texture(const scene::Texture& tx, const Vec3& p, std::vector<const scene::Pattern*>& warps,
                 const geometry::Hit& hit, const Vec3& raw_normal, const RayIn& ray, Vec3 colour, double weight,
                 Path& path) const;
    /// POV-Ray's PhotonTrace::ComputeLightedTexture: store, then refract and reflect.
    void surface(const scene::Texture& tx, const Vec3& p, const std::vector<const scene::Pattern*>& warps,
                 const geometry::Hit& hit, const Vec3& raw_normal, const RayIn& ray, Vec3 colour, double weight,
                 Path& path) const;
    /// POV-Ray's ComputeRefractionForPhotons; true on total internal reflection.
    bool refract(const geometry::Hit& hit, const Vec3& normal, const Vec3& raw_normal, const RayIn& ray,
                 const Vec3& colour, const Vec3& filter, double weight, Path& path) const;
    /// POV-Ray's TraceRefractionRayForPhotons: `next` bent by the relative index `ior`; true on total internal
    /// reflection, which reflects the incoming `ray` instead.
    bool refract_ray(const geometry::Hit& hit, const Vec3& normal, const Vec3& raw_normal, const RayIn& ray,
                     RayIn& next, double ior, const Vec3& colour, const Vec3& filter, double weight, Path& path) const;
    /// The media of the interiors the ray is in, between its origin and `hit`: they dim the photon and, past its
    /// first bounce with `media` in the photons block, keep photons along the way (ComputeLightedTexture's media).
    void through_media(const geometry::Hit& hit, const RayIn& ray, Vec3& colour, Path& path) const;
    /// POV-Ray's ComputeReflection for a photon.
    void reflect(const geometry::Hit& hit, const Vec3& normal, const Vec3& raw_normal, const RayIn& ray,
                 const Vec3& colour, double weight, Path& path) const;

    const scene::Scene& m_scene;
    const geometry::SceneGeometry& m_geometry;
    std::unique_ptr<const media::ParticipatingMedia> m_media;  ///< null when the scene has no media
    int m_max_level = 5;
    double m_bailout = 1.0 / 255.0;
    int m_noise_generator = 2;
    int m_surface_offset = 0;
    int m_media_offset = 0;
};

}  // namespace wardray::photons
