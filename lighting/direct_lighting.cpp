// Integrator: POV-Ray 3.7's ray recursion (TraceRay), direct light with filtered shadows, sky_sphere and fog.
#include "lighting/direct_lighting.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "cache/hemisphere_sampler.h"
#include "geometry/scene_geometry.h"
#include "texture/noise.h"
#include "texture/pattern.h"
#include "texture/pigment.h"

namespace wardray::lighting {

namespace {

constexpr double kDegrees = std::numbers::pi / 180.0;
constexpr double kEpsilon = 1.0e-10;  // POV-Ray's EPSILON

// POV-Ray compat: the spotlight edge is a cubic (smoothstep) ramp in cos α between falloff and radius.
double smooth_ramp(double low, double high, double x) {
    if (x <= low) return 0.0;
    if (x >= high) return 1.0;
    const double t = (x - low) / (high - low);
    return t * t * (3.0 - 2.0 * t);
}

// POV-Ray's filter colour of a pigment: what passes through it, rgb·filter + transmit.
Vec3 transmittance(const Color& c) { return c.rgb() * c.filter + Vec3{c.transmit, c.transmit, c.transmit}; }

bool pigment_opaque(const scene::Pigment& p) {
    if (p.is_solid()) return p.color.filter == 0.0 && p.color.transmit == 0.0;
    for (const auto& e : p.color_map)
        if (e.color.filter != 0.0 || e.color.transmit != 0.0) return false;
    for (const auto& e : p.pigment_map)
        if (!pigment_opaque(e.pigment)) return false;
    return true;
}

bool texture_opaque(const scene::Texture& t) {
    if (!t.texture_map.empty()) {
        for (const auto& e : t.texture_map)
            if (!texture_opaque(e.texture)) return false;
        return true;
    }
    // POV-Ray compat: only the layers' pigments decide whether light passes.
    if (!pigment_opaque(t.pigment)) return false;
    for (const auto& layer : t.layers)
        if (!texture_opaque(layer)) return false;
    return true;
}

bool object_opaque(const scene::Object& o) {
    if (!texture_opaque(o.texture)) return false;
    if (const auto* csg = std::get_if<scene::Csg>(&o.shape))
        for (const scene::Object& child : csg->children)
            if (!object_opaque(child)) return false;
    return true;
}

}  // namespace

bool InteriorStack::contains(std::uint32_t o) const {
    for (int i = 0; i < size; ++i)
        if (objects[i] == o) return true;
    return false;
}

void InteriorStack::push(std::uint32_t o) {
    if (size < kMax) objects[size++] = o;
}

bool InteriorStack::remove(std::uint32_t o) {
    for (int i = size - 1; i >= 0; --i) {
        if (objects[i] != o) continue;
        for (int j = i; j + 1 < size; ++j) objects[j] = objects[j + 1];
        --size;
        return true;
    }
    return false;
}

Integrator::Integrator(const scene::Scene& scene, const geometry::SceneGeometry& geometry,
                       IntegratorOptions options)
    : m_scene(scene), m_geometry(geometry), m_options(options) {
    // POV-Ray compat: with radiosity on, a 3.7 scene's `ambient` is not light; a scene that says
    // `#version 3.6` (or older) still gets it.
    m_ambient_is_light = !scene.global.radiosity.has_value() || scene.version < 3.7;
    m_noise_generator = scene.global.noise_generator;
    m_gi_enabled = scene.global.radiosity.has_value() && options.gi != GiMode::Off;
    // POV-Ray compat: camera rays start inside every object that contains the camera (an infinite plane's
    // inside too), which changes the relative indices of refraction. Containment is found by the parity of
    // crossings along one ray from the camera.
    {
        std::vector<int> crossings(scene.objects.size(), 0);
        const Vec3 origin = scene.camera.location;
        const Vec3 dir = normalize(Vec3{0.1234, 0.9871, 0.0456});
        double t0 = geometry.self_intersection_offset(origin);
        for (int i = 0; i < 4096; ++i) {
            const std::optional<geometry::Hit> hit =
                geometry.intersect(geometry::Ray{origin, dir, t0, 1e30, geometry::RayKind::Camera});
            if (!hit) break;
            ++crossings[hit->object];
            t0 = hit->t + geometry.self_intersection_offset(hit->position);
        }
        for (std::size_t o = 0; o < crossings.size(); ++o)
            if (crossings[o] % 2 == 1) m_camera_interiors.push(static_cast<std::uint32_t>(o));
    }
    // Shadow rays need to look through objects only when something lets light pass.
    m_opaque.reserve(scene.objects.size());
    for (const scene::Object& o : scene.objects) {
        const bool opaque = object_opaque(o);
        m_opaque.push_back(opaque ? 1 : 0);
        m_any_transparent = m_any_transparent || !opaque;
    }
}

Vec3 Integrator::trace_camera_ray(const geometry::Ray& ray, TraceContext& ctx) const {
    ++ctx.rays.camera;
    RayState state;
    state.adc_bailout = m_scene.global.adc_bailout;
    state.max_level = m_scene.global.max_trace_level;
    state.interiors = m_camera_interiors;
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
    if (hit) {
        depth = hit->t * scale;
        if (hit_distance) *hit_distance = depth;
        colour = shade(*hit, direction, depth, state, ctx);
    } else {
        colour = sky(direction);
    }
    if (!m_scene.fogs.empty()) colour = apply_fog(colour, depth);
    return colour;
}

Vec3 Integrator::sky(const Vec3& direction) const {
    Vec3 colour;
    Vec3 filter{1.0, 1.0, 1.0};
    if (m_scene.sky_sphere) {
        // POV-Ray 3.7's ComputeSky: pigments from the last to the first, each seen through those before it.
        const scene::SkySphere& sky = *m_scene.sky_sphere;
        const Vec3 p = sky.transform.is_identity() ? direction : sky.transform.inverse_point(direction);
        for (auto it = sky.pigments.rbegin(); it != sky.pigments.rend(); ++it) {
            const Color c = texture::evaluate_pigment(*it, p, m_noise_generator);
            colour += c.rgb() * (1.0 - c.filter - c.transmit) * filter * sky.emission.rgb();
            filter = filter * transmittance(c);
        }
    }
    // POV-Ray compat: the background's own filter and transmit are ignored.
    return colour + m_scene.background.rgb() * filter;
}

Vec3 Integrator::apply_fog(const Vec3& colour, double depth) const {
    // POV-Ray's constant fog: attenuation exp(−depth/distance) (at least the fog's transmit), filtered by its
    // colour where it has filter; the rest of the ray sees the fog colour.
    Vec3 attenuation{1.0, 1.0, 1.0};
    Vec3 added;
    for (const scene::Fog& fog : m_scene.fogs) {
        if (std::fabs(fog.distance) <= kEpsilon) continue;
        const Color& c = fog.color;
        double att = std::exp(-depth / fog.distance);
        att = std::max(att, c.transmit);
        attenuation = attenuation * (Vec3{1.0 - c.filter, 1.0 - c.filter, 1.0 - c.filter} + c.rgb() * c.filter) * att;
        added += c.rgb() * (1.0 - att);
    }
    return added + attenuation * colour;
}

Vec3 Integrator::texture_filter(const scene::Texture& texture, const Vec3& p) const {
    if (!texture.texture_map.empty()) {
        const Vec3 tp = texture::warp_point(texture.map_pattern, p);
        const double v = texture::pattern_value(texture.map_pattern, tp, m_noise_generator);
        const auto& map = texture.texture_map;
        const texture::MapLookup m =
            texture::search_map(v, static_cast<int>(map.size()), [&](int i) { return map[i].value; });
        const Vec3 cur = texture_filter(map[m.cur].texture, tp);
        if (m.prev == m.cur) return cur;
        return cur * m.fraction + texture_filter(map[m.prev].texture, tp) * (1.0 - m.fraction);
    }
    Vec3 filter = transmittance(texture::evaluate_pigment(texture.pigment, p, m_noise_generator));
    for (const scene::Texture& layer : texture.layers) filter = filter * texture_filter(layer, p);
    return filter;
}

Vec3 Integrator::shadow_filter(const Vec3& p, const Vec3& dir, double distance, InteriorStack interiors,
                               TraceContext& ctx) const {
    // POV-Ray walks the shadow ray through every surface it crosses, multiplying their filter colours and the
    // fade of the interiors it leaves.
    Vec3 filter{1.0, 1.0, 1.0};
    double t_origin = 0.0;
    double t0 = m_geometry.self_intersection_offset(p);
    const double t1 = distance - t0;
    for (int crossing = 0; crossing < 64 && t0 < t1; ++crossing) {
        ++ctx.rays.shadow;
        const geometry::Ray ray{p, dir, t0, t1, geometry::RayKind::Shadow};
        const std::optional<geometry::Hit> hit = m_geometry.intersect(ray);
        if (!hit) break;
        if (m_opaque[hit->object]) return {};
        const scene::Object& object = hit->leaf ? *hit->leaf : m_scene.objects[hit->object];
        filter = filter * texture_filter(object.texture, hit->position);
        const scene::Interior& interior = m_scene.objects[hit->object].interior;
        if (interiors.contains(hit->object) && interior.fade_power > 0.0 &&
            std::fabs(interior.fade_distance) > kEpsilon) {
            const double d = (hit->t - t_origin) / interior.fade_distance;
            const Vec3 fc = interior.fade_color.rgb();
            const Vec3 one{1.0, 1.0, 1.0};
            if (interior.fade_power >= 1000.0) {
                const Vec3 k = (one - fc) * -d;
                filter = filter * Vec3{std::exp(k.x), std::exp(k.y), std::exp(k.z)};
            } else {
                filter = filter * (fc + (one - fc) / (1.0 + std::pow(d, interior.fade_power)));
            }
        }
        // Entering adds the interior, leaving removes it (POV-Ray's ComputeShadowMedia bookkeeping).
        if (interiors.size == 0 || !interiors.remove(hit->object)) interiors.push(hit->object);
        if (max_abs_component(filter) < kEpsilon) return {};
        t_origin = hit->t;
        t0 = hit->t + m_geometry.self_intersection_offset(hit->position);
    }
    return filter;
}

Vec3 Integrator::light_arriving(const scene::Light& light, const Vec3& p, const Vec3& n,
                                const InteriorStack& interiors, bool area_lights, Vec3& to_light,
                                TraceContext& ctx) const {
    using Type = scene::Light::Type;
    double distance = 0.0;
    if (light.type == Type::Parallel || light.type == Type::Cylinder) {
        // Parallel light arrives along point_at → position; blockers count only up to the plane of the light.
        to_light = normalize(light.position - light.point_at);
        distance = dot(light.position - p, to_light);
        if (distance <= 0.0) return {};
    } else {
        const Vec3 d = light.position - p;
        distance = length(d);
        if (distance <= 0.0) return {};
        to_light = d / distance;
    }
    // POV-Ray compat: lights at grazing angles below EPSILON do not reach the surface.
    if (dot(n, to_light) < kEpsilon) return {};

    double attenuation = 1.0;
    if (light.type == Type::Spot) {
        // POV-Ray: cos α^tightness times the ramp from falloff (dark) to radius (full), angles in degrees.
        const Vec3 axis = normalize(light.point_at - light.position);
        const double cos_alpha = dot(-to_light, axis);
        const double cos_radius = std::cos(light.radius * kDegrees);
        const double cos_falloff = std::cos(light.falloff * kDegrees);
        if (cos_alpha <= cos_falloff) return {};
        if (light.tightness > 0.0) attenuation *= std::pow(cos_alpha, light.tightness);
        if (cos_alpha < cos_radius) attenuation *= smooth_ramp(cos_falloff, cos_radius, cos_alpha);
    } else if (light.type == Type::Cylinder) {
        // POV-Ray's cylinder light: only points ahead of the light and within `falloff` of its axis are lit,
        // (1 − d/falloff)^tightness, with the same cubic ramp between radius and falloff (d: distance from the axis).
        const Vec3 axis = normalize(light.point_at - light.position);
        const Vec3 v = p - light.position;
        const double k = dot(v, axis);
        if (k <= 0.0) return {};
        const double d = length(v - axis * k);
        if (!(d < light.falloff)) return {};
        const double closeness = 1.0 - d / light.falloff;
        attenuation *= std::pow(closeness, light.tightness);
        if (light.radius > 0.0 && d > light.radius)
            attenuation *= smooth_ramp(0.0, 1.0 - light.radius / light.falloff, closeness);
    }
    if (light.fade_distance > 0.0 && light.fade_power > 0.0) {
        // POV-Ray: 2 / (1 + (d / fade_distance)^fade_power); no inverse-square law otherwise.
        attenuation *= 2.0 / (1.0 + std::pow(distance / light.fade_distance, light.fade_power));
    }
    if (attenuation <= 0.0) return {};

    const Vec3 colour = light.color.rgb() * attenuation;
    if (light.shadowless) return colour;
    if (area_lights && light.area && (light.area_size1 > 1 || light.area_size2 > 1) && light.type != Type::Parallel &&
        light.type != Type::Cylinder)
        return area_light_shadow(light, colour, p, interiors, ctx);
    return colour * shadow_towards(p, to_light, distance, interiors, ctx);
}

Vec3 Integrator::shadow_towards(const Vec3& p, const Vec3& dir, double distance, const InteriorStack& interiors,
                                TraceContext& ctx) const {
    if (m_any_transparent) return shadow_filter(p, dir, distance, interiors, ctx);
    const double offset = m_geometry.self_intersection_offset(p);
    geometry::Ray shadow{p, dir, offset, distance - offset, geometry::RayKind::Shadow};
    ++ctx.rays.shadow;
    if (shadow.t_max > shadow.t_min && m_geometry.occluded(shadow)) return {};
    return {1.0, 1.0, 1.0};
}

Vec3 Integrator::area_light_shadow(const scene::Light& light, const Vec3& colour, const Vec3& p,
                                   const InteriorStack& interiors, TraceContext& ctx) const {
    const int n1 = light.area_size1;
    const int n2 = light.area_size2;
    Vec3 axis1 = light.area_axis1;
    Vec3 axis2 = light.area_axis2;
    if (light.orient) {
        // POV-Ray compat: `orient` turns the light's square to face the point, both axes as long as axis1.
        const Vec3 d = normalize(light.position - p);
        const Vec3 helper = std::fabs(std::fabs(d.z) - 1.0) < 0.01 ? Vec3{0.0, 1.0, 0.0} : Vec3{0.0, 0.0, 1.0};
        const double len = length(axis1);
        axis1 = normalize(cross(d, helper)) * len;
        axis2 = normalize(cross(d, axis1)) * len;
    }
    // Jitter is random in POV-Ray; here it is a fixed function of the point, so renders repeat exactly.
    cache::SplitMix64 rng(cache::seed_from(p, light.position));
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
        const Vec3 d = light.position + offset - p;
        const double distance = length(d);
        const Vec3 c = distance > 0.0 ? colour * shadow_towards(p, d / distance, distance, interiors, ctx) : colour;
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

Vec3 Integrator::direct_light(const scene::Finish& finish, const Vec3& pigment, double opacity, const Surface& s,
                              const Vec3& n, TraceContext& ctx) const {
    Vec3 colour;
    const Vec3& view_dir = s.direction;
    const Vec3 reflected = view_dir - 2.0 * dot(view_dir, n) * n;
    // POV-Ray's metallic highlight tint: 1 + metallic·(1 − F)·(pigment − 1), F an empirical Fresnel curve.
    auto metallic_tint = [&](double cos_light) {
        const double x = std::fabs(std::acos(std::clamp(cos_light, -1.0, 1.0))) / (std::numbers::pi / 2.0);
        const double f = std::clamp(0.014567225 / ((x - 1.12) * (x - 1.12)) - 0.011612903, 0.0, 1.0);
        return Vec3{1.0, 1.0, 1.0} + (pigment - Vec3{1.0, 1.0, 1.0}) * (finish.metallic * (1.0 - f));
    };
    for (const scene::Light& light : m_scene.lights) {
        Vec3 to_light;
        // POV-Ray compat (GetRadiosityQualityFlags): on a gather ray's path area lights are point lights.
        const Vec3 arriving = light_arriving(light, s.hit->position, n, *s.interiors, s.highlights, to_light, ctx);
        if (arriving == Vec3{}) continue;
        const double cos_i = dot(n, to_light);
        Vec3 light_colour;  // this light's diffuse and highlights
        // Lambert with POV-Ray's brilliance exponent: diffuse · opacity · cos^brilliance.
        if (finish.diffuse > 0.0) {
            const double shape = finish.brilliance == 1.0 ? std::fabs(cos_i) : std::pow(std::fabs(cos_i), finish.brilliance);
            light_colour += pigment * arriving * (finish.diffuse * opacity * shape);
        }
        // POV-Ray compat: shadowless (fill) lights cause no highlights, nor does any light on a gather ray's path.
        if (light.shadowless || !s.highlights) {
            if (finish.irid > 0.0)
                light_colour = light_colour * iridescence(finish, to_light, view_dir, n, s.hit->position);
            colour += light_colour;
            continue;
        }
        const Vec3 tint = finish.metallic > 0.0 ? metallic_tint(cos_i) : Vec3{1.0, 1.0, 1.0};
        // Phong highlight: phong · cos(reflected, light)^phong_size (POV-Ray drops tiny values for sizes ≥ 60).
        if (finish.phong > 0.0) {
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
        if (finish.irid > 0.0)
            light_colour = light_colour * iridescence(finish, to_light, view_dir, n, s.hit->position);
        colour += light_colour;
    }
    return colour;
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
