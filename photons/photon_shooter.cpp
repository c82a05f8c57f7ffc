// The photon pass: POV-Ray 3.7's light-and-target units, its spacing estimate for `count`, its shooting loop over
// the target's bounding sphere (PhotonShootingTask) and the map build (PhotonSortingTask); photon_trace.cpp
// follows each photon through the scene.
#include "photons/photon_shooter.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>

#include "core/constants.h"
#include "core/render_seed.h"
#include "geometry/object_query.h"
#include "geometry/scene_geometry.h"
#include "photons/photon_random.h"
#include "photons/photon_trace.h"

namespace wardray::photons {

namespace {

constexpr double kDegrees = std::numbers::pi / 180.0;

/// POV-Ray's merged on/off flags of a light and a target: on when one says on and neither says off.
bool merged_on(scene::PhotonSwitch a, scene::PhotonSwitch b) {
    return (a == scene::PhotonSwitch::On || b == scene::PhotonSwitch::On) && a != scene::PhotonSwitch::Off &&
           b != scene::PhotonSwitch::Off;
}

/// POV-Ray's parallel lights: `parallel` ones and cylinder lights, whose rays share one direction.
bool is_parallel(const scene::Light& light) {
    return light.type == scene::Light::Type::Parallel || light.type == scene::Light::Type::Cylinder;
}

/// Rotates `v` about the unit `axis` by `angle` radians (Rodrigues' formula).
Vec3 rotate(const Vec3& v, const Vec3& axis, double angle) {
    const double c = std::cos(angle), s = std::sin(angle);
    return v * c + cross(axis, v) * s + axis * (dot(axis, v) * (1.0 - c));
}

/// POV-Ray's ShootingDirection: the target's bounding sphere seen from a point of the light.
struct Aim {
    Vec3 centre, to_centre, up, left;
    double radius = 0.0, distance = 0.0;

    void from(const Vec3& origin, const scene::Light& light, const Vec3& light_direction) {
        to_centre = centre - origin;
        distance = length(to_centre);
        to_centre = distance > 0.0 ? to_centre / distance : Vec3{0.0, 0.0, 1.0};
        // Too close to vertical for comfort: cross with the horizon instead.
        up = std::fabs(std::fabs(to_centre.z) - 1.0) < 0.1 ? Vec3{0.0, 1.0, 0.0} : Vec3{0.0, 0.0, 1.0};
        left = normalize(cross(is_parallel(light) ? light_direction : to_centre, up));
    }
};

/// One light shooting at one target (POV-Ray's LightTargetCombo).
struct Unit {
    const scene::Light* light = nullptr;
    const scene::Object* target = nullptr;  ///< the target as placed in the world
    std::vector<const scene::Object*> parts;  ///< every object of the target's tree (what counts as hitting it)
    Aim aim;
    Vec3 light_direction;  ///< parallel, spot and cylinder lights: towards point_at
    double spread = 0.0, dtheta = 0.0, max_theta = 0.0;
    std::vector<const scene::Object*> light_interiors;  ///< the objects containing the light's position
};

void collect_parts(const scene::Object& o, std::vector<const scene::Object*>& out) {
    out.push_back(&o);
    if (const auto* csg = std::get_if<scene::Csg>(&o.shape))
        for (const scene::Object& child : csg->children) collect_parts(child, out);
}

/// POV-Ray's SearchThroughObjectsCreateUnits: targets at the top level, else inside CSG; `placed` keeps the
/// world-placed copies of children whose bounds need their parents' transforms.
void find_targets(const scene::Object& o, const Transform& parent, std::vector<Unit>& units,
                  std::vector<std::unique_ptr<scene::Object>>& placed, const scene::Light& light) {
    if (o.photons.target) {
        if (o.no_global_lights) return;
        Unit u;
        u.light = &light;
        collect_parts(o, u.parts);
        auto world = std::make_unique<scene::Object>(o);
        world->transform = o.transform.then(parent);
        u.target = world.get();
        placed.push_back(std::move(world));
        units.push_back(std::move(u));
        return;
    }
    if (const auto* csg = std::get_if<scene::Csg>(&o.shape))
        for (const scene::Object& child : csg->children) find_targets(child, o.transform.then(parent), units, placed, light);
}

/// Both of a unit's switches allow shooting: refraction or reflection merged on.
bool unit_shoots(const Unit& u) {
    const scene::ObjectPhotons& t = u.target->photons;
    return merged_on(u.light->photon_refraction, t.refraction) || merged_on(u.light->photon_reflection, t.reflection);
}

/// POV-Ray's bounding box of an object without bounds (an intersection of planes): the largest box it allows,
/// half of BOUND_HUGE (2e10) to each side. Its photons aim at that box's sphere, so a light inside it shoots all
/// round, and the few photons that reach the target make its map non-empty (which changes its shadows).
constexpr double kUnboundedHalfSide = 1.0e10;

/// POV-Ray's computeAnglesAndDeltas for a unit; false when its spacing leaves nothing to shoot.
bool aim_unit(Unit& u, double spacing, const geometry::ObjectQuery& query) {
    const auto extent = query.extent(*u.target);
    const Vec3 huge{kUnboundedHalfSide, kUnboundedHalfSide, kUnboundedHalfSide};
    const std::pair<Vec3, Vec3> box = extent ? *extent : std::pair{-huge, huge};
    const scene::Light& light = *u.light;
    u.light_direction = normalize(light.point_at - light.position);
    u.aim.centre = (box.first + box.second) * 0.5;
    u.aim.radius = length(u.aim.centre - box.first);
    u.aim.from(light.position, light, u.light_direction);
    u.spread = u.target->photons.spacing_multiplier * spacing;
    if (!is_parallel(light)) u.spread /= u.aim.distance;
    if (light.area && light.photon_area_light) u.spread *= std::sqrt(double(light.area_size1 * light.area_size2));
    if (!(u.spread > 0.0) || !std::isfinite(u.spread)) return false;
    u.dtheta = is_parallel(light) ? u.spread : std::atan(u.spread);
    if (is_parallel(light)) u.max_theta = u.aim.radius;
    else if (u.aim.distance >= u.aim.radius) u.max_theta = std::asin(u.aim.radius / u.aim.distance);
    else u.max_theta = std::numbers::pi;
    return true;
}

/// POV-Ray's PhotonEstimationTask: the photons a unit would store at spacing 1, roughly.
double estimate_count(const Unit& u, double spacing) {
    const scene::ObjectPhotons& t = u.target->photons;
    const bool refraction = merged_on(u.light->photon_refraction, t.refraction);
    const bool reflection = merged_on(u.light->photon_reflection, t.reflection);
    double x = u.aim.radius / (t.spacing_multiplier * spacing);
    x = x * x * std::numbers::pi;
    if (refraction && reflection) x *= 1.5;
    if (t.collect && refraction) x *= reflection ? 3.0 : 2.0;
    return x * 0.5;
}

/// POV-Ray's computeAttenuation: a spot or cylinder light's falloff along a photon's first ray.
double attenuation(const scene::Light& light, const Vec3& dir, const Vec3& axis, double from_axis) {
    using Type = scene::Light::Type;
    auto ramp = [](double low, double high, double x) {
        if (x <= low) return 0.0;
        if (x >= high) return 1.0;
        const double t = (x - low) / (high - low);
        return t * t * (3.0 - 2.0 * t);
    };
    if (light.type == Type::Spot) {
        const double c = dot(dir, axis);
        if (c <= 0.0) return 0.0;
        double a = std::pow(c, light.tightness);
        const double cos_radius = std::cos(light.radius * kDegrees);
        if (cos_radius > 0.0) a *= ramp(std::cos(light.falloff * kDegrees), cos_radius, c);
        return a;
    }
    if (light.type == Type::Cylinder) {
        if (dot(dir, axis) <= 0.0 || !(from_axis < light.falloff)) return 0.0;
        const double closeness = 1.0 - from_axis / light.falloff;
        double a = std::pow(closeness, light.tightness);
        if (light.radius > 0.0 && from_axis > light.radius) a *= ramp(0.0, 1.0 - light.radius / light.falloff, closeness);
        return a;
    }
    return 1.0;
}

/// Shoots one row (one theta) of a unit; returns whether a photon of it reached the target.
bool shoot_row(const Unit& u, double theta, std::uint64_t seed, const PhotonTracer& tracer, std::vector<Photon>& out,
               std::vector<Photon>& media_out, std::uint64_t& shot, double jitter) {
    const scene::Light& light = *u.light;
    Random rng(seed);
    double dphi = 2.0 * std::numbers::pi;
    if (theta >= kPovEpsilon) dphi = is_parallel(light) ? u.dtheta / theta : u.dtheta / std::sin(theta);
    const double min_phi = -std::numbers::pi + dphi * rng.uniform() * 0.5;
    const double max_phi = std::numbers::pi - dphi / 2.0 + (min_phi + std::numbers::pi);
    const bool area = light.area && light.photon_area_light && !is_parallel(light);
    const int nx = area ? light.area_size1 : 1, ny = area ? light.area_size2 : 1;
    const ShotUnit shot_unit{&light, &u.parts, u.spread, is_parallel(light), &u.light_interiors};
    bool hit = false;
    for (double phi = min_phi; phi < max_phi; phi += dphi) {
        const double jphi = phi + dphi * (rng.uniform() - 0.5) * jitter;
        const double jtheta = theta + u.dtheta * (rng.uniform() - 0.5) * jitter;
        for (int ax = 0; ax < nx; ++ax) {
            for (int ay = 0; ay < ny; ++ay) {
                Vec3 origin = light.position;
                Aim aim = u.aim;
                if (area) {
                    // POV-Ray's recomputeForAreaLight: the grid point, aimed at the same sphere.
                    if (nx > 1) origin += light.area_axis1 * (double(ax) / (nx - 1) - 0.5);
                    if (ny > 1) origin += light.area_axis2 * (double(ay) / (ny - 1) - 0.5);
                    aim.from(origin, light, u.light_direction);
                }
                Vec3 dir;
                double from_axis = 0.0;
                if (is_parallel(light)) {
                    // A parallel light's "theta" is a radius across the beam, around the sphere's centre.
                    dir = u.light_direction;
                    origin = aim.centre + dir * (-dot(dir, aim.to_centre) * aim.distance);
                    origin += rotate(aim.left * jtheta, dir, jphi);
                    from_axis = length(origin - light.position);
                } else {
                    const Vec3 v = aim.left * -std::sin(jtheta) + aim.to_centre * std::cos(jtheta);
                    dir = normalize(rotate(v, aim.to_centre, jphi));
                }
                const double a = attenuation(light, dir, u.light_direction, from_axis) / (nx * ny);
                ++shot;
                if (a < 0.00001) continue;
                hit = tracer.shoot(shot_unit, origin, dir, light.color.rgb() * a, out, media_out) || hit;
            }
        }
    }
    return hit;
}

}  // namespace

bool photons_replace_shadow(const scene::Object& blocker, const scene::Light& light) {
    const scene::ObjectPhotons& b = blocker.photons;
    return b.target && b.refraction != scene::PhotonSwitch::Off && light.photon_refraction != scene::PhotonSwitch::Off &&
           (b.refraction == scene::PhotonSwitch::On || light.photon_refraction == scene::PhotonSwitch::On);
}

ShotPhotons shoot_photon_sets(const scene::Scene& scene, const geometry::SceneGeometry& geometry, PhotonStats& stats,
                              void (*progress)(std::uint64_t), std::uint64_t seed) {
    const auto t0 = std::chrono::steady_clock::now();
    const scene::PhotonSettings& settings = *scene.global.photons;
    // The units: every global light but fill lights, with every target, in scene order (POV-Ray 3.7 shoots no
    // photons from the lights of light groups).
    std::vector<Unit> units;
    std::vector<std::unique_ptr<scene::Object>> placed;
    for (const scene::Light& light : scene.lights) {
        if (light.shadowless || light.group != 0) continue;
        for (const scene::Object& o : scene.objects) find_targets(o, Transform{}, units, placed, light);
    }
    const geometry::ObjectQuery query;
    double spacing = settings.spacing;
    std::erase_if(units, [&](Unit& u) { return !unit_shoots(u) || !aim_unit(u, spacing, query); });
    if (settings.count > 0 && !units.empty()) {
        // POV-Ray compat: `count` scales the spacing by the root of the estimated over the wanted count.
        double estimate = 0.0;
        for (const Unit& u : units) estimate += estimate_count(u, spacing);
        spacing *= std::sqrt(estimate / settings.count);
        for (Unit& u : units) aim_unit(u, spacing, query);
    }
    for (Unit& u : units) u.light_interiors = objects_containing(scene, u.light->position);
    stats.spacing = spacing;
    stats.units = units.size();
    const PhotonTracer tracer(scene, geometry, seed, spacing);
    std::vector<Photon> photons, media_photons;
    for (std::size_t ui = 0; ui < units.size(); ++ui) {
        const Unit& u = units[ui];
        const int rows = static_cast<int>(std::ceil(u.max_theta / u.dtheta));
        // Rows in parallel, a batch at a time; autostop (past `autostop` of the sphere, a row missing the target
        // after some row hit it) then cuts the rows in order, as POV-Ray's sequential loop does.
        constexpr int kBatch = 32;
        bool hit_once = false, stopped = false;
        for (int first = 0; first < rows && !stopped; first += kBatch) {
            const int last = std::min(rows, first + kBatch);
            std::vector<std::vector<Photon>> row_photons(last - first), row_media(last - first);
            std::vector<std::uint64_t> row_shot(last - first, 0);
            std::vector<char> row_hit(last - first, 0);
            tbb::parallel_for(first, last, [&](int r) {
                const double theta = r * u.dtheta;
                if (!(theta < u.max_theta)) return;
                const std::uint64_t row_seed = reseed(mix_seed(ui + 1, r), seed);
                row_hit[r - first] = shoot_row(u, theta, row_seed, tracer, row_photons[r - first],
                                               row_media[r - first], row_shot[r - first], settings.jitter);
            });
            for (int r = first; r < last; ++r) {
                const std::size_t i = r - first;
                photons.insert(photons.end(), row_photons[i].begin(), row_photons[i].end());
                media_photons.insert(media_photons.end(), row_media[i].begin(), row_media[i].end());
                stats.shot += row_shot[i];
                hit_once = hit_once || row_hit[i];
                if (hit_once && !row_hit[i] && r * u.dtheta > settings.autostop * u.max_theta) {
                    stopped = true;
                    break;
                }
            }
            if (progress) progress(photons.size() + media_photons.size());
        }
    }
    stats.shoot_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    ShotPhotons shot;
    shot.surface = std::move(photons);
    shot.media = std::move(media_photons);
    shot.surface_offset = tracer.surface_offset();
    shot.media_offset = tracer.media_offset();
    shot.spacing = spacing;
    return shot;
}

std::unique_ptr<const PhotonMap> build_photon_maps(ShotPhotons shot, const scene::PhotonSettings& settings,
                                                   PhotonStats& stats, std::unique_ptr<const PhotonMap>* media_map,
                                                   std::uint64_t seed) {
    const auto t1 = std::chrono::steady_clock::now();
    stats.stored = shot.surface.size();
    stats.media_stored = shot.media.size();
    stats.spacing = shot.spacing;
    if (media_map) {
        media_map->reset();
        if (!shot.media.empty()) {
            *media_map = std::make_unique<const PhotonMap>(std::move(shot.media), settings, true, seed,
                                                             shot.media_offset);
            stats.media_gather_radius = (*media_map)->min_gather_radius();
        }
    }
    std::unique_ptr<const PhotonMap> map;
    if (!shot.surface.empty()) {
        map = std::make_unique<const PhotonMap>(std::move(shot.surface), settings, false, seed, shot.surface_offset);
        stats.gather_radius = map->min_gather_radius();
    }
    stats.build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
    return map;
}

std::unique_ptr<const PhotonMap> shoot_photons(const scene::Scene& scene, const geometry::SceneGeometry& geometry,
                                               PhotonStats& stats, std::unique_ptr<const PhotonMap>* media_map,
                                               void (*progress)(std::uint64_t), std::uint64_t seed) {
    return build_photon_maps(shoot_photon_sets(scene, geometry, stats, progress, seed), *scene.global.photons, stats,
                             media_map, seed);
}

}  // namespace wardray::photons
