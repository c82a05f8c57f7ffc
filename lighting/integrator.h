// Integrator: the colour seen along a ray, from POV-Ray 3.7's lighting model (textures, finishes, reflection,
// refraction, transparency), reaching light sources, indirect light and the atmosphere through their own classes.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/vec3.h"
#include "lighting/indirect_light.h"
#include "lighting/light_sampler.h"
#include "lighting/path_guide.h"
#include "lighting/quality.h"
#include "lighting/trace_context.h"
#include "media/medium.h"
#include "media/rainbow.h"
#include "media/participating_media.h"
#include "media/sky.h"
#include "scene/scene.h"
#include "texture/surface_point.h"

namespace wardray::geometry {
class SceneGeometry;
struct Ray;
struct Hit;
}  // namespace wardray::geometry

namespace wardray::photons {
class PhotonMap;
class MediaPhotonGather;
struct Gathered;
struct PhotonStats;
struct ShotPhotons;
}  // namespace wardray::photons

namespace wardray::lighting {

/// How indirect light is computed (`--gi`).
enum class GiMode { Off, Cache, Reference };

/// How the integrator computes indirect light, from the command line.
struct IntegratorOptions {
    GiMode gi = GiMode::Off;
    int reference_rays = 256;  ///< --gi-rays: paths per pixel in reference mode
    /// --seed: turns every random stream the integrator draws (reference paths, area-light jitter, crand, media,
    /// rainbows, photons); 0 draws those of a render without it (core/render_seed.h).
    std::uint64_t seed = 0;
    /// --gi-path-seed: the reference paths' seed alone (nothing: `seed`), so that two references can differ in their
    /// paths and nothing else (the camera hits' area-light jitter of --gi-area-lights=grid stays `seed`'s).
    std::optional<std::uint64_t> path_seed;
    bool gradients = true;     ///< --gi-gradients: cache records keep and use their gradients
    bool gradient_cap = true;  ///< --gi-gradient-cap: with gradients, a record's radius ≤ E/|∇t E|
    bool hessian_spacing = true;  ///< --gi-spacing: with gradients, record radii from the Hessian (else harmonic)
    bool adaptive_gather = false;  ///< --gi-adaptive: part of each gather's rays where its strata differ most
    bool geometry_floor = true;    ///< --gi-reuse-floor=geometry: with gradients, radii below minimum_reuse near geometry
    /// --gi-lookup-sampling: at gather rays' hits one lookup in this many, the others the cache's ambient estimate
    /// (1: every hit looks up; the cache must keep its ambient grids otherwise).
    int lookup_sampling = 1;
    /// The pixel footprint per unit distance from the camera (image-plane width of one pixel over the focal
    /// length): cache record radii stay at least one footprint wide; 0 leaves the bound out.
    double footprint = 0.0;
    /// Where camera rays start, for finding the objects they start inside, when that is not the camera's
    /// location (mesh_camera: its first ray's origin on the camera mesh); nothing: the camera's location.
    std::optional<Vec3> camera_origin;
    /// Output_Alpha (+UA): camera rays see the background as transparent, and the transmit of what they see is
    /// left in TraceContext::transmit (1 − alpha).
    bool output_alpha = false;
    /// +Q: POV-Ray's quality level, 0..11 (lighting/quality.h); 9 and above render everything.
    int quality = 9;
    /// The photons of a photon `load_file`, built into the maps instead of shooting (null: shoot).
    std::shared_ptr<const photons::ShotPhotons> photons_from_file;
    /// Keep what the photon pass stored, for a photon `save_file` (shot_photons()).
    bool keep_shot_photons = false;
    /// On gather rays' paths: the lights tested with a shadow ray at each hit, picked by their unshadowed light
    /// (light_choice.h); 0 tests every light, as the camera's hits always do.
    int gather_light_picks = 1;
    /// Reference mode: jittered area lights at camera hits are sampled on a fine jittered grid (about reference_rays
    /// points shared among them) so that their jitter converges with the paths; false (--gi-area-lights=grid) keeps
    /// POV-Ray's own grid, jittered as the cache mode jitters it, so the reference converges the cache's image.
    bool fine_area_lights = true;
    /// Reference mode (--gi-guide): every bounce also samples where a pilot pass found the light coming from
    /// (learn_guide, path_guide.h); false samples the cosine alone.
    bool guide_paths = true;
};

/// Shades rays against a built scene. Stateless after construction, so one instance serves every thread; it
/// refers to the scene and geometry, which must outlive it, and is neither copied nor moved.
class Integrator final : private GatherTracer {
public:
    /// Prepares the light sources, indirect light (when the scene has radiosity and --gi is not off), the sky and
    /// the atmosphere, and finds the objects the camera is inside.
    Integrator(const scene::Scene& scene, const geometry::SceneGeometry& geometry, IntegratorOptions options);
    ~Integrator() override;
    Integrator(const Integrator&) = delete;
    Integrator& operator=(const Integrator&) = delete;

    /// Linear RGB radiance arriving along a camera ray (the background where it hits nothing).
    Vec3 trace_camera_ray(const geometry::Ray& ray, TraceContext& ctx) const;

    /// True when the reference's paths are to be guided: pilot() and learn_guide() must run before the render.
    bool wants_guide() const { return m_guide != nullptr; }
    /// The pilot's camera rays: a grid of kPilotGrid x kPilotGrid positions over the image.
    static constexpr int kPilotGrid = 64;
    /// Paths per pilot camera ray for a render of `pixels` pixels and `rays` paths each: an eighth of the render's
    /// paths over the grid, from 1 to 1024 a ray (at most 4.2 M paths, about 300 MB of vertices).
    static int pilot_paths(long long pixels, int rays);
    /// Reference mode's pilot (cosine-sampled, its own random streams): traces `paths` paths from where `ray`
    /// first hits and appends what each of their vertices received to `samples`. Safe to call from any thread.
    void pilot(const geometry::Ray& ray, int paths, std::vector<GuideSample>& samples) const;
    /// Learns the guide from the pilot's samples (path_guide.h): the same samples in the same order, the same
    /// guide, so the image depends on the scene, the seed, the size and the paths, not on threads.
    void learn_guide(const std::vector<GuideSample>& samples);

    /// True when indirect light goes through an irradiance cache that the renderer must fill in passes.
    bool uses_cache() const { return m_indirect && m_options.gi == GiMode::Cache; }

    /// Warnings about what this integrator leaves out of the picture (reported once per render).
    const std::vector<std::string>& limitations() const { return m_limitations; }

    /// What the photon pass did (null without photons in the scene).
    const photons::PhotonStats* photon_stats() const { return m_photon_stats.get(); }
    /// What the photon pass stored, when keep_shot_photons asked for it (else null).
    const photons::ShotPhotons* shot_photons() const { return m_shot_photons.get(); }

private:
    /// Where a texture is being shaded: the surface point, its normals and the ray that found it.
    struct Surface {
        const geometry::Hit* hit = nullptr;
        const scene::Object* object = nullptr;  ///< the primitive hit (its texture applies)
        Vec3 p_texture;                           ///< the point textures are evaluated at (enclosing space)
        Vec3 p_uv;                                ///< the surface's (u, v, 0), for uv_mapping
        Vec3 raw_normal;                          ///< unit, turned to face the incoming ray
        Vec3 direction;                           ///< unit direction of the incoming ray
        double depth = 0.0;                       ///< distance from the ray's origin
        const InteriorStack* interiors = nullptr;  ///< the interiors the incoming ray is in
        /// What slope and aoi read: shared by the copies made for map entries, its normal tilted by each layer's
        /// normal as POV-Ray's PNormal is.
        texture::SurfacePoint* surface = nullptr;
        /// POV-Ray compat: false on gather rays' paths, which see no phong or specular and area lights as points.
        bool highlights = true;
        /// The path's seed (RayState::path_seed), from which a gather path picks the lights it tests.
        std::uint64_t path_seed = 0;
        /// A reference path's place in its pixel's sequence (RayState's path fields and bounce depth), from which
        /// the light it picks here is drawn.
        struct {
            std::uint64_t group = 0;
            int index = 0;
            int count = 0;  ///< 0: not a reference path
            int gi_depth = 0;
        } path;
    };

    /// POV-Ray's TraceRay: the colour along `ray` (level and weight checks, surface or sky, then the atmosphere);
    /// `hit_distance`, when given, receives the distance to the surface hit (+infinity for none).
    Vec3 trace(const geometry::Ray& ray, const RayState& state, bool continued, TraceContext& ctx,
               double* hit_distance = nullptr) const;
    /// POV-Ray's ComputeAmbient: the indirect irradiance at the surface for the normal `n_layer` (used when the
    /// radiosity block says `normal on`), times brightness and mixed toward grey by gray_threshold.
    Vec3 indirect(const Surface& s, const Vec3& n_layer, double weight, const RayState& state,
                  TraceContext& ctx) const;
    /// POV-Ray's GatherLight, for the indirect light: one gather ray traced from `p` along `dir`.
    Vec3 gather_radiance(const Vec3& p, const Vec3& dir, const RayState& state, std::uint64_t path_seed,
                         TraceContext& ctx, double& distance) const override;
    /// POV-Ray's media on one ray: the interiors' media (when the ray reached a surface) and then the atmosphere's,
    /// each only on a ray inside no non-hollow object (media_hook.cpp).
    Vec3 apply_media(const geometry::Ray& ray, const Vec3& direction, double depth, bool hit, const RayState& state,
                     const Vec3& colour, TraceContext& ctx) const;
    /// The colour of the surface at `hit`, `depth` along the unit `direction`.
    Vec3 shade(const geometry::Hit& hit, const Vec3& direction, double depth, const RayState& state,
               TraceContext& ctx) const;
    /// POV-Ray's ComputeOneTextureColour: a texture_map blends the lit colours of its entries.
    Vec3 shade_texture(const scene::Texture& texture, Surface s, std::vector<const scene::Pattern*>& warps,
                       const RayState& state, TraceContext& ctx) const;
    /// POV-Ray's ComputeAverageTextureColours: an `average` texture_map's entries weighted by their values.
    Vec3 shade_average(const scene::Texture& texture, const Surface& s, std::vector<const scene::Pattern*>& warps,
                       const RayState& state, TraceContext& ctx) const;
    /// POV-Ray's ComputeLightedTexture: the layers of a plain texture, then refraction and reflection.
    Vec3 shade_layers(const scene::Texture& texture, const Surface& s, const std::vector<const scene::Pattern*>& warps,
                      const RayState& state, TraceContext& ctx) const;
    /// Direct light from every source on one layer (diffuse scaled by `opacity`, highlights not).
    Vec3 direct_light(const scene::Finish& finish, const Vec3& pigment, double opacity, const Surface& s,
                      const Vec3& n, TraceContext& ctx) const;
    /// direct_light on a gather ray's path: the lights that need shadow rays are picked by their unshadowed light
    /// and the picked ones divided by their chance (light_choice.cpp), so the expectation is every light's sum.
    Vec3 direct_light_picked(const scene::Finish& finish, const Vec3& pigment, double opacity, const Surface& s,
                             const Vec3& n, TraceContext& ctx) const;
    /// One light's diffuse and (with `highlights`) phong, specular and iridescence on one layer, for the light
    /// `arriving` from the unit direction `to_light`; `grain_from` seeds crand's graininess.
    Vec3 finish_light(const scene::Finish& finish, const Vec3& pigment, double opacity, const Surface& s,
                      const Vec3& n, const Vec3& to_light, const Vec3& arriving, bool highlights,
                      const Vec3& grain_from) const;
    /// POV-Ray's ComputePhotonDiffuseLight: the gathered photons lighting one layer like lights of their
    /// direction, each undoing the cosine it landed at, over the area π r² they were gathered from.
    Vec3 photon_light(const scene::Finish& finish, const Vec3& pigment, double opacity, const Surface& s,
                      const Vec3& n, const photons::Gathered& gathered) const;
    /// A reflected ray's colour (POV-Ray's ComputeReflection, with its fix-ups for bumped normals).
    Vec3 reflect(const Surface& s, const Vec3& n, double weight, const scene::Finish& finish, const RayState& state,
                 TraceContext& ctx) const;
    /// POV-Ray's ComputeIridColour: the thin-film interference factor for light arriving along `to_light` and
    /// leaving toward the viewer along −`view_dir`.
    Vec3 iridescence(const scene::Finish& finish, const Vec3& to_light, const Vec3& view_dir, const Vec3& n,
                     const Vec3& p) const;
    /// A refracted or transmitted ray's colour; sets `total_internal` when the ray reflects instead.
    Vec3 refract(const Surface& s, const Vec3& n, double weight, const scene::Finish& finish, const RayState& state,
                 bool& total_internal, TraceContext& ctx) const;
    /// The ray `next` bent by the relative index `ior` (POV-Ray's TraceRefractionRay); total internal reflection
    /// reflects the incoming ray of `state` instead and sets `total_internal`.
    Vec3 refract_ray(const Surface& s, const Vec3& n, double ior, double weight, const scene::Finish& finish,
                     const RayState& state, RayState& next, bool& total_internal, TraceContext& ctx) const;
    /// POV-Ray's refraction with dispersion: white light split into `bands` spectral bands, each bent by its own
    /// index (`ior` spread by the relative `dispersion`), carrying its band on, weighted by its hue.
    Vec3 refract_dispersive(const Surface& s, const Vec3& n, double ior, double dispersion, int bands, double weight,
                            const scene::Finish& finish, const RayState& state, RayState& next,
                            TraceContext& ctx) const;

    const scene::Scene& m_scene;
    const geometry::SceneGeometry& m_geometry;
    IntegratorOptions m_options;
    QualityFeatures m_quality;
    LightSampler m_lights;
    std::unique_ptr<PathGuide> m_guide;  ///< reference mode with guide_paths: the guide its paths read
    std::unique_ptr<const IndirectLight> m_indirect;  ///< null without a radiosity block or with --gi=off
    media::Sky m_sky;
    std::unique_ptr<const media::Medium> m_atmosphere;  ///< null when the scene has no fog
    std::unique_ptr<const media::Rainbows> m_rainbows;  ///< null when the scene has no rainbow
    bool m_volume_on_gathers = false;  ///< radiosity `media on`: gather rays see fog and rainbows too
    std::unique_ptr<const media::ParticipatingMedia> m_media;  ///< null when the scene has no media
    bool m_ambient_is_light = true;
    int m_noise_generator = 2;
    std::unique_ptr<const photons::PhotonMap> m_photons;  ///< null without photons, or when none were stored
    std::unique_ptr<const photons::PhotonMap> m_media_photons;  ///< the photons kept in media, or null
    std::unique_ptr<const photons::MediaPhotonGather> m_media_gather;  ///< reads m_media_photons for media/
    std::unique_ptr<photons::PhotonStats> m_photon_stats;
    std::unique_ptr<const photons::ShotPhotons> m_shot_photons;  ///< kept for a photon save_file
    InteriorStack m_camera_interiors;  ///< the objects the camera is inside: camera rays start in them
    std::vector<std::string> m_limitations;
};

}  // namespace wardray::lighting
