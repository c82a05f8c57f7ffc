// Surface shading: POV-Ray 3.7's texture evaluation (texture maps, layers, normals, finishes), transparency,
// refraction through interiors and reflection (trace.cpp's ComputeLightedTexture and friends).
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "geometry/mesh.h"
#include "geometry/scene_geometry.h"
#include "core/constants.h"
#include "lighting/integrator.h"
#include "lighting/metallic.h"
#include "photons/dispersion.h"
#include "photons/photon_map.h"
#include "photons/reflectivity.h"
#include "media/transmittance.h"
#include "texture/image_map.h"
#include "lighting/mesh_texture.h"
#include "lighting/blob_texture.h"
#include "texture/normal.h"
#include "texture/pattern.h"
#include "texture/pigment.h"

namespace wardray::lighting {

namespace {

double max3(const Vec3& c) { return std::max(c.x, std::max(c.y, c.z)); }

// One layer's reflection, gathered while the layers are shaded and traced afterwards.
struct LayerReflection {
    double weight;
    Vec3 normal;
    Vec3 reflectivity;
    double exponent;
};

}  // namespace

using photons::reflectivity;

Vec3 Integrator::shade(const geometry::Hit& hit, const Vec3& direction, double depth, const RayState& state,
                       TraceContext& ctx) const {
    // The leaf primitive carries the texture (a CSG child's own or the one it inherited).
    const scene::Object& object = hit.leaf ? *hit.leaf : m_scene.objects[hit.object];
    Surface s;
    s.hit = &hit;
    s.object = &object;
    s.p_texture = hit.position;
    s.direction = direction;
    // POV-Ray compat: the normal is turned to face the incoming ray before anything else.
    s.raw_normal = dot(hit.normal, direction) > 0.0 ? -hit.normal : hit.normal;
    s.depth = depth;
    s.interiors = &state.interiors;
    s.highlights = !state.gather_ray;
    s.path_seed = state.path_seed;
    s.path = {state.path_group, state.path_index, state.path_count, state.gi_depth};
    texture::SurfacePoint surface{hit.position, s.raw_normal, direction, m_quality.quick_colors};
    s.surface = &surface;
    std::vector<const scene::Pattern*> warps;
    // POV-Ray compat: a surface met from inside shows its interior texture, when it has one.
    const bool inside = !object.interior_texture.empty() && dot(hit.normal, direction) > 0.0;
    const scene::Texture& texture = inside ? object.interior_texture.front() : *object.texture;
    const auto* mesh = hit.face >= 0 ? std::get_if<scene::Mesh>(&object.shape) : nullptr;
    if (mesh == nullptr) {
        if (const auto* patch = std::get_if<scene::BicubicPatch>(&object.shape); patch && hit.has_params)
            s.p_uv = geometry::bicubic_patch_uv(*patch, hit.params);
        if (object.uv_mapping) s.p_texture = s.p_uv;
        const auto* blob = std::get_if<scene::Blob>(&object.shape);
        if (blob == nullptr || blob->textures.empty()) return shade_texture(texture, s, warps, state, ctx);
        // POV-Ray compat: a blob with component textures blends their lit colours by the components' densities
        // (and shows no interior texture).
        WeightedTextures weighted;
        blob_textures(*blob, *object.texture, hit.position, weighted);
        if (weighted.empty()) return shade_texture(*object.texture, s, warps, state, ctx);
        if (weighted.size() == 1) return shade_texture(*weighted[0].first, s, warps, state, ctx);
        Vec3 colour;
        double transmit = 0.0;
        for (const auto& [tx, w] : weighted) {
            colour += shade_texture(*tx, s, warps, state, ctx) * w;
            transmit += ctx.transmit * w;
        }
        ctx.transmit = transmit;
        return colour;
    }
    s.p_uv = mesh_uv(*mesh, hit);
    if (object.uv_mapping) s.p_texture = s.p_uv;
    std::array<const scene::Texture*, 3> textures{};
    std::array<double, 3> weights{};
    const int count = inside ? 0 : mesh_face_textures(*mesh, object, hit, textures, weights);
    if (count == 0) return shade_texture(texture, s, warps, state, ctx);
    if (count == 1) return shade_texture(*textures[0], s, warps, state, ctx);
    // POV-Ray compat: a triangle with a texture per corner blends the three lit colours.
    Vec3 colour;
    double transmit = 0.0;
    for (int k = 0; k < 3; ++k) {
        colour += shade_texture(*textures[k], s, warps, state, ctx) * weights[k];
        transmit += ctx.transmit * weights[k];
    }
    ctx.transmit = transmit;
    return colour;
}

Vec3 Integrator::shade_texture(const scene::Texture& texture, Surface s, std::vector<const scene::Pattern*>& warps,
                               const RayState& state, TraceContext& ctx) const {
    if (texture.uv_mapping) s.p_texture = s.p_uv;
    if (texture.texture_map.empty()) return shade_layers(texture, s, warps, state, ctx);
    // texture_map: each entry is lit on its own at the map's warped point, and the colours are blended.
    const scene::Pattern& pattern = texture.map_pattern;
    s.p_texture = texture::warp_point(pattern, s.p_texture);
    const auto& map = texture.texture_map;
    if (pattern.type == scene::Pattern::Type::Average) return shade_average(texture, s, warps, state, ctx);
    if (texture.material_map) {
        // material_map: the image picks one material, lit on its own at the map's warped point.
        const int i = texture::material_map_index(*texture.material_map, s.p_texture, static_cast<int>(map.size()));
        warps.push_back(&pattern);
        const Vec3 colour = shade_texture(map[static_cast<std::size_t>(i)].texture, s, warps, state, ctx);
        warps.pop_back();
        return colour;
    }
    const double value = texture::pattern_value(pattern, s.p_texture, m_noise_generator, s.surface);
    const texture::MapLookup m =
        texture::search_map(value, static_cast<int>(map.size()), [&](int i) { return map[i].value; });
    warps.push_back(&pattern);
    Vec3 colour = shade_texture(map[m.cur].texture, s, warps, state, ctx);
    if (m.prev != m.cur) {
        const double transmit = ctx.transmit;
        const Vec3 other = shade_texture(map[m.prev].texture, s, warps, state, ctx);
        colour = colour * m.fraction + other * (1.0 - m.fraction);
        ctx.transmit = transmit * m.fraction + ctx.transmit * (1.0 - m.fraction);
    }
    warps.pop_back();
    return colour;
}

Vec3 Integrator::shade_average(const scene::Texture& texture, const Surface& s,
                               std::vector<const scene::Pattern*>& warps, const RayState& state,
                               TraceContext& ctx) const {
    // POV-Ray's ComputeAverageTextureColours: the entries lit on their own, weighted by their map values.
    warps.push_back(&texture.map_pattern);
    Vec3 sum;
    double transmit = 0.0;
    float total = 0.0f;
    for (const scene::TextureMapEntry& e : texture.texture_map) {
        sum += shade_texture(e.texture, s, warps, state, ctx) * e.value;
        transmit += ctx.transmit * e.value;
        total += static_cast<float>(e.value);
    }
    warps.pop_back();
    ctx.transmit = transmit / static_cast<double>(total);
    return sum / static_cast<double>(total);
}

Vec3 Integrator::shade_layers(const scene::Texture& texture, const Surface& s,
                              const std::vector<const scene::Pattern*>& warps, const RayState& state,
                              TraceContext& ctx) const {
    // POV-Ray's last listed texture is the top layer; the texture holds the bottom layer and the layers over it.
    // Fixed-size storage keeps the common single-layer case free of allocations.
    constexpr std::size_t kMaxLayers = 8;
    std::array<const scene::Texture*, kMaxLayers> layers{};
    std::size_t layer_count = 0;
    for (auto it = texture.layers.rbegin(); it != texture.layers.rend() && layer_count + 1 < kMaxLayers; ++it)
        layers[layer_count++] = &*it;
    layers[layer_count++] = &texture;

    const double bailout = state.adc_bailout;
    // POV-Ray compat: the interior is the leaf's (a CSG child's own, or the one it shares with its parent).
    const scene::Object& owner = *s.object;
    const scene::Interior& interior = owner.interior;
    Vec3 colour;
    Vec3 filter{1.0, 1.0, 1.0};  // what the layers so far let through
    double trans = 1.0;
    Vec3 top_normal = s.raw_normal;
    // Radiosity: indirect light reaches a surface only below the recursion limit.
    const bool gi_needed = m_indirect && state.gi_depth < m_scene.global.radiosity->recursion_limit;
    bool gi_done = false;
    Vec3 indirect_light;
    // Photons are gathered once, at the first layer lit by them, about its normal (POV-Ray's PhotonGatherer).
    const bool photons_here = m_photons && s.object->photons.collect;
    photons::Gathered gathered;
    bool gathered_done = false;
    std::array<LayerReflection, kMaxLayers> reflections;  // filled before use
    std::size_t reflection_count = 0;
    for (std::size_t li = 0; li < layer_count; ++li) {
        const scene::Texture* layer = layers[li];
        if (trans <= bailout) break;
        Vec3 n = s.raw_normal;
        if (m_quality.normals && layer->normal.perturbs()) {
            for (const scene::Pattern* w : warps) n = texture::warp_normal(*w, n);
            n = texture::perturb_normal(layer->normal, n, layer->normal.uv_mapping ? s.p_uv : s.p_texture,
                                        m_noise_generator, s.surface);
            // POV-Ray compat: the layers' pigments and the layers after see this normal (its PNormal).
            s.surface->normal = n;
            for (auto it = warps.rbegin(); it != warps.rend(); ++it) n = texture::unwarp_normal(**it, n);
        }
        if (reflection_count == 0) top_normal = n;
        const Color pc = texture::evaluate_pigment(layer->pigment, layer->pigment.uv_mapping ? s.p_uv : s.p_texture,
                                                   m_noise_generator, s.surface);
        const Vec3 pigment = pc.rgb();
        const scene::Finish& f = layer->finish;
        if (!m_quality.lighting) {
            // POV-Ray compat (+Q0, +Q1, Q_FULL_AMBIENT): the layer's pigment replaces the colour, unlit; layers
            // below are reached as the layers' transparency allows.
            colour = pigment;
            filter = filter * (pigment * pc.filter + Vec3{pc.transmit, pc.transmit, pc.transmit});
            trans = std::min(1.0, std::fabs(texture::grey(filter)));
            continue;
        }

        LayerReflection r;
        r.weight = state.weight * trans;
        r.normal = n;
        r.exponent = f.reflection_exponent;
        const double cos_i = -dot(s.direction, n);
        double ior = 1.0;
        if (f.reflection_fresnel) {
            // POV-Ray's ComputeRelativeIOR from the interiors the ray is in.
            const InteriorStack& in = state.interiors;
            if (in.size == 0) ior = interior.ior;
            else if (in.contains(owner))
                ior = in.size == 1 ? 1.0 / interior.ior : in.top().interior.ior / interior.ior;
            else ior = interior.ior / in.top().interior.ior;
        }
        r.reflectivity = reflectivity(f, cos_i, ior, r.weight);
        // Metallic reflection is tinted by the pigment away from grazing angles.
        if (f.reflection_metallic != 0.0)
            r.reflectivity = r.reflectivity * metallic_tint(pigment, f.reflection_metallic, cos_i);

        // POV-Ray 3.7: the layer's own light is scaled by its opacity, 1 − filter − transmit. POV-Ray compat: in
        // scenes of version 3.6 and older it is 1 − (filter · max(r, g, b) + transmit), the formula POV-Ray keeps
        // for legacy scenes (ComputeLightedTexture).
        const double opacity = m_scene.version < 3.7 ? 1.0 - (pc.filter * max3(pigment) + pc.transmit)
                                                     : 1.0 - pc.filter - pc.transmit;
        Vec3 own = pigment * f.emission.rgb() * opacity;
        if (m_ambient_is_light) own += pigment * f.ambient.rgb() * m_scene.global.ambient_light.rgb() * opacity;
        if (gi_needed && f.diffuse != 0.0) {
            // POV-Ray compat (ComputeLightedTexture): indirect light is computed once, at the first layer whose
            // diffuse part could pass the bailout, and then lights every layer's diffuse (brilliance aside).
            if (!gi_done) {
                const double most = texture::grey(filter * pigment) * opacity * f.diffuse;
                if (most > state.adc_bailout) {
                    indirect_light = indirect(s, n, state.weight * most, state, ctx);
                    gi_done = true;
                }
            }
            own += pigment * indirect_light * (opacity * f.diffuse);
        }
        // POV-Ray compat: pretrace camera rays only fill the cache, so their own direct light is skipped.
        const bool pretrace_eye = !ctx.colour_kept && state.gi_depth == 0;
        const bool lit = f.diffuse != 0.0 || f.specular != 0.0 || f.phong != 0.0;
        ctx.lit_ignores_photons = !s.object->photons.collect;
        if (lit && !pretrace_eye) own += direct_light(f, pigment, opacity, s, n, ctx);
        if (photons_here && lit && !pretrace_eye) {
            if (!gathered_done) m_photons->gather_adaptive(s.hit->position, n, gathered);
            gathered_done = true;
            own += photon_light(f, pigment, opacity, s, n, gathered);
        }
        colour += own * filter;

        filter = filter * (pigment * pc.filter + Vec3{pc.transmit, pc.transmit, pc.transmit});
        if (f.conserve_energy) {
            const Vec3& rf = r.reflectivity;
            filter = filter * Vec3{std::min(1.0, 1.0 - rf.x), std::min(1.0, 1.0 - rf.y), std::min(1.0, 1.0 - rf.z)};
        }
        trans = std::min(1.0, std::fabs(texture::grey(filter)));
        reflections[reflection_count++] = r;
    }

    // Light from behind the surface: straight through (ior 1) or refracted by the interior.
    bool total_internal = false;
    double transmit = 0.0;  // Output_Alpha: how much of the transparent background shows through the surface
    if (trans > bailout && m_quality.refraction) {
        const double w = std::max(std::fabs(filter.x), std::max(std::fabs(filter.y), std::fabs(filter.z)));
        const Vec3 through = refract(s, top_normal, state.weight * w, texture.finish, state, total_internal, ctx);
        // POV-Ray's interior fade over the distance travelled inside, and its 3.1 `refraction` amount.
        Vec3 fade{interior.refraction, interior.refraction, interior.refraction};
        if (state.interiors.contains(owner) && std::fabs(interior.fade_distance) > kPovEpsilon)
            fade = fade * media::interior_fade(interior, s.depth);
        colour += total_internal ? fade * through : fade * through * filter;
        // POV-Ray compat (ComputeLightedTexture): the background's transmit seen through the surface, scaled by the
        // grey of the interior fade and by the layers' transparency; none after total internal reflection.
        if (state.alpha_background && !total_internal) transmit = texture::grey(fade) * ctx.transmit * trans;
    }

    for (std::size_t i = 0; i < (m_quality.reflection ? reflection_count : 0); ++i) {
        const LayerReflection& r = reflections[i];
        const scene::Finish& finish = layers[i]->finish;
        // POV-Ray compat: after total internal reflection the top normal's reflection is already counted.
        if (total_internal && length(r.normal - top_normal) <= kPovEpsilon) continue;
        if (r.reflectivity == Vec3{}) continue;
        Vec3 reflected = reflect(s, r.normal, r.weight, finish, state, ctx);
        if (r.exponent != 1.0) {
            // POV-Ray's reflection `exponent e` raises the reflected colour to 1/e.
            const double e = 1.0 / r.exponent;
            reflected = {std::pow(reflected.x, e), std::pow(reflected.y, e), std::pow(reflected.z, e)};
        }
        colour += r.reflectivity * reflected;
    }
    ctx.transmit = transmit;
    return colour;
}

Vec3 Integrator::reflect(const Surface& s, const Vec3& n, double weight, const scene::Finish& finish,
                         const RayState& state, TraceContext& ctx) const {
    // Mirror direction about the (possibly bumped) normal; POV-Ray bends it back above the true surface.
    Vec3 d = s.direction - 2.0 * dot(s.direction, n) * n;
    const double k = dot(d, s.raw_normal);
    if (k < 0.0) {
        if (dot(d, n) < 0.0) d = s.direction - 2.0 * dot(s.direction, s.raw_normal) * s.raw_normal;
        else d += -2.0 * k * s.raw_normal;
    }
    RayState next = state;
    next.weight = weight;
    next.alpha_background = false;  // POV-Ray compat (ComputeReflection): a mirror shows the background opaque
    const Vec3& p = s.hit->position;
    const geometry::Ray ray{p, normalize(d), m_geometry.self_intersection_offset(p), 1e30,
                            geometry::RayKind::Reflection};
    ++ctx.rays.secondary;
    const Vec3 colour = trace(ray, next, false, ctx);
    if (finish.irid <= 0.0) return colour;
    return colour * iridescence(finish, ray.direction, s.direction, n, p);
}

Vec3 Integrator::refract(const Surface& s, const Vec3& n, double weight, const scene::Finish& finish,
                         const RayState& state, bool& total_internal, TraceContext& ctx) const {
    total_internal = false;
    RayState next = state;
    next.weight = weight;
    // POV-Ray's interior bookkeeping: entering pushes the object, leaving the innermost pops it; the relative
    // index (and dispersion) is outside over inside (the atmosphere's are 1).
    const scene::Object& owner = *s.object;
    const scene::Interior& inner = owner.interior;
    InteriorStack& in = next.interiors;
    double ior = 1.0, dispersion = 1.0;
    int bands = inner.dispersion_samples;
    if (in.size == 0) {
        in.push(owner);
        ior = 1.0 / inner.ior;
        dispersion = 1.0 / inner.dispersion;
    } else if (scene::same_interior(in.top(), owner)) {
        in.remove(owner);
        if (in.size == 0) {
            ior = inner.ior;
            dispersion = inner.dispersion;
        } else {
            const scene::Interior& outer = in.top().interior;
            ior = inner.ior / outer.ior;
            dispersion = inner.dispersion / outer.dispersion;
            bands = std::max(bands, outer.dispersion_samples);
        }
    } else if (!in.remove(owner)) {
        const scene::Interior& outer = in.top().interior;
        ior = outer.ior / inner.ior;
        dispersion = outer.dispersion / inner.dispersion;
        in.push(owner);
    }
    const Vec3& p = s.hit->position;
    if (std::fabs(ior - 1.0) < kPovEpsilon && std::fabs(dispersion - 1.0) < kPovEpsilon) {
        // POV-Ray compat: light passing straight through continues the same ray (no new trace level).
        ++ctx.rays.secondary;
        const geometry::Ray ray{p, s.direction, m_geometry.self_intersection_offset(p), 1e30,
                                geometry::RayKind::Camera};
        return trace(ray, next, true, ctx);
    }
    if (std::fabs(dispersion - 1.0) < kPovEpsilon)
        return refract_ray(s, n, ior, weight, finish, state, next, total_internal, ctx);
    // A ray already split keeps its band; white light splits here.
    if (state.band.monochromatic())
        return refract_ray(s, n, photons::dispersion_ior(ior, dispersion, state.band), weight, finish, state, next,
                           total_internal, ctx);
    return refract_dispersive(s, n, ior, dispersion, bands, weight, finish, state, next, ctx);
}

Vec3 Integrator::refract_ray(const Surface& s, const Vec3& n, double ior, double weight, const scene::Finish& finish,
                             const RayState& state, RayState& next, bool& total_internal, TraceContext& ctx) const {
    ++ctx.rays.secondary;
    // Snell's law in vector form (Heckbert 1989): t = η·d + (η cos i − sqrt(1 + η²(cos² i − 1)))·n.
    double cos_n = dot(s.direction, n);
    Vec3 local = -n;
    if (cos_n <= 0.0) {
        local = n;
        cos_n = -cos_n;
    }
    const double t = 1.0 + ior * ior * (cos_n * cos_n - 1.0);
    if (t < 0.0) {
        total_internal = true;
        return reflect(s, n, weight, finish, state, ctx);
    }
    const Vec3& p = s.hit->position;
    const Vec3 d = s.direction * ior + local * (ior * cos_n - std::sqrt(t));
    const geometry::Ray ray{p, normalize(d), m_geometry.self_intersection_offset(p), 1e30, geometry::RayKind::Camera};
    return trace(ray, next, false, ctx);
}

Vec3 Integrator::refract_dispersive(const Surface& s, const Vec3& n, double ior, double dispersion, int bands,
                                    double weight, const scene::Finish& finish, const RayState& state,
                                    RayState& next, TraceContext& ctx) const {
    // POV-Ray's ComputeRefraction with dispersion: one ray per band, its colour weighted by the band's hue, the
    // sum divided by the band count (the hues of all bands average to white).
    Vec3 sum;
    for (int i = 0; i < bands; ++i) {
        next.band = photons::SpectralBand{i, bands};
        bool reflected = false;  // POV-Ray compat: a band's total internal reflection is not reported upward
        const Vec3 c = refract_ray(s, n, photons::dispersion_ior(ior, dispersion, next.band), weight, finish, state,
                                   next, reflected, ctx);
        sum += c * photons::band_hue(next.band);
    }
    // POV-Ray compat: the sum of the bands is a colour without a transmit channel, so no background shows through.
    ctx.transmit = 0.0;
    return sum / static_cast<double>(bands);
}

}  // namespace wardray::lighting
