// Integrator: POV-Ray 3.7's ray recursion (TraceRay) and the direct light of a finish (diffuse, phong, specular,
// metallic, iridescence); surface.cpp shades textures, indirect.cpp holds the indirect light.
#include "lighting/integrator.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "cache/hemisphere_sampler.h"
#include "core/render_seed.h"
#include "geometry/object_query.h"
#include "geometry/scene_geometry.h"
#include "lighting/graininess.h"
#include "lighting/light_choice.h"
#include "lighting/metallic.h"
#include "media/atmosphere.h"
#include "media/fog.h"
#include "photons/photon_map.h"
#include "photons/photon_shooter.h"
#include "texture/noise.h"
#include "texture/pigment.h"

namespace wardray::lighting {

bool InteriorStack::contains(const scene::Object& o) const {
    for (int i = 0; i < size; ++i)
        if (scene::same_interior(*objects[i], o)) return true;
    return false;
}

void InteriorStack::push(const scene::Object& o) {
    if (size < kMax) objects[size++] = &o;
}

bool hollow_ray(const InteriorStack& interiors) {
    for (int i = 0; i < interiors.size; ++i)
        if (!interiors.objects[i]->interior.hollow) return false;
    return true;
}

bool InteriorStack::remove(const scene::Object& o) {
    for (int i = size - 1; i >= 0; --i) {
        if (!scene::same_interior(*objects[i], o)) continue;
        for (int j = i; j + 1 < size; ++j) objects[j] = objects[j + 1];
        --size;
        return true;
    }
    return false;
}

Integrator::Integrator(const scene::Scene& scene, const geometry::SceneGeometry& geometry,
                       IntegratorOptions options)
    : m_scene(scene),
      m_geometry(geometry),
      m_options(options),
      m_quality(quality_features(options.quality)),
      m_lights(scene, geometry, options.seed),
      m_sky(scene),
      m_atmosphere(media::make_atmosphere(scene)) {
    m_volume_on_gathers = scene.global.radiosity.has_value() && scene.global.radiosity->media;
    // POV-Ray compat (+Q): below quality 9 no media, fog or rainbows; below 5 area lights are points; below 4
    // nothing casts a shadow.
    m_lights.limit_quality(m_quality.shadows, m_quality.area_lights, m_quality.volume);
    m_lights.use_quick_colors(m_quality.quick_colors);
    if (!m_quality.volume) m_atmosphere.reset();
    if (m_quality.volume && !scene.rainbows.empty())
        m_rainbows = std::make_unique<const media::Rainbows>(scene.rainbows, scene.global.noise_generator);
    // POV-Ray compat: with radiosity on, a 3.7 scene's `ambient` is not light; a scene that says
    // `#version 3.6` (or older) still gets it.
    m_ambient_is_light = !scene.global.radiosity.has_value() || scene.version < 3.7;
    m_noise_generator = scene.global.noise_generator;
    texture::set_number_of_waves(scene.global.number_of_waves);
    // Indirect light only for a radiosity block with --gi on: through the cache, or by brute force.
    // POV-Ray compat (+Q): radiosity and photons only from quality 9.
    const bool radiosity = scene.global.radiosity.has_value() && m_quality.advanced_light;
    if (radiosity && options.gi == GiMode::Cache)
        m_indirect = make_cached_irradiance(scene, *this, options.gradients, options.footprint, options.gradient_cap,
                                            options.hessian_spacing, options.adaptive_gather, options.geometry_floor,
                                            options.lookup_sampling);
    else if (radiosity && options.gi == GiMode::Reference) {
        if (options.guide_paths) m_guide = std::make_unique<PathGuide>();
        m_indirect = make_reference_irradiance(*this, options.reference_rays, options.path_seed.value_or(options.seed),
                                                m_guide.get());
        // The reference converges the direct light at camera hits too: each jittered area light is sampled at about
        // as many points as the pixel has paths, shared out among the area lights.
        int area_lights = 0;
        for (const scene::Light& light : scene.lights) area_lights += light.area && light.jitter ? 1 : 0;
        if (area_lights > 0 && options.fine_area_lights)
            m_lights.sample_area_lights_finely(std::max(16, options.reference_rays / area_lights));
    }
    // POV-Ray compat: camera rays start inside every object that contains the camera (an infinite plane's
    // inside too), which changes the relative indices of refraction. Containment is found by the parity of
    // crossings along one ray from the camera. POV-Ray finds it once, at the origin of the first camera ray
    // (InitRayContainerState), which for a mesh_camera is on the camera mesh, not at `location` (an offset there).
    {
        std::vector<int> crossings(scene.objects.size(), 0);
        const Vec3 origin = options.camera_origin.value_or(scene.camera.location);
        const Vec3 dir = normalize(Vec3{0.1234, 0.9871, 0.0456});
        double t0 = geometry.self_intersection_offset(origin);
        for (int i = 0; i < 4096; ++i) {
            const std::optional<geometry::Hit> hit =
                geometry.intersect(geometry::Ray{origin, dir, t0, 1e30, geometry::RayKind::Camera});
            if (!hit) break;
            ++crossings[hit->object];
            t0 = hit->t + geometry.self_intersection_offset(hit->position);
        }
        // POV-Ray compat (InitRayContainerState): containment is its Inside test; an infinite plane is crossed
        // once or never along the ray, so it is tested directly.
        const geometry::ObjectQuery query;
        for (std::size_t o = 0; o < crossings.size(); ++o) {
            const bool plane = std::holds_alternative<scene::Plane>(scene.objects[o].shape);
            // POV-Ray compat: the top-level object's interior, once for the parts of a union that share it.
            const scene::Object& object = scene.objects[o];
            if ((plane ? query.inside(object, origin) : crossings[o] % 2 == 1) && !m_camera_interiors.contains(object))
                m_camera_interiors.push(object);
        }
    }
    if (m_quality.volume && media::ParticipatingMedia::in_scene(scene))
        m_media = std::make_unique<media::ParticipatingMedia>(scene, options.seed);
    if (scene.global.photons && m_quality.advanced_light) {
        // The photon pass, before any pixel: its map lights diffuse surfaces, and shadows through the targets that
        // shot it turn black (LightSampler).
        m_photon_stats = std::make_unique<photons::PhotonStats>();
        photons::ShotPhotons shot =
            options.photons_from_file
                ? *options.photons_from_file
                : photons::shoot_photon_sets(scene, geometry, *m_photon_stats, nullptr, options.seed);
        // POV-Ray's photons' exponent byte wraps round past a flux of 2^5, and such photons come out nearly black.
        // wardray's do the same at a fine spacing; at a coarse one (a power-of-two offset, which keeps the scene's
        // picture at any scale) they keep their light, and the user is told.
        const auto wraps = [&](const std::vector<photons::Photon>& set, int offset) {
            return std::ranges::any_of(set, [&](const photons::Photon& p) { return photons::beyond_povray_flux(p, offset); });
        };
        if (wraps(shot.surface, shot.surface_offset) || wraps(shot.media, shot.media_offset))
            m_limitations.push_back("photons: at this scene's coarse photon spacing some photons carry more light than "
                                    "POV-Ray's photon format holds (a flux of 32 or more); POV-Ray's wrap round to "
                                    "almost nothing there, wardray's keep their light, so the caustics may differ "
                                    "from POV-Ray's; a spacing below 1/32 (or a larger count) keeps both alike");
        if (options.keep_shot_photons) m_shot_photons = std::make_unique<const photons::ShotPhotons>(shot);
        m_photons = photons::build_photon_maps(std::move(shot), *scene.global.photons, *m_photon_stats,
                                               &m_media_photons, options.seed);
        if (m_photons) m_lights.use_photon_shadows();
        if (m_media_photons) m_media_gather = std::make_unique<const photons::MediaPhotonGather>(*m_media_photons);
        for (const scene::Light& light : scene.lights)
            if (m_photons && !light.projected_through.empty())
                m_limitations.push_back("photons of a light with projected_through are shot as if it had none (not "
                                        "rendered yet)");
    }
    // POV-Ray 3.7 has this warning commented out (View::CheckCameraHollowObject); wardray gives it, as the
    // documentation describes, since media and fog then leave the camera's stretch of every ray out.
    if (options.output_alpha && (m_media || !scene.rainbows.empty()))
        m_limitations.push_back("Output_Alpha: participating media and rainbows do not change the alpha channel "
                                "(not rendered yet)");
    if ((m_media || !scene.fogs.empty()) && !hollow_ray(m_camera_interiors))
        m_limitations.push_back("Camera is inside a non-hollow object. Fog and participating media may not work as "
                                "expected.");
}

Integrator::~Integrator() = default;

int Integrator::pilot_paths(long long pixels, int rays) {
    const long long per_ray = pixels * rays / (8LL * kPilotGrid * kPilotGrid);
    return static_cast<int>(std::clamp(per_ray, 1LL, 1024LL));
}

void Integrator::pilot(const geometry::Ray& ray, int paths, std::vector<GuideSample>& samples) const {
    if (!m_guide || !m_indirect) return;
    const std::optional<geometry::Hit> hit = m_geometry.intersect(ray);
    if (!hit) return;
    TraceContext ctx;
    ctx.guide_samples = &samples;
    ctx.pilot_paths = paths;
    // A gather as a camera hit starts one, around the geometric normal facing the ray; the path seed keeps the
    // pilot's random numbers apart from the render's, so that the guide does not depend on the render's samples.
    const Vec3 n = dot(hit->normal, ray.direction) > 0.0 ? -hit->normal : hit->normal;
    RayState state;
    state.level = 1;
    state.adc_bailout = m_scene.global.adc_bailout;
    state.max_level = m_scene.global.max_trace_level;
    state.interiors = m_camera_interiors;
    state.path_seed = 0x50494C4F54ull;
    m_indirect->irradiance(hit->position, n, 1.0, state, ctx);
}

void Integrator::learn_guide(const std::vector<GuideSample>& samples) {
    if (m_guide) *m_guide = PathGuide::build(samples);
}

Vec3 Integrator::trace_camera_ray(const geometry::Ray& ray, TraceContext& ctx) const {
    ++ctx.rays.camera;
    RayState state;
    state.adc_bailout = m_scene.global.adc_bailout;
    state.max_level = m_scene.global.max_trace_level;
    state.interiors = m_camera_interiors;
    state.alpha_background = m_options.output_alpha;
    return trace(ray, state, false, ctx);
}

Vec3 Integrator::trace(const geometry::Ray& ray, const RayState& in, bool continued, TraceContext& ctx,
                       double* hit_distance) const {
    if (hit_distance) *hit_distance = INFINITY;
    // POV-Ray compat: a ray beyond max_trace_level, or weighing less than adc_bailout, is black.
    if (in.level >= in.max_level || in.weight < in.adc_bailout) return {};
    RayState state = in;
    if (!continued) ++state.level;
    const std::optional<geometry::Hit> hit = m_geometry.intersect(ray);
    const double scale = length(ray.direction);
    const Vec3 direction = ray.direction / scale;
    Vec3 colour;
    double depth = INFINITY;
    double transmit = 0.0;  // Output_Alpha: the background showing through, POV-Ray's transmit channel
    if (hit) {
        depth = hit->t * scale;
        if (hit_distance) *hit_distance = depth;
        colour = shade(*hit, direction, depth, state, ctx);
        if (state.alpha_background) transmit = ctx.transmit;
    } else if (state.alpha_background) {
        colour = m_sky.radiance_with_alpha(direction, transmit);
    } else {
        colour = m_sky.radiance(direction);
    }
    // POV-Ray compat (TraceRay): on a ray through hollow space the rainbow (its jitter drawn from the ray), then the
    // atmosphere's media, then fog; a ray inside a non-hollow object passes none of them, nor does a radiosity
    // gather ray, or anything it leads to, unless the radiosity block says `media on` (apply_media checks its own).
    const bool volume = (m_rainbows || m_atmosphere) && (!state.gather_ray || m_volume_on_gathers) &&
                        hollow_ray(state.interiors);
    if (volume && m_rainbows)
        colour = m_rainbows->apply(colour, direction, hit ? depth : media::kSkyDepth,
                                   cache::seed_from(ray.origin, direction, reseed(0x5241494E, m_options.seed)));
    if (m_media) colour = apply_media(ray, direction, depth, hit.has_value(), state, colour, ctx);
    if (volume && m_atmosphere) {
        const media::Segment segment{ray.origin, direction, depth};
        colour = m_atmosphere->along_segment(colour, segment);
        // POV-Ray compat (ComputeFog): the fog's attenuation dims the transmit channel by its grey level.
        if (transmit > 0.0) transmit *= texture::grey(m_atmosphere->transmittance(segment));
    }
    ctx.transmit = transmit;
    return colour;
}

Vec3 Integrator::direct_light(const scene::Finish& finish, const Vec3& pigment, double opacity, const Surface& s,
                              const Vec3& n, TraceContext& ctx) const {
    // On a gather ray's path a few lights picked by importance stand for all (an unbiased estimate).
    if (!s.highlights && m_options.gather_light_picks > 0 && m_scene.lights.size() > 1)
        return direct_light_picked(finish, pigment, opacity, s, n, ctx);
    Vec3 colour;
    for (const scene::Light& light : m_scene.lights) {
        // POV-Ray's ComputeDiffuseLight: the global lights unless the surface's light group turns them off, and
        // the lights of the groups the surface is in.
        if (!lights_object(light, *s.object)) continue;
        Vec3 to_light;
        // POV-Ray compat (GetRadiosityQualityFlags): on a gather ray's path area lights are point lights.
        const Vec3 arriving =
            m_lights.light_arriving(light, s.hit->position, n, *s.interiors, s.highlights,
                                    s.object->double_illuminate, to_light, ctx);
        if (arriving == Vec3{}) continue;
        // POV-Ray compat: shadowless (fill) lights cause no highlights, nor does any light on a gather ray's path.
        colour += finish_light(finish, pigment, opacity, s, n, to_light, arriving, !light.shadowless && s.highlights,
                               light.position);
    }
    return colour;
}

Vec3 Integrator::finish_light(const scene::Finish& finish, const Vec3& pigment, double opacity, const Surface& s,
                              const Vec3& n, const Vec3& to_light, const Vec3& arriving, bool highlights,
                              const Vec3& grain_from) const {
    const Vec3& view_dir = s.direction;
    const double cos_i = dot(n, to_light);
    Vec3 light_colour;  // this light's diffuse and highlights
    // Lambert with POV-Ray's brilliance exponent: diffuse · opacity · cos^brilliance.
    if (finish.diffuse > 0.0) {
        const double shape =
            finish.brilliance == 1.0 ? std::fabs(cos_i) : std::pow(std::fabs(cos_i), finish.brilliance);
        double intensity = finish.diffuse * opacity * shape;
        if (finish.crand > 0.0) intensity -= graininess(finish.crand, s.hit->position, grain_from, m_options.seed);
        light_colour += pigment * arriving * intensity;
    }
    if (highlights) {
        // POV-Ray's metallic highlight tint.
        const Vec3 tint = finish.metallic > 0.0 ? metallic_tint(pigment, finish.metallic, cos_i) : Vec3{1.0, 1.0, 1.0};
        // Phong highlight: phong · cos(reflected, light)^phong_size (POV-Ray drops tiny values for sizes ≥ 60).
        if (finish.phong > 0.0) {
            const Vec3 reflected = view_dir - 2.0 * dot(view_dir, n) * n;
            const double c = dot(reflected, to_light);
            if (c > 0.0 && (finish.phong_size < 60.0 || c > 0.0008))
                light_colour += arriving * tint * (finish.phong * std::pow(c, finish.phong_size));
        }
        // Blinn specular: specular · cos(half vector, normal)^(1/roughness).
        if (finish.specular > 0.0) {
            const Vec3 half = normalize(to_light - view_dir);
            const double c = dot(half, n);
            if (c > 0.0) light_colour += arriving * tint * (finish.specular * std::pow(c, 1.0 / finish.roughness));
        }
    }
    if (finish.irid > 0.0) light_colour = light_colour * iridescence(finish, to_light, view_dir, n, s.hit->position);
    return light_colour;
}

Vec3 Integrator::iridescence(const scene::Finish& finish, const Vec3& to_light, const Vec3& view_dir, const Vec3& n,
                             const Vec3& p) const {
    // Thin-film interference: phase 2π·thickness·(|cos θ_light| + |cos θ_eye|) per wavelength; the film
    // thickness varies with POV-Ray's 5-octave turbulence when `turbulence` is given.
    double film = finish.irid_thickness;
    if (finish.irid_turbulence != 0.0) {
        const double t = 2.0 * texture::turbulence(p, texture::TurbulenceParams{5, 0.5, 2.0}, m_noise_generator) - 1.0;
        film *= 1.0 + t * finish.irid_turbulence;
    }
    // POV-Ray's default irid_wavelength (global_settings) is rgb <0.70, 0.52, 0.48>.
    constexpr double kWavelength[3] = {0.70, 0.52, 0.48};
    const double phase =
        2.0 * std::numbers::pi * film * (std::fabs(dot(n, to_light)) + std::fabs(dot(n, view_dir)));
    return {1.0 + finish.irid * std::cos(phase / kWavelength[0]), 1.0 + finish.irid * std::cos(phase / kWavelength[1]),
            1.0 + finish.irid * std::cos(phase / kWavelength[2])};
}

}  // namespace wardray::lighting
