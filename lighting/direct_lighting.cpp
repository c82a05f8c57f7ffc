// Integrator: POV-Ray 3.7's direct lighting (ambient, emission, diffuse, phong, specular) with hard shadows.
#include "lighting/direct_lighting.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "geometry/scene_geometry.h"

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

Integrator::Integrator(const parser::Scene& scene, const geometry::SceneGeometry& geometry,
                       IntegratorOptions options)
    : m_scene(scene), m_geometry(geometry), m_options(options) {
    // POV-Ray compat: with radiosity on, a 3.7 scene's `ambient` is not light; a scene that says
    // `#version 3.6` (or older) still gets it.
    m_ambient_is_light = !scene.global.radiosity.has_value() || scene.version < 3.7;
    if (scene.global.radiosity && options.gi != GiMode::Off)
        m_limitations.push_back("radiosity is not computed yet: the image has direct light only");
    for (const parser::Light& light : scene.lights) {
        if (light.type == parser::Light::Type::Cylinder) {
            m_limitations.push_back("cylinder light sources are not rendered yet");
            break;
        }
    }
}

Vec3 Integrator::trace_camera_ray(const geometry::Ray& ray, RayCounters& counters) const {
    ++counters.camera;
    const std::optional<geometry::Hit> hit = m_geometry.intersect(ray);
    if (!hit) return m_scene.background.rgb();
    return shade(*hit, normalize(ray.direction), counters);
}

Vec3 Integrator::light_arriving(const parser::Light& light, const Vec3& p, const Vec3& n, Vec3& to_light,
                                RayCounters& counters) const {
    using Type = parser::Light::Type;
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
    if (dot(n, to_light) <= 0.0) return {};

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
    }
    if (light.fade_distance > 0.0 && light.fade_power > 0.0) {
        // POV-Ray: 2 / (1 + (d / fade_distance)^fade_power); no inverse-square law otherwise.
        attenuation *= 2.0 / (1.0 + std::pow(distance / light.fade_distance, light.fade_power));
    }
    if (attenuation <= 0.0) return {};

    if (!light.shadowless) {
        const double offset = m_geometry.self_intersection_offset(p);
        geometry::Ray shadow{p, to_light, offset, distance - offset, geometry::RayKind::Shadow};
        ++counters.shadow;
        if (shadow.t_max > shadow.t_min && m_geometry.occluded(shadow)) return {};
    }
    return light.color.rgb() * attenuation;
}

Vec3 Integrator::shade(const geometry::Hit& hit, const Vec3& view_dir, RayCounters& counters) const {
    const parser::Object& object = m_scene.objects[hit.object];
    const parser::Finish& finish = object.texture.finish;
    const Vec3 pigment = object.texture.pigment.color.rgb();

    // POV-Ray compat: the normal is turned to face the viewer before lighting.
    Vec3 n = hit.normal;
    if (dot(n, view_dir) > 0.0) n = -n;

    Vec3 colour = pigment * finish.emission.rgb();
    if (m_ambient_is_light) colour += pigment * finish.ambient.rgb() * m_scene.global.ambient_light.rgb();

    const Vec3 reflected = view_dir - 2.0 * dot(view_dir, n) * n;
    for (const parser::Light& light : m_scene.lights) {
        Vec3 to_light;
        const Vec3 arriving = light_arriving(light, hit.position, n, to_light, counters);
        if (arriving == Vec3{}) continue;
        const double cos_i = dot(n, to_light);
        // Lambert with POV-Ray's brilliance exponent: diffuse * cos^brilliance.
        if (finish.diffuse != 0.0) {
            const double shape = finish.brilliance == 1.0 ? cos_i : std::pow(cos_i, finish.brilliance);
            colour += pigment * arriving * (finish.diffuse * shape);
        }
        // POV-Ray compat: shadowless (fill) lights cause no highlights.
        if (light.shadowless) continue;
        // Phong highlight: phong * cos(reflected, light)^phong_size.
        if (finish.phong > 0.0) {
            const double c = dot(reflected, to_light);
            if (c > 0.0) colour += arriving * (finish.phong * std::pow(c, finish.phong_size));
        }
        // Blinn specular: specular * cos(half vector, normal)^(1/roughness).
        if (finish.specular > 0.0) {
            const Vec3 half = normalize(to_light - view_dir);
            const double c = dot(half, n);
            if (c > 0.0) colour += arriving * (finish.specular * std::pow(c, 1.0 / finish.roughness));
        }
    }
    return colour;
}

}  // namespace wardray::lighting
