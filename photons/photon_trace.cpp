// PhotonTracer: POV-Ray 3.7's photon path (PhotonTrace::TraceRay, ComputeLightedTexture for photons,
// ComputeRefractionForPhotons) on Embree: photons pass only targets and pass_through objects until they first
// refract or reflect, then land on every collecting surface, carrying the flux of their share of the light.
#include "photons/photon_trace.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "core/constants.h"
#include "geometry/object_query.h"
#include "geometry/scene_geometry.h"
#include "media/participating_media.h"
#include "media/transmittance.h"
#include "photons/reflectivity.h"
#include "texture/normal.h"
#include "texture/pattern.h"
#include "texture/pigment.h"

namespace wardray::photons {

namespace {

double max3(const Vec3& c) { return std::max(c.x, std::max(c.y, c.z)); }

bool switch_on(scene::PhotonSwitch object, scene::PhotonSwitch light) {
    return (object == scene::PhotonSwitch::On && light != scene::PhotonSwitch::Off) ||
           (object != scene::PhotonSwitch::Off && light == scene::PhotonSwitch::On);
}

/// The index of the innermost entry of `interiors` that has the interior of `o`, or -1.
std::ptrdiff_t find_interior(const std::vector<const scene::Object*>& interiors, const scene::Object& o) {
    for (auto i = static_cast<std::ptrdiff_t>(interiors.size()) - 1; i >= 0; --i)
        if (scene::same_interior(*interiors[i], o)) return i;
    return -1;
}

}  // namespace

std::vector<const scene::Object*> objects_containing(const scene::Scene& scene, const Vec3& p) {
    std::vector<const scene::Object*> out;
    const geometry::ObjectQuery query;
    for (const scene::Object& o : scene.objects)
        if (query.inside(o, p) && find_interior(out, o) < 0) out.push_back(&o);
    return out;
}

/// What one photon's path carries: POV-Ray's thread variables of the photon pass.
struct PhotonTracer::Path {
    const ShotUnit* unit = nullptr;
    std::vector<Photon>* out = nullptr;
    std::vector<Photon>* media_out = nullptr;
    int level = 0;
    bool pass_prev = true;
    bool pass_this = false;
    double depth = 0.0;  ///< POV-Ray's photonDepth: the distance travelled from the light
    bool hit_target = false;
};

PhotonTracer::PhotonTracer(const scene::Scene& scene, const geometry::SceneGeometry& geometry, std::uint64_t seed,
                           double spacing)
    : m_scene(scene), m_geometry(geometry), m_noise_generator(scene.global.noise_generator),
      m_surface_offset(flux_exponent_offset(spacing, 2)), m_media_offset(flux_exponent_offset(spacing, 3)) {
    const scene::PhotonSettings& s = *scene.global.photons;
    m_max_level = s.max_trace_level >= 0 ? s.max_trace_level : scene.global.max_trace_level;
    m_bailout = s.adc_bailout >= 0.0 ? s.adc_bailout : scene.global.adc_bailout;
    if (media::ParticipatingMedia::in_scene(scene))
        m_media = std::make_unique<const media::ParticipatingMedia>(scene, seed);
}

PhotonTracer::~PhotonTracer() = default;

bool PhotonTracer::shoot(const ShotUnit& unit, const Vec3& origin, const Vec3& dir, const Vec3& colour,
                         std::vector<Photon>& out, std::vector<Photon>& media_out) const {
    Path path;
    path.unit = &unit;
    path.out = &out;
    path.media_out = &media_out;
    RayIn ray{origin, dir, {}, {}};
    ray.interiors = origin == unit.light->position && unit.light_interiors ? *unit.light_interiors
                                                                            : objects_containing(m_scene, origin);
    trace(ray, colour, 1.0, path);
    return path.hit_target;
}

void PhotonTracer::trace(const RayIn& ray, Vec3 colour, double weight, Path& path) const {
    if (path.level >= m_max_level || weight < m_bailout) return;
    ++path.level;
    const geometry::Ray r{ray.origin, ray.dir, m_geometry.self_intersection_offset(ray.origin), 1e30,
                          geometry::RayKind::Shadow};
    const std::optional<geometry::Hit> hit = m_geometry.intersect(r);
    if (hit) {
        const scene::Object& leaf = hit->leaf ? *hit->leaf : m_scene.objects[hit->object];
        const bool old = path.pass_prev;
        path.pass_prev = path.pass_this;
        path.pass_this = false;
        // Until it has refracted or reflected, a photon passes only pass_through objects on its way to the target.
        bool stop = false;
        if (path.level == 1 || path.pass_prev) {
            const auto& parts = *path.unit->parts;
            const bool in_target = std::find(parts.begin(), parts.end(), &leaf) != parts.end() ||
                                   std::find(parts.begin(), parts.end(), &m_scene.objects[hit->object]) != parts.end();
            if (leaf.photons.target && in_target) path.hit_target = true;
            else if (leaf.photons.pass_through) path.pass_this = true;
            else stop = true;
        }
        if (!stop) {
            Vec3 raw = hit->normal;
            if (dot(raw, ray.dir) > 0.0) raw = -raw;
            const bool inside = !leaf.interior_texture.empty() && dot(hit->normal, ray.dir) > 0.0;
            std::vector<const scene::Pattern*> warps;
            texture(inside ? leaf.interior_texture.front() : *leaf.texture, hit->position, warps, *hit, raw, ray,
                    colour, weight, path);
        }
        path.pass_this = path.pass_prev;
        path.pass_prev = old;
    }
    --path.level;
}

void PhotonTracer::texture(const scene::Texture& tx, const Vec3& p, std::vector<const scene::Pattern*>& warps,
                           const geometry::Hit& hit, const Vec3& raw, const RayIn& ray, Vec3 colour, double weight,
                           Path& path) const {
    if (tx.texture_map.empty()) {
        surface(tx, p, warps, hit, raw, ray, colour, weight, path);
        return;
    }
    // A texture map splits the photon between the two entries around the pattern's value (by their weights for
    // an average map).
    const scene::Pattern& pattern = tx.map_pattern;
    const Vec3 tp = texture::warp_point(pattern, p);
    const auto& map = tx.texture_map;
    warps.push_back(&pattern);
    if (pattern.type == scene::Pattern::Type::Average) {
        float total = 0.0f;
        for (const auto& e : map) total += static_cast<float>(e.value);
        for (const auto& e : map) texture(e.texture, tp, warps, hit, raw, ray, colour * (e.value / total), weight, path);
    } else {
        const texture::SurfacePoint at{hit.position, raw, ray.dir};
        const double v = texture::pattern_value(pattern, tp, m_noise_generator, &at);
        const texture::MapLookup m = texture::search_map(v, static_cast<int>(map.size()), [&](int i) { return map[i].value; });
        if (m.prev == m.cur) {
            texture(map[m.cur].texture, tp, warps, hit, raw, ray, colour, weight, path);
        } else {
            texture(map[m.cur].texture, tp, warps, hit, raw, ray, colour * m.fraction, weight, path);
            texture(map[m.prev].texture, tp, warps, hit, raw, ray, colour * (1.0 - m.fraction), weight, path);
        }
    }
    warps.pop_back();
}

void PhotonTracer::surface(const scene::Texture& tx, const Vec3& p, const std::vector<const scene::Pattern*>& warps,
                           const geometry::Hit& hit, const Vec3& raw, const RayIn& ray, Vec3 colour, double weight,
                           Path& path) const {
    // POV-Ray compat: the interior is the leaf's (a CSG child's own, or the one it shares with its parent).
    const scene::Object& leaf = hit.leaf ? *hit.leaf : m_scene.objects[hit.object];
    const scene::Interior& interior = leaf.interior;
    const bool inside_this = find_interior(ray.interiors, leaf) >= 0;
    if (m_media) through_media(hit, ray, colour, path);
    // POV-Ray's 3.1 `refraction` amount of the surface's interior, and its fade over the stretch travelled inside.
    if (interior.refraction != 1.0) colour = colour * interior.refraction;
    if (inside_this && interior.fade_power > 0.0 && std::fabs(interior.fade_distance) > kPovEpsilon)
        colour = colour * media::interior_fade(interior, hit.t);
    path.depth += hit.t;
    // Store where it lands, once it has refracted or reflected (POV-Ray's addSurfacePhoton), with the flux of its
    // share of the light: colour · spread² · distance² (not for parallel light), undoing the light's fade.
    const ShotUnit& unit = *path.unit;
    if (path.level > 1 && !path.pass_prev && leaf.photons.collect) {
        const scene::Light& light = *unit.light;
        double a = 1.0;
        if (light.fade_power > 0.0 && std::fabs(light.fade_distance) > kPovEpsilon)
            a = 2.0 / (1.0 + std::pow(path.depth / light.fade_distance, light.fade_power));
        Vec3 flux = colour * (a * unit.spread * unit.spread);
        if (!unit.parallel) flux = flux * (path.depth * path.depth);
        path.out->push_back(make_photon(hit.position, flux, ray.origin, m_surface_offset));
    }
    // The layers, top first: their normals, reflectivities and what they let through.
    constexpr std::size_t kMaxLayers = 8;
    std::array<const scene::Texture*, kMaxLayers> layers{};
    std::size_t count = 0;
    for (auto it = tx.layers.rbegin(); it != tx.layers.rend() && count + 1 < kMaxLayers; ++it) layers[count++] = &*it;
    layers[count++] = &tx;
    struct Layer {
        double weight;
        Vec3 normal, reflectivity;
        double exponent;
    };
    std::array<Layer, kMaxLayers> list{};
    std::size_t listed = 0;
    Vec3 filter{1.0, 1.0, 1.0};
    double trans = 1.0;
    Vec3 top_normal = raw, normal = raw;
    texture::SurfacePoint at{hit.position, raw, ray.dir};
    for (std::size_t li = 0; li < count && trans > m_bailout; ++li) {
        const scene::Texture& layer = *layers[li];
        normal = raw;
        if (layer.normal.pattern.type != scene::Pattern::Type::None) {
            for (const scene::Pattern* w : warps) normal = texture::warp_normal(*w, normal);
            normal = texture::perturb_normal(layer.normal, normal, p, m_noise_generator, &at);
            at.normal = normal;  // POV-Ray compat: the layers' pigments see this normal (its PNormal)
            for (auto it = warps.rbegin(); it != warps.rend(); ++it) normal = texture::unwarp_normal(**it, normal);
        }
        if (li == 0) top_normal = normal;
        const Color pc = texture::evaluate_pigment(layer.pigment, p, m_noise_generator, &at);
        // POV-Ray compat (photon pass): the layer's colour is filtered by the layers above before it tints the
        // metallic reflection and the filter.
        const Vec3 lay = pc.rgb() * filter;
        Layer l{weight * trans, normal, {}, layer.finish.reflection_exponent};
        const double cos_i = -dot(ray.dir, normal);
        double ior = 1.0;
        if (layer.finish.reflection_fresnel) {
            const auto& in = ray.interiors;
            const double top = in.empty() ? 1.0 : in.back()->interior.ior;
            if (in.empty()) ior = interior.ior;
            else if (inside_this) ior = in.size() == 1 ? 1.0 / interior.ior : top / interior.ior;
            else ior = interior.ior / top;
        }
        l.reflectivity = reflectivity(layer.finish, cos_i, ior, l.weight);
        if (layer.finish.reflection_metallic != 0.0) {
            const double x = std::fabs(std::acos(std::clamp(cos_i, -1.0, 1.0))) / (std::numbers::pi / 2.0);
            const double f = std::clamp(0.014567225 / ((x - 1.12) * (x - 1.12)) - 0.011612903, 0.0, 1.0);
            const double rm = layer.finish.reflection_metallic;
            l.reflectivity = l.reflectivity * (Vec3{1.0, 1.0, 1.0} + (lay - Vec3{1.0, 1.0, 1.0}) * (rm * (1.0 - f)));
        }
        list[listed++] = l;
        filter = filter * (lay * pc.filter + Vec3{pc.transmit, pc.transmit, pc.transmit});
        if (layer.finish.conserve_energy) {
            const Vec3& rf = l.reflectivity;
            filter = filter * Vec3{std::min(1.0, 1.0 - rf.x), std::min(1.0, 1.0 - rf.y), std::min(1.0, 1.0 - rf.z)};
        }
        trans = std::min(1.0, std::fabs(texture::grey(filter)));
    }
    if (path.pass_this) {
        // POV-Ray compat (photons.cpp is built with PT_FILTER_BEFORE_TARGET): a pass_through object met before the
        // target lets the photon on in the same direction, filtered by its layers as a transmitted ray would be,
        // and its depth is not taken back.
        RayIn next{hit.position, ray.dir, ray.interiors, ray.band};
        const std::ptrdiff_t i = find_interior(next.interiors, leaf);
        if (i >= 0) next.interiors.erase(next.interiors.begin() + i);
        else next.interiors.push_back(&leaf);
        trace(next, colour * filter, weight * std::max(max3(filter), 0.0), path);
        return;
    }
    bool total_internal = false;
    if (switch_on(leaf.photons.refraction, unit.light->photon_refraction) && trans > m_bailout) {
        const double w = weight * std::max(max3(filter), 0.0);
        total_internal = refract(hit, top_normal, raw, ray, colour, filter, w, path);
    }
    if (switch_on(leaf.photons.reflection, unit.light->photon_reflection)) {
        for (std::size_t i = 0; i < listed; ++i) {
            const Layer& l = list[i];
            const Vec3 d = top_normal - l.normal;
            const bool same = std::fabs(d.x) <= kPovEpsilon && std::fabs(d.y) <= kPovEpsilon && std::fabs(d.z) <= kPovEpsilon;
            if ((total_internal && same) || l.reflectivity == Vec3{}) continue;
            Vec3 c = colour;
            if (l.exponent != 1.0) {
                const double e = 1.0 / l.exponent;
                c = {std::pow(c.x, e), std::pow(c.y, e), std::pow(c.z, e)};
            }
            // POV-Ray compat: every layer's reflection leaves about the last layer's normal.
            reflect(hit, normal, raw, ray, l.reflectivity * c, l.weight * max3(l.reflectivity), path);
        }
    }
    path.depth -= hit.t;
}

bool PhotonTracer::refract(const geometry::Hit& hit, const Vec3& normal, const Vec3& raw, const RayIn& ray,
                           const Vec3& colour, const Vec3& filter, double weight, Path& path) const {
    // POV-Ray's interior bookkeeping and relative index and dispersion, as for camera rays.
    const scene::Object& leaf = hit.leaf ? *hit.leaf : m_scene.objects[hit.object];
    const scene::Interior& inner = leaf.interior;
    RayIn next{hit.position, ray.dir, ray.interiors, ray.band};
    auto& in = next.interiors;
    double ior = 1.0, dispersion = 1.0;
    int bands = inner.dispersion_samples;
    if (in.empty()) {
        in.push_back(&leaf);
        ior = 1.0 / inner.ior;
        dispersion = 1.0 / inner.dispersion;
    } else if (scene::same_interior(*in.back(), leaf)) {
        in.pop_back();
        if (in.empty()) {
            ior = inner.ior;
            dispersion = inner.dispersion;
        } else {
            const scene::Interior& outer = in.back()->interior;
            ior = inner.ior / outer.ior;
            dispersion = inner.dispersion / outer.dispersion;
            bands = std::max(bands, outer.dispersion_samples);
        }
    } else if (const std::ptrdiff_t i = find_interior(in, leaf); i >= 0) {
        in.erase(in.begin() + i);
    } else {
        const scene::Interior& outer = in.back()->interior;
        ior = outer.ior / inner.ior;
        dispersion = outer.dispersion / inner.dispersion;
        in.push_back(&leaf);
    }
    if (std::fabs(ior - 1.0) < kPovEpsilon && std::fabs(dispersion - 1.0) < kPovEpsilon) {
        trace(next, colour * filter, weight, path);
        return false;
    }
    if (std::fabs(dispersion - 1.0) < kPovEpsilon)
        return refract_ray(hit, normal, raw, ray, next, ior, colour, filter, weight, path);
    // A photon already split keeps its band; white light splits here into one photon per band, each with its
    // share of the colour weighted by the band's hue (POV-Ray 3.7 splits at the surface rather than giving each
    // photon a band when it is shot).
    if (ray.band.monochromatic())
        return refract_ray(hit, normal, raw, ray, next, dispersion_ior(ior, dispersion, ray.band), colour, filter,
                           weight, path);
    for (int b = 0; b < bands; ++b) {
        next.band = SpectralBand{b, bands};
        const Vec3 share = colour * band_hue(next.band) / static_cast<double>(bands);
        // POV-Ray compat: a band's total internal reflection is not reported upward.
        (void)refract_ray(hit, normal, raw, ray, next, dispersion_ior(ior, dispersion, next.band), share, filter,
                          weight, path);
    }
    return false;
}

bool PhotonTracer::refract_ray(const geometry::Hit& hit, const Vec3& normal, const Vec3& raw, const RayIn& ray,
                               RayIn& next, double ior, const Vec3& colour, const Vec3& filter, double weight,
                               Path& path) const {
    // Snell's law in vector form (Heckbert 1989).
    double cos_n = dot(ray.dir, normal);
    Vec3 local = -normal;
    if (cos_n <= 0.0) {
        local = normal;
        cos_n = -cos_n;
    }
    const double t = 1.0 + ior * ior * (cos_n * cos_n - 1.0);
    if (t < 0.0) {
        reflect(hit, normal, raw, ray, colour, weight, path);
        return true;
    }
    next.dir = normalize(ray.dir * ior + local * (ior * cos_n - std::sqrt(t)));
    trace(next, colour * filter, weight, path);
    return false;
}

void PhotonTracer::through_media(const geometry::Hit& hit, const RayIn& ray, Vec3& colour, Path& path) const {
    // POV-Ray compat: media act only in hollow objects, and only those of the objects the ray is in (the
    // atmosphere's keep no photons and, in the photon pass, do not dim them).
    media::MediaList list;
    for (const scene::Object* o : ray.interiors) {
        if (!o->interior.hollow) return;
        list.add(o->interior.media);
    }
    if (list.empty()) return;
    const media::Segment segment{ray.origin, ray.dir, hit.t};
    const scene::PhotonSettings& settings = *m_scene.global.photons;
    if (path.level <= 1 || path.pass_prev || settings.media_steps <= 0) {
        colour = colour * m_media->transmittance(list, segment);
        return;
    }
    // POV-Ray's DepositMediaPhotons and addMediaPhoton: each photon kept along the ray carries the flux of the
    // stretch of beam it stands for, colour · factor · spread · distance (its length) times spread² · distance²
    // (its cross-section), undoing the light's fade; distances from the light.
    const ShotUnit& unit = *path.unit;
    const scene::Light& light = *unit.light;
    media::PhotonDeposit deposit;
    deposit.step = unit.parallel ? unit.spread : unit.spread * path.depth;
    deposit.factor = settings.media_factor;
    deposit.max_steps = settings.media_steps;
    deposit.jitter = settings.jitter;
    std::vector<media::DepositPoint> points;
    const Vec3 incoming = colour;
    colour = m_media->deposit_photons(list, segment, incoming, deposit, points);
    for (const media::DepositPoint& d : points) {
        const double depth = path.depth + d.t;
        double a = 1.0;
        if (light.fade_power > 0.0 && std::fabs(light.fade_distance) > kPovEpsilon)
            a = 2.0 / (1.0 + std::pow(depth / light.fade_distance, light.fade_power));
        Vec3 flux = incoming * (d.factor * unit.spread * a * unit.spread * unit.spread);
        if (!unit.parallel) flux = flux * (depth * depth * depth);
        path.media_out->push_back(make_photon(ray.origin + ray.dir * d.t, flux, ray.origin, m_media_offset));
    }
}

void PhotonTracer::reflect(const geometry::Hit& hit, const Vec3& n, const Vec3& raw, const RayIn& ray,
                           const Vec3& colour, double weight, Path& path) const {
    // The mirror direction, bent back above the true surface as POV-Ray does for bumped normals.
    Vec3 d = ray.dir - 2.0 * dot(ray.dir, n) * n;
    const double k = dot(d, raw);
    if (k < 0.0) {
        if (dot(d, n) < 0.0) d = ray.dir - 2.0 * dot(ray.dir, raw) * raw;
        else d += -2.0 * k * raw;
    }
    const RayIn next{hit.position, normalize(d), ray.interiors, ray.band};
    trace(next, colour, weight, path);
}

}  // namespace wardray::photons
