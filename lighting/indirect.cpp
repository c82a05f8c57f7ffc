// Indirect light: POV-Ray 3.7's radiosity (ComputeAmbient, GatherLight) through wardray's irradiance cache, or
// brute force, each behind IndirectLight.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "cache/gather.h"
#include "cache/hemisphere_sampler.h"
#include "cache/irradiance_cache.h"
#include "cache/irradiance_record.h"
#include "core/constants.h"
#include "core/render_seed.h"
#include "geometry/scene_geometry.h"
#include "lighting/indirect_light.h"
#include "lighting/integrator.h"
#include "lighting/path_guide.h"
#include "lighting/path_sequence.h"
#include "texture/pigment.h"

namespace wardray::lighting {

namespace {

/// POV-Ray compat (GetRecursionSettings): rays per gather halve with each bounce, at least 5.
int rays_at_depth(const scene::RadiositySettings& rs, int depth) {
    return std::max(5, static_cast<int>(rs.count * std::ldexp(1.0, -depth)));
}

/// base^exponent as std::pow gives it, remembered per thread: every gather ray of a bounce asks the same.
double gather_weight(double base, int exponent) {
    thread_local double last_base = 0.0, last_value = 1.0;
    thread_local int last_exponent = 0;
    if (base != last_base || exponent != last_exponent) {
        last_base = base;
        last_exponent = exponent;
        last_value = std::pow(base, exponent);
    }
    return last_value;
}

/// Cache mode: interpolate from the tile's cache view, or gather a new record when too few are valid.
class CachedIrradiance final : public IndirectLight {
public:
    CachedIrradiance(const scene::Scene& scene, const GatherTracer& tracer, bool gradients, double footprint,
                     bool gradient_cap, bool hessian_spacing, bool adaptive_gather, bool geometry_floor,
                     int lookup_sampling)
        : m_scene(scene), m_tracer(tracer), m_gradients(gradients), m_gradient_cap(gradient_cap),
          m_hessian_spacing(hessian_spacing), m_adaptive_gather(adaptive_gather),
          m_geometry_floor(geometry_floor), m_lookup_sampling(std::max(lookup_sampling, 1)), m_footprint(footprint) {}

    Vec3 irradiance(const Vec3& p, const Vec3& n, double weight, const RayState& state,
                    TraceContext& ctx) const override {
        const scene::RadiositySettings& rs = *m_scene.global.radiosity;
        const int depth = state.gi_depth;
        // Lazy evaluation (Ward, Rubinstein & Clear 1988): reuse the valid records when they cover the point.
        cache::LookupParams params = cache::lookup_params(rs, depth, ctx.final_pass, weight);
        params.gradients = m_gradients;
        // --gi-lookup-sampling K: at a gather ray's hit where the frozen records give a coarse estimate a
        // (IrradianceCache::ambient()), only the rays its gather marked (one in K, by their seed's low bit) look up,
        // and return a + K (E − a); the others return a. A control variate: over a gather's rays the mean is what
        // every ray looking up would give, with a K-th of the lookups and, where a is close to E, little more noise.
        Vec3 ambient;
        bool sampled = false;
        if (m_lookup_sampling > 1 && depth >= 1 && ctx.cache && ctx.cache->ambient(p, n, depth, ambient)) {
            if ((state.path_seed & 1) == 0) return ambient;
            sampled = true;
        }
        const auto corrected = [&](const Vec3& e) {
            return sampled ? ambient + (e - ambient) * static_cast<double>(m_lookup_sampling) : e;
        };
        cache::Interpolation found;
        if (ctx.cache) {
            found = ctx.cache->lookup(p, n, depth, params);
            if (found.sufficient) return corrected(found.irradiance);
        }
        // Otherwise gather a new record, its rays seeded by its position so no thread changes it.
        ++ctx.rays.gathers;
        // With --gi-adaptive, a coarser stratified grid and the rest of the same budget where its cells differ.
        const cache::GatherPlan plan = cache::gather_plan(rays_at_depth(rs, depth), m_adaptive_gather);
        cache::SplitMix64 seeds(ctx.gather_seed++);
        // --gi-lookup-sampling K: every K-th ray of the gather, from a phase its seed picks, is marked to look up at
        // its hit; along the strata's order, so that the marked rays spread over the hemisphere.
        const auto k = static_cast<std::uint64_t>(m_lookup_sampling);
        const std::uint64_t phase = k > 1 ? seeds.next() % k : 0;
        std::uint64_t ray = 0;
        const cache::GatherResult gathered = cache::gather_seeded(
            p, n, plan.strata,
            [&](const Vec3& dir) {
                cache::RadianceSample sample;
                // Each ray's own seed (after the gather's), for the lights its path picks.
                std::uint64_t seed = seeds.next();
                if (k > 1) seed = (seed & ~std::uint64_t{1}) | (ray++ % k == phase ? 1 : 0);
                sample.radiance = m_tracer.gather_radiance(p, dir, state, seed, ctx, sample.distance);
                return sample;
            },
            seeds.next() ^ static_cast<std::uint64_t>(depth), m_gradients && m_hessian_spacing, plan.extra);
        if (ctx.cache) {
            const double camera_distance = length(p - m_scene.camera.location);
            const cache::RadiusLimits limits =
                cache::radius_limits(rs, depth, camera_distance, m_footprint * camera_distance);
            cache::RecordOptions options;
            options.gradients = m_gradients;
            options.gradient_radius_cap = m_gradients && m_gradient_cap;
            options.spacing = m_hessian_spacing ? cache::RadiusSpacing::Hessian : cache::RadiusSpacing::Harmonic;
            // The bound lookups use on the final pass at this depth (interpolation.cpp's lookup_params).
            options.error_bound = std::ldexp(rs.error_bound, depth);
            options.geometry_floor = m_gradients && m_geometry_floor;
            ctx.cache->add(cache::make_record(p, n, gathered, depth, limits, options));
        }
        // POV-Ray compat (ComputeAmbient): records that were valid but too few blend in by their coverage.
        if (found.records > 0)
            return corrected((found.irradiance * found.coverage + gathered.irradiance) / (found.coverage + 1.0));
        return corrected(gathered.irradiance);
    }

private:
    const scene::Scene& m_scene;
    const GatherTracer& m_tracer;
    bool m_gradients = true;
    bool m_gradient_cap = true;
    bool m_hessian_spacing = true;
    bool m_adaptive_gather = false;
    bool m_geometry_floor = false;
    int m_lookup_sampling = 1;
    double m_footprint = 0.0;
};

/// Reference mode: a Monte Carlo estimate, many rays at the first bounce and one per path deeper.
class ReferenceIrradiance final : public IndirectLight {
public:
    ReferenceIrradiance(const GatherTracer& tracer, int rays, std::uint64_t seed, const PathGuide* guide)
        : m_tracer(tracer), m_rays(std::max(1, rays)), m_seed(seed), m_guide(guide) {}

    Vec3 irradiance(const Vec3& p, const Vec3& n, double, const RayState& state, TraceContext& ctx) const override {
        // Brute force: the cosine-weighted mean of radiance over the hemisphere (POV-Ray's normalisation, no π);
        // the first bounce takes all of --gi-rays, each deeper bounce continues its path with one ray, so a pixel
        // averages --gi-rays independent paths. Each path is one point of a scrambled Sobol sequence, two of its
        // dimensions per direction and one per light picked (path_sequence.h), so the pixel's paths stratify
        // every bounce and the bounces jointly.
        const std::uint64_t salt = reseed(state.path_seed * 0x9E3779B97F4A7C15ULL + state.gi_depth, m_seed);
        cache::SplitMix64 rng(cache::seed_from(p, n, salt));
        Frame frame;
        frame.n = n;
        cache::orthonormal_basis(n, frame.t, frame.b);
        // Where the guide (learned before the render) says this point's light comes from; none: cosine alone.
        frame.guide = m_guide && !m_guide->empty() && !ctx.guide_samples ? m_guide->find(p, n) : nullptr;
        ++ctx.rays.gathers;
        if (state.gi_depth > 0) {
            // A path below its first bounce: its own point's next two dimensions, or a uniform pair past them.
            const int dim = path_direction_dimension(state.gi_depth);
            if (state.path_count > 0 && dim + 1 < kPathDimensions) {
                const auto index = static_cast<std::uint32_t>(state.path_index);
                return one_path(p, frame, path_sample(index, dim, state.path_group),
                                path_sample(index, dim + 1, state.path_group), state, rng.next(), ctx);
            }
            const double u = rng.uniform();
            const double v = rng.uniform();
            return one_path(p, frame, u, v, state, rng.next(), ctx);
        }
        // The pixel's paths: one Sobol sequence, scrambled by this hit's stream.
        RayState path = state;
        path.path_group = rng.next();
        path.path_count = ctx.pilot_paths > 0 ? ctx.pilot_paths : m_rays;
        Vec3 sum;
        for (int i = 0; i < path.path_count; ++i) {
            path.path_index = i;
            const auto index = static_cast<std::uint32_t>(i);
            const int dim = path_direction_dimension(0);
            sum += one_path(p, frame, path_sample(index, dim, path.path_group),
                            path_sample(index, dim + 1, path.path_group), path, rng.next(), ctx);
        }
        return sum / static_cast<double>(path.path_count);
    }

private:
    /// A shading point's frame and the guide's density there (null: cosine sampling alone).
    struct Frame {
        Vec3 n, t, b;
        const GuideDistribution* guide = nullptr;
    };

    /// One path's estimate of the irradiance from the uniforms (u, v): a cosine-distributed direction, or with a
    /// guide a one-sample mixture of the cosine density and the guide's (Veach 1997, sec. 9.2.2: the sample
    /// weighted by the cosine density over the mixture's). Its weight is at most 1/kCosineShare, and its
    /// expectation is that of cosine sampling because the mixture's cosine part covers the whole hemisphere.
    Vec3 one_path(const Vec3& p, const Frame& f, double u, double v, const RayState& state, std::uint64_t path_seed,
                  TraceContext& ctx) const {
        if (!f.guide) {
            const Vec3 d = cosine_direction(u, v);
            return trace_one(p, f.t * d.x + f.b * d.y + f.n * d.z, state, path_seed, ctx);
        }
        // The first uniform chooses the part and, rescaled, still places the direction, so strata stay strata.
        Vec3 dir;
        double guide_pdf = 0.0;
        if (u < kCosineShare) {
            const Vec3 d = cosine_direction(u / kCosineShare, v);
            dir = f.t * d.x + f.b * d.y + f.n * d.z;
        } else {
            dir = f.guide->sample((u - kCosineShare) / (1.0 - kCosineShare), v, guide_pdf);
        }
        const double cos_theta = dot(dir, f.n);
        if (!(cos_theta > 0.0)) return {};  // the guide's lobe below the surface: this path adds nothing
        if (u < kCosineShare) guide_pdf = f.guide->pdf(dir);
        const double cosine_pdf = cos_theta * std::numbers::inv_pi;
        const double pdf = kCosineShare * cosine_pdf + (1.0 - kCosineShare) * guide_pdf;
        return trace_one(p, dir, state, path_seed, ctx) * (cosine_pdf / pdf);
    }

    Vec3 trace_one(const Vec3& p, const Vec3& dir, const RayState& state, std::uint64_t path_seed,
                   TraceContext& ctx) const {
        double distance = 0.0;
        const Vec3 l = m_tracer.gather_radiance(p, dir, state, path_seed, ctx, distance);
        if (!is_finite(l)) return {};
        // The pilot pass records what each vertex received, for the guide.
        if (ctx.guide_samples)
            ctx.guide_samples->push_back({{static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z)},
                                          {static_cast<float>(dir.x), static_cast<float>(dir.y),
                                           static_cast<float>(dir.z)},
                                          static_cast<float>((l.x + l.y + l.z) / 3.0)});
        return l;
    }

    /// The mixture's share of cosine sampling (Müller et al. 2017 use one half).
    static constexpr double kCosineShare = 0.5;

    const GatherTracer& m_tracer;
    int m_rays = 256;
    std::uint64_t m_seed = 0;
    const PathGuide* m_guide = nullptr;
};

}  // namespace

std::unique_ptr<const IndirectLight> make_cached_irradiance(const scene::Scene& scene, const GatherTracer& tracer,
                                                            bool gradients, double footprint, bool gradient_cap,
                                                            bool hessian_spacing, bool adaptive_gather,
                                                            bool geometry_floor, int lookup_sampling) {
    return std::make_unique<CachedIrradiance>(scene, tracer, gradients, footprint, gradient_cap, hessian_spacing,
                                              adaptive_gather, geometry_floor, lookup_sampling);
}

std::unique_ptr<const IndirectLight> make_reference_irradiance(const GatherTracer& tracer, int rays,
                                                               std::uint64_t seed, const PathGuide* guide) {
    return std::make_unique<ReferenceIrradiance>(tracer, rays, seed, guide);
}

Vec3 Integrator::indirect(const Surface& s, const Vec3& n_layer, double weight, const RayState& state,
                          TraceContext& ctx) const {
    const scene::RadiositySettings& rs = *m_scene.global.radiosity;
    // POV-Ray compat: `normal on` gathers around the perturbed normal, otherwise around the true one.
    const Vec3 n = rs.normal ? n_layer : s.raw_normal;
    Vec3 e = m_indirect->irradiance(s.hit->position, n, weight, state, ctx);
    // POV-Ray compat (ComputeAmbient): gray_threshold mixes toward grey, then brightness scales.
    if (rs.gray_threshold != 0.0) {
        const double g = texture::grey(e);
        e = e * (1.0 - rs.gray_threshold) + Vec3{g, g, g} * rs.gray_threshold;
    }
    e = e * rs.brightness;
    if (ctx.capture_irradiance && !ctx.captured && state.gi_depth == 0) {
        ctx.irradiance = e;
        ctx.captured = true;
    }
    return e;
}

Vec3 Integrator::gather_radiance(const Vec3& p, const Vec3& dir, const RayState& state, std::uint64_t path_seed,
                                 TraceContext& ctx, double& distance) const {
    const scene::RadiositySettings& rs = *m_scene.global.radiosity;
    // POV-Ray compat (GetRecursionSettings, GatherLight): a gather ray starts afresh at trace level
    // ⌊1.5·(depth+1)⌋ with weight (brightness/2)^(depth+1), radiosity's adc_bailout, and room for one more level.
    RayState next;
    next.level = static_cast<int>(1.5 * (state.gi_depth + 1));
    next.max_level = std::max(state.max_level, next.level + 1);
    next.weight = std::max(rs.adc_bailout + kPovEpsilon, gather_weight(0.5 * rs.brightness, state.gi_depth + 1));
    next.adc_bailout = rs.adc_bailout;
    next.gi_depth = state.gi_depth + 1;
    next.gather_ray = true;
    next.path_seed = path_seed;
    next.path_group = state.path_group;
    next.path_index = state.path_index;
    next.path_count = state.path_count;
    next.interiors = state.interiors;
    const geometry::Ray ray{p, dir, m_geometry.self_intersection_offset(p), 1e30, geometry::RayKind::Gather};
    ++ctx.rays.gather;
    const Vec3 l = trace(ray, next, false, ctx, &distance);
    // POV-Ray compat (GatherLight): max_sample scales a sample down so that its largest channel is at most that.
    const double brightest = std::max(l.x, std::max(l.y, l.z));
    if (rs.max_sample > 0.0 && brightest > rs.max_sample) return l * (rs.max_sample / brightest);
    return l;
}

}  // namespace wardray::lighting
