// Integrator: the colour seen along a ray, from POV-Ray 3.7's lighting model (direct light, textures, reflection,
// refraction, transparency, sky and fog).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "scene/scene.h"
#include "core/vec3.h"

namespace wardray::geometry {
class SceneGeometry;
struct Ray;
struct Hit;
}  // namespace wardray::geometry

namespace wardray::cache {
class TileCache;
}  // namespace wardray::cache

namespace wardray::lighting {

/// How indirect light is computed (`--gi`).
enum class GiMode { Off, Cache, Reference };

/// Rays traced, by kind, for --stats. Each thread keeps its own and the totals are summed.
struct RayCounters {
    std::uint64_t camera = 0;
    std::uint64_t shadow = 0;
    std::uint64_t secondary = 0;  ///< reflected, refracted and transmitted rays
    std::uint64_t gather = 0;     ///< hemisphere rays for indirect light (cache gathers and reference paths)
    std::uint64_t gathers = 0;    ///< hemisphere gathers made (new cache records, or reference estimates)

    RayCounters& operator+=(const RayCounters& o) {
        camera += o.camera;
        shadow += o.shadow;
        secondary += o.secondary;
        gather += o.gather;
        gathers += o.gathers;
        return *this;
    }
};

struct IntegratorOptions {
    GiMode gi = GiMode::Off;
    int reference_rays = 256;  ///< --gi-rays: paths per pixel in reference mode
    bool gradients = true;     ///< --gi-gradients: cache records keep and use their gradients
    /// The pixel footprint per unit distance from the camera (image-plane width of one pixel over the focal
    /// length): cache record radii stay at least one footprint wide; 0 leaves the bound out.
    double footprint = 0.0;
};

/// What one worker carries through the ray recursion of one tile: its counters and its view of the cache.
struct TraceContext {
    RayCounters rays;
    cache::TileCache* cache = nullptr;  ///< the tile's view of the irradiance cache (cache mode only)
    bool final_pass = true;             ///< false in POV-Ray's pretrace passes
    /// The next cache gather's seed: set per tile and pass by the renderer and stepped by each gather, so a record's
    /// samples depend on the order the tile makes records in (fixed), not on its position: a scene scaled by any
    /// factor then draws the same samples.
    std::uint64_t gather_seed = 0;
    /// --aov irradiance: the indirect irradiance first computed on the current camera path lands here.
    bool capture_irradiance = false;
    bool captured = false;
    Vec3 irradiance;
};

/// The interiors a ray is inside, innermost last (POV-Ray's ray interior list), by object index.
struct InteriorStack {
    static constexpr int kMax = 16;
    std::array<std::uint32_t, kMax> objects{};
    int size = 0;

    bool contains(std::uint32_t o) const;
    void push(std::uint32_t o);
    bool remove(std::uint32_t o);
};

/// What travels with a ray through the recursion: POV-Ray's trace level, weight (for adc_bailout) and interiors.
struct RayState {
    int level = 0;
    int max_level = 5;    ///< POV-Ray's max_trace_level, raised for gathers so they always see one surface
    double weight = 1.0;
    double adc_bailout = 0.0;  ///< POV-Ray's ticket bailout: the scene's, or radiosity's inside a gather
    int gi_depth = 0;          ///< radiosity bounce depth: 0 for camera paths, +1 per gather
    bool gather_ray = false;   ///< on a gather ray's path: highlights are left out (POV-Ray compat)
    std::uint64_t path_seed = 0;  ///< reference mode: tells the independent paths of one pixel apart
    InteriorStack interiors;
};

/// Shades rays against a built scene. Stateless after construction, so one instance serves every thread.
class Integrator {
public:
    Integrator(const scene::Scene& scene, const geometry::SceneGeometry& geometry, IntegratorOptions options);

    /// Linear RGB radiance arriving along a camera ray (the background where it hits nothing).
    Vec3 trace_camera_ray(const geometry::Ray& ray, TraceContext& ctx) const;

    /// True when indirect light goes through an irradiance cache that the renderer must fill in passes.
    bool uses_cache() const { return m_gi_enabled && m_options.gi == GiMode::Cache; }

    /// Warnings about what this integrator leaves out of the picture (reported once per render).
    const std::vector<std::string>& limitations() const { return m_limitations; }

private:
    /// Where a texture is being shaded: the surface point, its normals and the ray that found it.
    struct Surface {
        const geometry::Hit* hit = nullptr;
        const scene::Object* object = nullptr;  ///< the primitive hit (its texture applies)
        Vec3 p_texture;                           ///< the point textures are evaluated at (enclosing space)
        Vec3 raw_normal;                          ///< unit, turned to face the incoming ray
        Vec3 direction;                           ///< unit direction of the incoming ray
        double depth = 0.0;                       ///< distance from the ray's origin
        const InteriorStack* interiors = nullptr;  ///< the interiors the incoming ray is in
        /// POV-Ray compat: false on gather rays' paths, which see no phong or specular and area lights as points.
        bool highlights = true;
    };

    /// POV-Ray's TraceRay: the colour along `ray` (level and weight checks, surface or sky, then fog);
    /// `hit_distance`, when given, receives the distance to the surface hit (+infinity for none).
    Vec3 trace(const geometry::Ray& ray, const RayState& state, bool continued, TraceContext& ctx,
               double* hit_distance = nullptr) const;
    /// POV-Ray's ComputeAmbient: the indirect irradiance at the surface for the normal `n_layer` (used when the
    /// radiosity block says `normal on`), times brightness and mixed toward grey by gray_threshold.
    Vec3 indirect(const Surface& s, const Vec3& n_layer, double weight, const RayState& state,
                  TraceContext& ctx) const;
    /// Cache mode: interpolate from the tile's cache view, or gather a new record when too few are valid.
    Vec3 cached_irradiance(const Vec3& p, const Vec3& n, double weight, const RayState& state,
                           TraceContext& ctx) const;
    /// Reference mode: a Monte Carlo estimate, many rays at the first bounce and one per path deeper.
    Vec3 reference_irradiance(const Vec3& p, const Vec3& n, const RayState& state, TraceContext& ctx) const;
    /// The radiance arriving at `p` along the gather direction `dir`, traced as POV-Ray's radiosity rays are.
    Vec3 gather_radiance(const Vec3& p, const Vec3& dir, const RayState& state, std::uint64_t path_seed,
                         TraceContext& ctx, double& distance) const;
    /// The colour of the surface at `hit`, `depth` along the unit `direction`.
    Vec3 shade(const geometry::Hit& hit, const Vec3& direction, double depth, const RayState& state,
               TraceContext& ctx) const;
    /// POV-Ray's ComputeOneTextureColour: a texture_map blends the lit colours of its entries.
    Vec3 shade_texture(const scene::Texture& texture, Surface s, std::vector<const scene::Pattern*>& warps,
                       const RayState& state, TraceContext& ctx) const;
    /// POV-Ray's ComputeLightedTexture: the layers of a plain texture, then refraction and reflection.
    Vec3 shade_layers(const scene::Texture& texture, const Surface& s, const std::vector<const scene::Pattern*>& warps,
                      const RayState& state, TraceContext& ctx) const;
    /// Direct light from every source on one layer (diffuse scaled by `opacity`, highlights not).
    Vec3 direct_light(const scene::Finish& finish, const Vec3& pigment, double opacity, const Surface& s,
                      const Vec3& n, TraceContext& ctx) const;
    /// The light arriving at `p` from `light` through whatever stands between: colour times attenuation times the
    /// filter colour of transparent blockers; zero when blocked or behind the surface (cos below EPSILON). With
    /// `area_lights` false an area light counts as a point light at its centre.
    Vec3 light_arriving(const scene::Light& light, const Vec3& p, const Vec3& n, const InteriorStack& interiors,
                        bool area_lights, Vec3& to_light, TraceContext& ctx) const;
    /// The transmittance from `p` towards a light `distance` away along the unit `dir`: 0 or 1 when every object is
    /// opaque, else the filter colours of what stands between (shadow_filter).
    Vec3 shadow_towards(const Vec3& p, const Vec3& dir, double distance, const InteriorStack& interiors,
                        TraceContext& ctx) const;
    /// POV-Ray's area light shadow: `colour` (taken at the light's centre) times the adaptive average of the shadow
    /// towards the points of the light's grid.
    Vec3 area_light_shadow(const scene::Light& light, const Vec3& colour, const Vec3& p,
                           const InteriorStack& interiors, TraceContext& ctx) const;
    /// Transmittance of the shadow ray from `p` along `dir` up to `distance` (POV-Ray multiplies the filter colour
    /// of every surface it crosses).
    /// `interiors` are those of the ray that found `p` (POV-Ray starts the shadow ray with them and fades light
    /// crossing an interior).
    Vec3 shadow_filter(const Vec3& p, const Vec3& dir, double distance, InteriorStack interiors,
                       TraceContext& ctx) const;
    /// The filter colour of an object's texture at a point (its layers' filter·colour + transmit, multiplied).
    Vec3 texture_filter(const scene::Texture& texture, const Vec3& p) const;
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
    /// POV-Ray's ComputeSky: sky_sphere pigments over the background colour.
    Vec3 sky(const Vec3& direction) const;
    /// POV-Ray's constant fog over a ray segment of length `depth`.
    Vec3 apply_fog(const Vec3& colour, double depth) const;

    const scene::Scene& m_scene;
    const geometry::SceneGeometry& m_geometry;
    IntegratorOptions m_options;
    bool m_ambient_is_light = true;
    bool m_gi_enabled = false;  ///< the scene has a radiosity block and --gi is not off
    bool m_any_transparent = false;  ///< some object can let light through (filter or transmit somewhere)
    std::vector<std::uint8_t> m_opaque;  ///< per top-level object: its textures never filter or transmit
    int m_noise_generator = 2;
    InteriorStack m_camera_interiors;  ///< the objects the camera is inside: camera rays start in them
    std::vector<std::string> m_limitations;
};

}  // namespace wardray::lighting
