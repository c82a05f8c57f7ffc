// The integrator's hook into participating media: which media a ray passes through, and the light they scatter
// (trace.cpp's calls of ComputeMedia in TraceRay and ComputeTextureColour).
#include "geometry/scene_geometry.h"
#include "lighting/integrator.h"
#include "photons/photon_map.h"

namespace wardray::lighting {

namespace {

// POV-Ray's TestShadow from a media sample: the ray's interiors go with the shadow ray.
class MediaLights final : public media::LightQuery {
public:
    MediaLights(const scene::Scene& scene, const LightSampler& lights, const RayState& state, TraceContext& ctx,
                const media::MediaPhotons* photons)
        : m_scene(scene), m_lights(lights), m_state(state), m_ctx(ctx), m_photons(photons) {}
    Vec3 arriving(std::size_t light, const Vec3& p, Vec3& to_light) const override {
        // POV-Ray compat (ComputeOneMediaSample): media never ignore photons, so shadow rays through the targets
        // that refract this light's photons are black for them.
        m_ctx.lit_ignores_photons = false;
        // POV-Ray compat (GetRadiosityQualityFlags): on a gather ray's path area lights are point lights.
        return m_lights.light_in_medium(m_scene.lights[light], p, m_state.interiors, !m_state.gather_ray, to_light,
                                        m_ctx);
    }
    const media::MediaPhotons* photons() const override { return m_photons; }

private:
    const scene::Scene& m_scene;
    const LightSampler& m_lights;
    const RayState& m_state;
    TraceContext& m_ctx;
    const media::MediaPhotons* m_photons;
};

}  // namespace

Vec3 Integrator::apply_media(const geometry::Ray& ray, const Vec3& direction, double depth, bool hit,
                             const RayState& state, const Vec3& colour, TraceContext& ctx) const {
    // POV-Ray compat: media fill only hollow objects; a ray inside a non-hollow one sees none.
    if (!hollow_ray(state.interiors)) return colour;
    // POV-Ray compat (GetRadiosityQualityFlags): gather rays' paths see media only with the radiosity block's
    // `media on`.
    if (state.gather_ray && !(m_scene.global.radiosity && m_scene.global.radiosity->media)) return colour;
    const MediaLights lights(m_scene, m_lights, state, ctx, m_media_gather.get());
    const media::Segment segment{ray.origin, direction, depth};
    Vec3 c = colour;
    // The media of every interior the ray is in act together (ComputeTextureColour, only where a surface is hit).
    if (hit && state.interiors.size > 0) {
        media::MediaList inside;
        for (int i = 0; i < state.interiors.size; ++i) inside.add(state.interiors.objects[i]->interior.media);
        c = m_media->along(inside, segment, c, lights);
    }
    // Then the atmosphere's media (TraceRay, before fog).
    return m_media->along(m_media->atmosphere(), segment, c, lights);
}

}  // namespace wardray::lighting
