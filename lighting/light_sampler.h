// LightSampler: the light arriving at a point from one light source, through shadows and area-light grids.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "lighting/trace_context.h"
#include "media/medium.h"
#include "media/participating_media.h"
#include "scene/scene.h"
#include "texture/surface_point.h"

namespace wardray::geometry {
class SceneGeometry;
}  // namespace wardray::geometry

namespace wardray::lighting {

/// What dims a shadow ray between surfaces: the fog and, when `media`, the atmosphere's media.
struct ShadowAtmosphere {
    const media::Medium* fog = nullptr;
    bool media = false;
    bool any() const { return fog != nullptr || media; }
};
class ProjectedThrough;

/// POV-Ray 3.7's light sources: attenuation (spot, cylinder, fade), filtered shadows and adaptive area lights.
/// Stateless after construction; refers to the scene and its geometry, which must outlive it.
class LightSampler {
public:
    /// Notes which objects can let light through, so shadow rays look through only those. `seed` is the render
    /// seed (--seed), which turns area-light and media jitter.
    LightSampler(const scene::Scene& scene, const geometry::SceneGeometry& geometry, std::uint64_t seed = 0);
    ~LightSampler();
    LightSampler(const LightSampler&) = delete;
    LightSampler& operator=(const LightSampler&) = delete;

    /// A photon map was built: shadow rays through the targets that refract a light's photons are black for it
    /// (POV-Ray's ComputeShadowColour), unless the lit surface ignores photons (TraceContext::lit_ignores_photons).
    void use_photon_shadows() { m_photon_shadows = true; }

    /// POV-Ray's quality flags (+Q): without `shadows` light reaches every point it faces, without `area_lights`
    /// an area light is a point light at its centre, without `volume` neither fog nor media dim a light.
    void limit_quality(bool shadows, bool area_lights, bool volume) {
        m_shadows = shadows;
        m_area_lights = area_lights;
        if (!volume) {
            m_fog.reset();
            m_media.reset();
        }
    }

    /// The reference mode's converged direct light: a jittered area light is sampled at about `samples` points of a
    /// fine jittered grid (same expectation as POV-Ray's grid fully subdivided) instead of its own adaptive grid;
    /// 0 keeps POV-Ray's grid.
    void sample_area_lights_finely(int samples) { m_fine_area_samples = samples; }

    /// POV-Ray's Q_QUICKC (+Q0 to +Q5): shadow rays see pigments' quick_color.
    void use_quick_colors(bool on) { m_quick_colors = on; }

    /// The light arriving at `p` from `light` through whatever stands between: colour times attenuation times the
    /// filter colour of transparent blockers; zero when blocked or behind the surface (cos below EPSILON). With
    /// `area_lights` false (on a gather ray's path) an area light counts as a point light at its centre. `to_light`
    /// receives the unit direction towards the light. `both_sides` (double_illuminate) lets light behind the
    /// surface reach it too.
    Vec3 light_arriving(const scene::Light& light, const Vec3& p, const Vec3& n, const InteriorStack& interiors,
                        bool area_lights, bool both_sides, Vec3& to_light, TraceContext& ctx) const;

    /// What a light sends towards a point before any shadow test: light_arriving's answer when nothing stands
    /// between (its colour times spot, cylinder and fade attenuation), and what the shadow test needs.
    struct Reach {
        bool lit = false;      ///< the light reaches the point unshadowed (in front of the surface, inside its cone)
        Vec3 colour;           ///< colour × attenuation
        Vec3 to_light;         ///< unit direction towards the light
        double distance = 0.0; ///< to the light (to its plane for parallel and cylinder lights)
    };

    /// The first half of light_arriving: where `light` reaches `p` (facing `n` unless `both_sides`) unshadowed.
    Reach reach(const scene::Light& light, const Vec3& p, const Vec3& n, bool both_sides) const {
        return reach_point(light, p, both_sides ? nullptr : &n);
    }

    /// The second half of light_arriving: `reach`'s colour through whatever stands between (shadow rays, area-light
    /// grids, projected_through, media attenuation); `reach` must be lit.
    Vec3 through(const scene::Light& light, const Reach& reach, const Vec3& p, const InteriorStack& interiors,
                 bool area_lights, TraceContext& ctx) const;

    /// True when through() traces shadow rays for this light (false: it returns the reach's colour, unless the
    /// light is projected_through an object).
    bool casts_shadows(const scene::Light& light, const Reach& reach) const {
        return m_shadows && !light.shadowless && reach.distance > 0.0;
    }

    /// The light arriving at `p` inside a medium, as light_arriving without a surface to face (POV-Ray's TestShadow
    /// for a media sample).
    Vec3 light_in_medium(const scene::Light& light, const Vec3& p, const InteriorStack& interiors, bool area_lights,
                         Vec3& to_light, TraceContext& ctx) const;

private:
    /// light_arriving, with the facing test only when there is a surface normal `n`.
    Vec3 arriving(const scene::Light& light, const Vec3& p, const Vec3* n, const InteriorStack& interiors,
                  bool area_lights, Vec3& to_light, TraceContext& ctx) const;
    /// reach(), with the facing test only when there is a surface normal `n`.
    Reach reach_point(const scene::Light& light, const Vec3& p, const Vec3* n) const;
    /// The transmittance from `p` towards a light `distance` away along the unit `dir`: 0 or 1 when every object is
    /// opaque, else the filter colours of what stands between (shadow_filter).
    Vec3 shadow_towards(const scene::Light& light, const Vec3& p, const Vec3& dir, double distance,
                        const InteriorStack& interiors, ShadowAtmosphere fog, TraceContext& ctx) const;
    /// The axes of an area light's square as seen from `p` (turned to face it by `orient`).
    static void area_axes(const scene::Light& light, const Vec3& p, Vec3& axis1, Vec3& axis2);
    /// Where grid coordinates (ju, jv) of an area light lie relative to its centre (circular lights mapped).
    static Vec3 area_offset(const scene::Light& light, const Vec3& axis1, const Vec3& axis2, double ju, double jv);
    /// sample_area_lights_finely's area light: `colour` times the mean shadow over a fine jittered grid.
    Vec3 area_light_fine(const scene::Light& light, const Vec3& colour, const Vec3& p, const InteriorStack& interiors,
                         ShadowAtmosphere fog, TraceContext& ctx) const;
    /// POV-Ray's area light shadow: `colour` (taken at the light's centre) times the adaptive average of the shadow
    /// towards the points of the light's grid.
    Vec3 area_light_shadow(const scene::Light& light, const Vec3& colour, const Vec3& p,
                           const InteriorStack& interiors, ShadowAtmosphere fog, TraceContext& ctx) const;
    /// Transmittance of the shadow ray from `p` along `dir` up to `distance` (POV-Ray multiplies the filter colour
    /// of every surface it crosses). `interiors` are those of the ray that found `p` (POV-Ray starts the shadow
    /// ray with them and fades light crossing an interior).
    /// `fog`, when the light has media_attenuation, dims the stretches outside non-hollow objects.
    Vec3 shadow_filter(const scene::Light& light, const Vec3& p, const Vec3& dir, double distance,
                       InteriorStack interiors, ShadowAtmosphere fog, TraceContext& ctx) const;
    /// What POV-Ray's fake caustics need at a shadow ray's surface: the interior's exponent, the raw normal turned
    /// against the ray, the ray's unit direction and the warps of the texture maps entered so far.
    struct Caustics {
        double power = 0.0;
        Vec3 raw_normal;
        Vec3 direction;
        std::vector<const scene::Pattern*> warps;
    };
    /// The filter colour of an object's texture at a point (its layers' filter·colour + transmit, multiplied);
    /// with `caustics`, each layer's also times POV-Ray's fake-caustics factor. `surface` is the shadow ray's
    /// intersection as slope and aoi read it.
    Vec3 texture_filter(const scene::Texture& texture, const Vec3& p, Caustics* caustics,
                        texture::SurfacePoint& surface) const;

    /// A spotlight's cone, computed once per light instead of at every point it lights.
    struct SpotCone {
        Vec3 axis;                 ///< unit, from the light towards point_at
        double cos_radius = 1.0;   ///< cos of the full-intensity half angle
        double cos_falloff = 1.0;  ///< cos of the dark edge's half angle
    };
    static SpotCone spot_cone(const scene::Light& light);

    const scene::Scene& m_scene;
    const geometry::SceneGeometry& m_geometry;
    std::vector<SpotCone> m_cones;  ///< per light of m_scene.lights (meaningful for spotlights only)
    bool m_any_transparent = false;  ///< some object can let light through (filter or transmit somewhere)
    bool m_photon_shadows = false;   ///< a photon map carries the light refracted by photon targets
    bool m_shadows = true;           ///< +Q4 and up: shadow rays are traced
    bool m_area_lights = true;       ///< +Q5 and up: area lights are sampled over their area
    bool m_quick_colors = false;     ///< +Q0 to +Q5: pigments' quick_color in shadow filters
    int m_fine_area_samples = 0;     ///< sample_area_lights_finely's points per area light (0: POV-Ray's grid)
    std::vector<std::uint8_t> m_opaque;  ///< per top-level object: its textures never filter or transmit
    int m_noise_generator = 2;
    std::uint64_t m_seed = 0;
    std::unique_ptr<const media::Medium> m_fog;  ///< the scene's fog, for lights with media_attenuation
    bool m_volume_on_gathers = false;  ///< radiosity `media on`: fog dims lights on gather paths too
    std::unique_ptr<const media::ParticipatingMedia> m_media;  ///< null when the scene has no media
    /// Per light, the geometry of its projected_through object (null for the others); empty when no light has one.
    std::vector<std::unique_ptr<const ProjectedThrough>> m_projected;
};

}  // namespace wardray::lighting
