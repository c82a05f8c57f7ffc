// LightSampler: POV-Ray 3.7's light sources (spot, cylinder, fade), shadows filtered through transparent objects
// and its adaptive area lights.
#include "lighting/light_sampler.h"

#include "lighting/projected_through.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "cache/hemisphere_sampler.h"
#include "core/constants.h"
#include "core/render_seed.h"
#include "geometry/scene_geometry.h"
#include "media/atmosphere.h"
#include "media/participating_media.h"
#include "media/transmittance.h"
#include "scene/opacity.h"
#include "photons/photon_shooter.h"
#include "texture/image_map.h"
#include "texture/normal.h"
#include "texture/pattern.h"
#include "texture/pigment.h"

namespace wardray::lighting {

namespace {

constexpr double kDegrees = std::numbers::pi / 180.0;

// POV-Ray compat: the spotlight edge is a cubic (smoothstep) ramp in cos α between falloff and radius.
double smooth_ramp(double low, double high, double x) {
    if (x <= low) return 0.0;
    if (x >= high) return 1.0;
    const double t = (x - low) / (high - low);
    return t * t * (3.0 - 2.0 * t);
}

}  // namespace

LightSampler::LightSampler(const scene::Scene& scene, const geometry::SceneGeometry& geometry, std::uint64_t seed)
    : m_scene(scene),
      m_geometry(geometry),
      m_noise_generator(scene.global.noise_generator),
      m_seed(seed),
      m_fog(media::make_atmosphere(scene)),
      m_volume_on_gathers(scene.global.radiosity.has_value() && scene.global.radiosity->media) {
    if (media::ParticipatingMedia::in_scene(scene)) m_media = std::make_unique<media::ParticipatingMedia>(scene, seed);
    // Shadow rays need to look through objects only when something lets light pass.
    m_opaque.reserve(scene.objects.size());
    for (const scene::Object& o : scene.objects) {
        const bool opaque = scene::object_opaque(o);
        m_opaque.push_back(opaque ? 1 : 0);
        m_any_transparent = m_any_transparent || !opaque;
    }
    m_projected = ProjectedThrough::for_lights(scene);
    for (const scene::Light& light : scene.lights) m_cones.push_back(spot_cone(light));
}

LightSampler::SpotCone LightSampler::spot_cone(const scene::Light& light) {
    return {normalize(light.point_at - light.position), std::cos(light.radius * kDegrees),
            std::cos(light.falloff * kDegrees)};
}

LightSampler::~LightSampler() = default;

Vec3 LightSampler::texture_filter(const scene::Texture& texture, const Vec3& p, Caustics* caustics,
                                  texture::SurfacePoint& surface) const {
    if (!texture.texture_map.empty()) {
        const Vec3 tp = texture::warp_point(texture.map_pattern, p);
        // The map's pattern warps the normals of the entries' layers (fake caustics only).
        if (caustics) caustics->warps.push_back(&texture.map_pattern);
        Vec3 filter;
        if (texture.map_pattern.type == scene::Pattern::Type::Average) {
            // POV-Ray's ComputeAverageTextureColours in a shadow: the entries' filters, weighted by map value.
            Vec3 sum;
            float total = 0.0f;
            for (const auto& e : texture.texture_map) {
                sum += texture_filter(e.texture, tp, caustics, surface) * e.value;
                total += static_cast<float>(e.value);
            }
            filter = sum / static_cast<double>(total);
        } else if (texture.material_map) {
            const auto& map = texture.texture_map;
            const int i = texture::material_map_index(*texture.material_map, tp, static_cast<int>(map.size()));
            filter = texture_filter(map[static_cast<std::size_t>(i)].texture, tp, caustics, surface);
        } else {
            const double v = texture::pattern_value(texture.map_pattern, tp, m_noise_generator, &surface);
            const auto& map = texture.texture_map;
            const texture::MapLookup m =
                texture::search_map(v, static_cast<int>(map.size()), [&](int i) { return map[i].value; });
            filter = texture_filter(map[m.cur].texture, tp, caustics, surface);
            if (m.prev != m.cur)
                filter = filter * m.fraction + texture_filter(map[m.prev].texture, tp, caustics, surface) * (1.0 - m.fraction);
        }
        if (caustics) caustics->warps.pop_back();
        return filter;
    }
    Vec3 filter = media::filter_colour(texture::evaluate_pigment(texture.pigment, p, m_noise_generator, &surface));
    if (caustics) {
        // POV-Ray's fake caustics (ComputeShadowTexture): each layer's transmitted colour times
        // 1 + |n·d|^power, n the layer's (perturbed) normal and d the shadow ray's direction, so light through a
        // surface facing it comes out brighter than it went in.
        Vec3 n = caustics->raw_normal;
        if (texture.normal.pattern.type != scene::Pattern::Type::None) {
            for (const scene::Pattern* w : caustics->warps) n = texture::warp_normal(*w, n);
            n = texture::perturb_normal(texture.normal, n, p, m_noise_generator, &surface);
            surface.normal = n;  // POV-Ray compat: the layers after see this normal (its PNormal)
            for (auto it = caustics->warps.rbegin(); it != caustics->warps.rend(); ++it)
                n = texture::unwarp_normal(**it, n);
        }
        filter = filter * (1.0 + std::pow(std::fabs(dot(n, caustics->direction)), caustics->power));
    }
    for (const scene::Texture& layer : texture.layers) filter = filter * texture_filter(layer, p, caustics, surface);
    return filter;
}

Vec3 LightSampler::shadow_filter(const scene::Light& light, const Vec3& p, const Vec3& dir, double distance,
                                 InteriorStack interiors, ShadowAtmosphere fog, TraceContext& ctx) const {
    // POV-Ray compat (ComputeShadowMedia): with media_attenuation, fog dims each stretch of the shadow ray that is
    // inside no non-hollow object.
    auto fog_over = [&](double from, double to) {
        Vec3 t{1.0, 1.0, 1.0};
        if (!fog.any() || !(to > from) || !hollow_ray(interiors)) return t;
        const media::Segment stretch{p + dir * from, dir, to - from};
        if (fog.media) t = m_media->transmittance(m_media->atmosphere(), stretch);
        if (fog.fog) t = t * fog.fog->transmittance(stretch);
        return t;
    };
    // POV-Ray walks the shadow ray through every surface it crosses, multiplying their filter colours and the
    // fade of the interiors it leaves.
    Vec3 filter{1.0, 1.0, 1.0};
    double t_origin = 0.0;
    // POV-Ray compat (TracePointLightShadowRay's SmallToleranceRayObjectCondition): a shadow ray sees no crossing
    // within SMALL_TOLERANCE, ten times MIN_ISECT_DEPTH, of where it starts, so leaves of overlapping transparent
    // spheres a hair apart do not shadow each other.
    const double small_tolerance = 10.0 * m_geometry.min_isect_parameter(dir);
    double t0 = std::fmax(m_geometry.self_intersection_offset(p), small_tolerance);
    const double t1 = distance - t0;
    for (int crossing = 0; crossing < 64 && t0 < t1; ++crossing) {
        ++ctx.rays.shadow;
        const geometry::Ray ray{p, dir, t0, t1, geometry::RayKind::Shadow};
        const std::optional<geometry::Hit> hit = m_geometry.intersect(ray);
        if (!hit) break;
        if (m_opaque[hit->object]) return {};
        // POV-Ray compat (ComputeShadowColour): the media of the interiors the ray is in dim it, media_attenuation
        // or not, when none of them is a non-hollow object.
        if (m_media && interiors.size > 0 && hollow_ray(interiors)) {
            media::MediaList inside;
            for (int i = 0; i < interiors.size; ++i) inside.add(interiors.objects[i]->interior.media);
            if (!inside.empty())
                filter = filter * m_media->transmittance(inside, media::Segment{p + dir * t_origin, dir,
                                                                                 hit->t - t_origin});
        }
        filter = filter * fog_over(t_origin, hit->t);
        const scene::Object& object = hit->leaf ? *hit->leaf : m_scene.objects[hit->object];
        // POV-Ray compat (ComputeShadowColour): the photons of a target that refracts this light carry its light.
        if (m_photon_shadows && !ctx.lit_ignores_photons && photons::photons_replace_shadow(object, light)) return {};
        // POV-Ray compat (ComputeShadowTexture): a surface met from inside shows its interior texture.
        const bool inside = !object.interior_texture.empty() && dot(hit->normal, dir) > 0.0;
        const scene::Texture& texture = inside ? object.interior_texture.front() : *object.texture;
        const double caustics = object.interior.caustics;
        // POV-Ray compat (ComputeShadowColour): patterns see the normal turned against the shadow ray.
        const Vec3 raw = dot(hit->normal, dir) > 0.0 ? -hit->normal : hit->normal;
        texture::SurfacePoint surface{hit->position, raw, dir, m_quick_colors};
        if (caustics != 0.0) {
            Caustics c{caustics, raw, dir, {}};
            filter = filter * texture_filter(texture, hit->position, &c, surface);
        } else {
            filter = filter * texture_filter(texture, hit->position, nullptr, surface);
        }
        const scene::Interior& interior = object.interior;
        if (interiors.contains(object) && interior.fade_power > 0.0 &&
            std::fabs(interior.fade_distance) > kPovEpsilon)
            filter = filter * media::interior_fade(interior, hit->t - t_origin);
        // Entering adds the interior, leaving removes it (POV-Ray's ComputeShadowMedia bookkeeping).
        if (interiors.size == 0 || !interiors.remove(object)) interiors.push(object);
        if (max_abs_component(filter) < kPovEpsilon) return {};
        t_origin = hit->t;
        // POV-Ray compat: its shadow ray starts anew at the crossing, so the next crossing must be SMALL_TOLERANCE on.
        t0 = hit->t + std::fmax(m_geometry.self_intersection_offset(hit->position), small_tolerance);
    }
    return filter * fog_over(t_origin, distance);
}

Vec3 LightSampler::light_arriving(const scene::Light& light, const Vec3& p, const Vec3& n,
                                  const InteriorStack& interiors, bool area_lights, bool both_sides,
                                  Vec3& to_light, TraceContext& ctx) const {
    // double_illuminate (`both_sides`): light behind the surface reaches it too, so no facing test.
    return arriving(light, p, both_sides ? nullptr : &n, interiors, area_lights, to_light, ctx);
}

Vec3 LightSampler::light_in_medium(const scene::Light& light, const Vec3& p, const InteriorStack& interiors,
                                   bool area_lights, Vec3& to_light, TraceContext& ctx) const {
    return arriving(light, p, nullptr, interiors, area_lights, to_light, ctx);
}

Vec3 LightSampler::arriving(const scene::Light& light, const Vec3& p, const Vec3* n, const InteriorStack& interiors,
                            bool area_lights, Vec3& to_light, TraceContext& ctx) const {
    const Reach r = reach_point(light, p, n);
    to_light = r.to_light;
    if (!r.lit) return {};
    return through(light, r, p, interiors, area_lights, ctx);
}

LightSampler::Reach LightSampler::reach_point(const scene::Light& light, const Vec3& p, const Vec3* n) const {
    using Type = scene::Light::Type;
    Reach r;
    Vec3& to_light = r.to_light;
    double& distance = r.distance;
    if (light.type == Type::Parallel || light.type == Type::Cylinder) {
        // Parallel light arrives along point_at → position; blockers count only up to the plane of the light.
        to_light = normalize(light.position - light.point_at);
        distance = dot(light.position - p, to_light);
        // A cylinder light lights nothing behind it (Attenuate_Light); a parallel light does, see below.
        if (distance <= 0.0 && light.type == Type::Cylinder) return r;
    } else {
        const Vec3 d = light.position - p;
        distance = length(d);
        if (distance <= 0.0) return r;
        to_light = d / distance;
    }
    // POV-Ray compat: lights at grazing angles below EPSILON do not reach the surface.
    if (n != nullptr && dot(*n, to_light) < kPovEpsilon) return r;

    double attenuation = 1.0;
    if (light.type == Type::Spot) {
        // POV-Ray: cos α^tightness times the ramp from falloff (dark) to radius (full), angles in degrees.
        const std::ptrdiff_t i = &light - m_scene.lights.data();
        const SpotCone cone = i >= 0 && static_cast<std::size_t>(i) < m_cones.size() ? m_cones[i] : spot_cone(light);
        const double cos_alpha = dot(-to_light, cone.axis);
        // POV-Ray compat: dark beyond falloff only through the ramp, which applies outside radius alone; so a
        // falloff smaller than radius lights the whole radius cone at full strength, with a hard edge there.
        if (!(cos_alpha > 0.0)) return r;
        if (cone.cos_radius > 0.0 && cos_alpha < cone.cos_radius) {
            const double ramp = smooth_ramp(cone.cos_falloff, cone.cos_radius, cos_alpha);
            if (ramp == 0.0) return r;
            attenuation *= ramp;
        }
        // pow(x, 1) is x exactly; the common tightness 1 skips the call.
        if (light.tightness == 1.0) attenuation *= cos_alpha;
        else if (light.tightness > 0.0) attenuation *= std::pow(cos_alpha, light.tightness);
    } else if (light.type == Type::Cylinder) {
        // POV-Ray's cylinder light: only points ahead of the light and within `falloff` of its axis are lit,
        // (1 − d/falloff)^tightness, with the same cubic ramp between radius and falloff (d: distance from the axis).
        const Vec3 axis = normalize(light.point_at - light.position);
        const Vec3 v = p - light.position;
        const double k = dot(v, axis);
        if (k <= 0.0) return r;
        const double d = length(v - axis * k);
        if (!(d < light.falloff)) return r;
        const double closeness = 1.0 - d / light.falloff;
        attenuation *= std::pow(closeness, light.tightness);
        if (light.radius > 0.0 && d > light.radius)
            attenuation *= smooth_ramp(0.0, 1.0 - light.radius / light.falloff, closeness);
    }
    if (light.fade_distance > 0.0 && light.fade_power > 0.0 && distance > 0.0) {
        // POV-Ray: 2 / (1 + (d / fade_distance)^fade_power); no inverse-square law otherwise.
        // The common fade_power 2 squares (correctly rounded, as pow is to within its last bit).
        const double ratio = distance / light.fade_distance;
        attenuation *= 2.0 / (1.0 + (light.fade_power == 2.0 ? ratio * ratio : std::pow(ratio, light.fade_power)));
    }
    if (attenuation <= 0.0) return r;
    r.colour = light.color.rgb() * attenuation;
    r.lit = true;
    return r;
}

Vec3 LightSampler::through(const scene::Light& light, const Reach& reach, const Vec3& p,
                           const InteriorStack& interiors, bool area_lights, TraceContext& ctx) const {
    using Type = scene::Light::Type;
    area_lights = area_lights && m_area_lights;
    const Vec3& colour = reach.colour;
    const Vec3& to_light = reach.to_light;
    double distance = reach.distance;  // projected_through shortens it to the object
    // POV-Ray compat (+Q below 4): no shadow ray at all, so no projected_through either.
    if (!m_shadows) return colour;
    if (!m_projected.empty() && !light.projected_through.empty()) {
        // POV-Ray's TracePointLightShadowRay: only through the object, and shadows only on the way to it.
        const std::ptrdiff_t i = &light - m_scene.lights.data();
        const bool ours = i >= 0 && static_cast<std::size_t>(i) < m_projected.size() && m_projected[i];
        if (ours && !m_projected[i]->shine_through(p, to_light, distance)) return {};
    }
    // POV-Ray compat: a point past a parallel light's plane is lit too; its shadow ray has negative length and
    // meets nothing.
    if (light.shadowless || distance <= 0.0) return colour;
    // POV-Ray compat (ComputeShadowMedia): fog and the atmosphere's media dim the light only with media_attenuation,
    // and on a gather ray's path (area_lights false) only when the radiosity block says media on.
    const bool attenuated = light.media_attenuation && light.media_interaction && (area_lights || m_volume_on_gathers);
    const ShadowAtmosphere fog{attenuated ? m_fog.get() : nullptr,
                               attenuated && m_media && !m_media->atmosphere().empty()};
    if (area_lights && light.area && (light.area_size1 > 1 || light.area_size2 > 1) && light.type != Type::Parallel &&
        light.type != Type::Cylinder) {
        if (m_fine_area_samples > 0 && light.jitter) return area_light_fine(light, colour, p, interiors, fog, ctx);
        return area_light_shadow(light, colour, p, interiors, fog, ctx);
    }
    return colour * shadow_towards(light, p, to_light, distance, interiors, fog, ctx);
}

Vec3 LightSampler::shadow_towards(const scene::Light& light, const Vec3& p, const Vec3& dir, double distance,
                                  const InteriorStack& interiors, ShadowAtmosphere fog, TraceContext& ctx) const {
    if (m_any_transparent || fog.any()) return shadow_filter(light, p, dir, distance, interiors, fog, ctx);
    const double offset = m_geometry.self_intersection_offset(p);
    geometry::Ray shadow{p, dir, offset, distance - offset, geometry::RayKind::Shadow};
    ++ctx.rays.shadow;
    if (shadow.t_max > shadow.t_min && m_geometry.occluded(shadow)) return {};
    return {1.0, 1.0, 1.0};
}

Vec3 LightSampler::area_offset(const scene::Light& light, const Vec3& axis1, const Vec3& axis2, double ju,
                               double jv) {
    const int n1 = light.area_size1;
    const int n2 = light.area_size2;
    Vec3 offset;
    if (light.circular && n1 > 1 && n2 > 1) {
        // POV-Ray compat (circular area lights): the square grid's shells are mapped onto circles.
        ju = ju / (n1 - 1) - 0.5 + 0.001;
        jv = jv / (n2 - 1) - 0.5 + 0.001;
        const double scale = std::max(std::fabs(ju), std::fabs(jv)) / std::sqrt(ju * ju + jv * jv);
        offset = axis1 * (ju * scale) + axis2 * (jv * scale);
    } else {
        if (n1 > 1) offset += axis1 * (ju / (n1 - 1) - 0.5);
        if (n2 > 1) offset += axis2 * (jv / (n2 - 1) - 0.5);
    }
    return offset;
}

void LightSampler::area_axes(const scene::Light& light, const Vec3& p, Vec3& axis1, Vec3& axis2) {
    axis1 = light.area_axis1;
    axis2 = light.area_axis2;
    if (light.orient) {
        // POV-Ray compat: `orient` turns the light's square to face the point, both axes as long as axis1.
        const Vec3 d = normalize(light.position - p);
        const Vec3 helper = std::fabs(std::fabs(d.z) - 1.0) < 0.01 ? Vec3{0.0, 1.0, 0.0} : Vec3{0.0, 0.0, 1.0};
        const double len = length(axis1);
        axis1 = normalize(cross(d, helper)) * len;
        axis2 = normalize(cross(d, axis1)) * len;
    }
}

Vec3 LightSampler::area_light_fine(const scene::Light& light, const Vec3& colour, const Vec3& p,
                                   const InteriorStack& interiors, ShadowAtmosphere fog, TraceContext& ctx) const {
    Vec3 axis1, axis2;
    area_axes(light, p, axis1, axis2);
    const int n1 = light.area_size1;
    const int n2 = light.area_size2;
    // POV-Ray's jitter moves grid point u uniformly within [u − ½, u + ½] (area_light_shadow), so over a fully
    // subdivided grid the points are uniform over the grid coordinates [−½, n − ½]²: a finer jittered grid over that
    // range has the same expectation and far less variance.
    const int m = std::max(1, static_cast<int>(std::ceil(std::sqrt(static_cast<double>(m_fine_area_samples)))));
    const int m1 = n1 > 1 ? m : 1, m2 = n2 > 1 ? m : 1;
    cache::SplitMix64 rng(cache::seed_from(p, light.position, reseed(0x41524541ull, m_seed)));
    Vec3 sum;
    for (int a = 0; a < m1; ++a) {
        for (int b = 0; b < m2; ++b) {
            const double ju = n1 > 1 ? -0.5 + n1 * (a + rng.uniform()) / m1 : 0.0;
            const double jv = n2 > 1 ? -0.5 + n2 * (b + rng.uniform()) / m2 : 0.0;
            const Vec3 d = light.position + area_offset(light, axis1, axis2, ju, jv) - p;
            const double distance = length(d);
            sum += distance > 0.0 ? shadow_towards(light, p, d / distance, distance, interiors, fog, ctx)
                                  : Vec3{1.0, 1.0, 1.0};
        }
    }
    return colour * (sum / static_cast<double>(m1 * m2));
}

Vec3 LightSampler::area_light_shadow(const scene::Light& light, const Vec3& colour, const Vec3& p,
                                     const InteriorStack& interiors, ShadowAtmosphere fog,
                                     TraceContext& ctx) const {
    const int n1 = light.area_size1;
    const int n2 = light.area_size2;
    Vec3 axis1, axis2;
    area_axes(light, p, axis1, axis2);
    // Jitter is random in POV-Ray; here it is a fixed function of the point and the seed, so renders repeat exactly.
    cache::SplitMix64 rng(cache::seed_from(p, light.position, reseed(0, m_seed)));
    auto uniform = [&rng]() { return rng.uniform(); };
    std::vector<Vec3> grid(static_cast<std::size_t>(n1) * n2);
    std::vector<char> known(grid.size(), 0);
    // The light arriving from grid point (u, v): the colour taken at the centre, times the shadow towards it.
    auto sample = [&](int u, int v) -> Vec3 {
        const std::size_t k = static_cast<std::size_t>(u) * n2 + v;
        if (known[k]) return grid[k];
        double ju = u, jv = v;
        if (light.jitter) {
            ju += uniform() - 0.5;
            jv += uniform() - 0.5;
        }
        const Vec3 d = light.position + area_offset(light, axis1, axis2, ju, jv) - p;
        const double distance = length(d);
        const Vec3 c = distance > 0.0 ? colour * shadow_towards(light, p, d / distance, distance, interiors, fog, ctx)
                                        : colour;
        grid[k] = c;
        known[k] = 1;
        return c;
    };
    auto differ = [](const Vec3& a, const Vec3& b) {
        return std::fabs(a.x - b.x) + std::fabs(a.y - b.y) + std::fabs(a.z - b.z) > 0.1;
    };
    // POV-Ray's adaptive area light: average the region's four corners, and split it in four while corners differ
    // by more than 0.1 (summed RGB) or the level is below `adaptive`, down to single grid cells.
    auto region = [&](auto&& self, int u1, int v1, int u2, int v2, int level) -> Vec3 {
        Vec3 c[4] = {sample(u1, v1), sample(u2, v1), sample(u1, v2), sample(u2, v2)};
        if ((u2 - u1 > 1 || v2 - v1 > 1) && (level < light.adaptive || differ(c[0], c[1]) || differ(c[1], c[3]) ||
                                             differ(c[3], c[2]) || differ(c[2], c[0]))) {
            const int ul = (u1 + u2) / 2, uh = (u1 + u2 + 1) / 2;
            const int vl = (v1 + v2) / 2, vh = (v1 + v2 + 1) / 2;
            c[0] = self(self, u1, v1, ul, vl, level + 1);
            c[1] = self(self, uh, v1, u2, vl, level + 1);
            c[2] = self(self, u1, vh, ul, v2, level + 1);
            c[3] = self(self, uh, vh, u2, v2, level + 1);
        }
        return (c[0] + c[1] + c[2] + c[3]) * 0.25;
    };
    return region(region, 0, 0, n1 - 1, n2 - 1, 0);
}

}  // namespace wardray::lighting
