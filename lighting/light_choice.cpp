// Light choice on gather paths: the lights that would each need a shadow ray are picked by their unshadowed light and
// the picked ones weighted by 1/chance, so a gather ray's hit traces one shadow ray (or a few), not one per light.
#include "lighting/light_choice.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "cache/hemisphere_sampler.h"
#include "core/render_seed.h"
#include "geometry/scene_geometry.h"
#include "lighting/integrator.h"
#include "lighting/path_sequence.h"

namespace wardray::lighting {

LightPick pick_light(std::span<const double> importance, double total, double u) {
    const double target = u * total;
    double below = 0.0;
    std::size_t last = 0;
    for (std::size_t i = 0; i < importance.size(); ++i) {
        if (!(importance[i] > 0.0)) continue;
        last = i;
        below += importance[i];
        if (target < below) return {i, importance[i] / total};
    }
    // Rounding left u·total at or past the running sum: the last light that could be picked takes it.
    return {last, importance.empty() ? 0.0 : importance[last] / total};
}

bool lights_object(const scene::Light& light, const scene::Object& object) {
    if (light.group == 0) return !object.no_global_lights;
    return std::find(object.light_groups.begin(), object.light_groups.end(), light.group) !=
           object.light_groups.end();
}

Vec3 Integrator::direct_light_picked(const scene::Finish& finish, const Vec3& pigment, double opacity,
                                     const Surface& s, const Vec3& n, TraceContext& ctx) const {
    struct Candidate {
        const scene::Light* light;
        LightSampler::Reach reach;
    };
    // Reused per thread: nothing below this call shades a surface, so it never runs twice at once on one thread.
    thread_local std::vector<Candidate> candidates;
    thread_local std::vector<double> importance;
    candidates.clear();
    importance.clear();
    const Vec3& p = s.hit->position;
    // POV-Ray compat (GetRadiosityQualityFlags): on a gather ray's path area lights are point lights at their centre
    // and no light makes a highlight.
    auto light_of = [&](const scene::Light& light, const LightSampler::Reach& reach, double scale) {
        const Vec3 arriving = m_lights.through(light, reach, p, *s.interiors, false, ctx);
        if (arriving == Vec3{}) return Vec3{};
        return finish_light(finish, pigment, opacity, s, n, reach.to_light, arriving * scale, false, light.position);
    };
    Vec3 colour;
    double total = 0.0;
    for (const scene::Light& light : m_scene.lights) {
        if (!lights_object(light, *s.object)) continue;
        const LightSampler::Reach reach = m_lights.reach(light, p, n, s.object->double_illuminate);
        if (!reach.lit) continue;
        // The unshadowed diffuse response (its brilliance aside) is each light's importance: colour × attenuation ×
        // |cos|, the cosine floored so that no light that could add anything is never picked.
        const Vec3& c = reach.colour;
        const double weight = (std::fabs(c.x) + std::fabs(c.y) + std::fabs(c.z)) *
                              std::max(std::fabs(dot(n, reach.to_light)), 1e-3);
        // A light that needs no shadow ray, or whose importance is unusable, adds its exact share.
        if (!m_lights.casts_shadows(light, reach) || !std::isfinite(weight)) {
            colour += light_of(light, reach, 1.0);
            continue;
        }
        if (!(weight > 0.0)) continue;  // black: it adds nothing
        candidates.push_back({&light, reach});
        importance.push_back(weight);
        total += weight;
    }
    const std::size_t picks = static_cast<std::size_t>(m_options.gather_light_picks);
    if (candidates.size() <= picks) {
        for (const Candidate& c : candidates) colour += light_of(*c.light, c.reach, 1.0);
        return colour;
    }
    // The picks' uniforms: one number from the path's seed and the ray, stratified over the picks, so the image
    // depends on neither thread nor order, and --seed turns it.
    // A reference path takes it from its pixel's sequence instead, so the pixel's paths stratify their picks too.
    double u = 0.0;
    const int dim = path_pick_dimension(s.path.gi_depth);
    if (s.path.count > 0 && dim < kPathDimensions) {
        u = path_sample(static_cast<std::uint32_t>(s.path.index), dim, s.path.group);
    } else {
        cache::SplitMix64 rng(cache::seed_from(s.direction, n, reseed(s.path_seed ^ 0x4C49474854ull, m_options.seed)));
        u = rng.uniform();
    }
    for (std::size_t k = 0; k < picks; ++k) {
        const LightPick pick = pick_light(importance, total, (static_cast<double>(k) + u) / static_cast<double>(picks));
        const Candidate& c = candidates[pick.index];
        colour += light_of(*c.light, c.reach, 1.0 / (static_cast<double>(picks) * pick.probability));
    }
    return colour;
}

}  // namespace wardray::lighting
