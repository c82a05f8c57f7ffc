// IndirectLight: how the integrator gets indirect irradiance (POV-Ray's radiosity), without knowing how it is made.
#pragma once

#include <cstdint>
#include <memory>

#include "lighting/trace_context.h"
#include "scene/scene.h"

namespace wardray::lighting {

/// The integrator's side of a gather: the radiance arriving at `p` along the unit `dir`, traced as POV-Ray's
/// radiosity rays are (a new trace level and weight from `state`'s bounce depth); `distance` receives the hit
/// distance (+infinity for none).
class GatherTracer {
public:
    virtual ~GatherTracer() = default;
    /// One gather ray's radiance; `path_seed` tells independent reference paths apart.
    virtual Vec3 gather_radiance(const Vec3& p, const Vec3& dir, const RayState& state, std::uint64_t path_seed,
                                 TraceContext& ctx, double& distance) const = 0;
};

/// The indirect irradiance at a surface point, before POV-Ray's brightness and gray_threshold (the integrator
/// applies those): the cosine-weighted mean of incoming radiance, POV-Ray's normalisation (no π).
class IndirectLight {
public:
    virtual ~IndirectLight() = default;
    /// Irradiance at `p` around the unit normal `n`; `weight` is the shading ray's weight (POV-Ray lowers the
    /// cache's accuracy for rays that matter little).
    virtual Vec3 irradiance(const Vec3& p, const Vec3& n, double weight, const RayState& state,
                            TraceContext& ctx) const = 0;
};

/// Ward's irradiance cache in the tile's view `TraceContext::cache` (Ward, Rubinstein & Clear 1988): interpolate
/// where valid records cover the point, else gather a new record. `footprint`, `gradient_cap`,
/// `hessian_spacing`, `adaptive_gather`, `geometry_floor` and `lookup_sampling` as in IntegratorOptions.
std::unique_ptr<const IndirectLight> make_cached_irradiance(const scene::Scene& scene, const GatherTracer& tracer,
                                                            bool gradients, double footprint, bool gradient_cap,
                                                            bool hessian_spacing = true, bool adaptive_gather = false,
                                                            bool geometry_floor = true, int lookup_sampling = 1);

/// Brute force (the ground truth): `rays` paths at the first bounce, one per path deeper, drawn from the render
/// seed `seed` (--seed); with a `guide` that is not empty, every bounce mixes cosine sampling with the guide's
/// (path_guide.h), which changes the noise, not the expectation. The guide must outlive the estimator and may be
/// filled after it is made, before the render.
std::unique_ptr<const IndirectLight> make_reference_irradiance(const GatherTracer& tracer, int rays,
                                                               std::uint64_t seed, const PathGuide* guide = nullptr);

}  // namespace wardray::lighting
