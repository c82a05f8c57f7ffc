// Gather: one hemisphere of stratified rays at a point, reduced to irradiance, mean distance and both gradients.
#pragma once

#include <array>
#include <cstdint>
#include <functional>

#include "cache/hemisphere_sampler.h"
#include "core/vec3.h"

namespace wardray::cache {

/// What one gather ray brings back: the radiance arriving along it and the distance to what it hit.
struct RadianceSample {
    Vec3 radiance;  ///< linear RGB
    double distance = 0.0;  ///< hit distance; +infinity for a miss
};

/// Traces one gather ray leaving the point along `direction_world` (unit length, in the hemisphere of the normal).
using RadianceFunction = std::function<RadianceSample(const Vec3& direction_world)>;

/// One gradient vector (world space) per colour channel: [0] red, [1] green, [2] blue.
using ChannelGradients = std::array<Vec3, 3>;

/// One symmetric 2x2 tangent-plane Hessian per colour channel, as {∂²/∂t², ∂²/∂t∂b, ∂²/∂b²} along the tangent t
/// and bitangent b that orthonormal_basis() gives for the gather's normal.
using ChannelHessians = std::array<std::array<double, 3>, 3>;

/// The reduction of one gather, in POV-Ray's normalisation: irradiance is the cosine-weighted mean of the incoming
/// radiance (no factor π), and both gradients are derivatives of that same quantity.
struct GatherResult {
    Vec3 irradiance;
    /// Harmonic mean of the hit distances (misses count as infinitely far): 0 when a ray hit at distance 0,
    /// +infinity when every ray missed (Ward, Rubinstein & Clear 1988).
    double harmonic_mean_distance = 0.0;
    double nearest_distance = 0.0;  ///< the smallest hit distance (+infinity when every ray missed)
    /// dE/dα for a rotation of the normal by α about an axis a is a·rotational[c] (Ward & Heckbert 1992).
    ChannelGradients rotational{};
    /// dE/dx for a move of the point by x along a tangent direction u is u·translational[c]
    /// (Ward & Heckbert 1992, in the occlusion-robust form of Křivánek et al. 2005).
    ChannelGradients translational{};
    /// (gather_seeded() with second_order) Second derivatives of E for a move of the point in its tangent plane,
    /// each hit taken as a small planar patch that stays in place (its orientation from the neighbouring hits;
    /// see gather.cpp). It sees no change of visibility: that is occlusion_curvature's part.
    ChannelHessians hessian{};
    /// (With second_order) Per channel, a bound on what moving occlusion edges add to |∂²E/∂x²| (units of E per length²): each wall
    /// between neighbouring cells across a depth step adds |ΔL| times its gradient weight over the nearer
    /// distance squared (Schwarzhaupt, Jensen & Jarosz 2012's occlusion-aware idea, in a conservative form).
    Vec3 occlusion_curvature;
    bool second_order = false;  ///< whether hessian and occlusion_curvature were computed
    int ray_count = 0;  ///< rays traced, extras included
};

/// Gathers at `position` with unit `normal` using one jittered ray per cell of `strata`, seeded by
/// seed_from(position, normal, salt) so that the result never depends on the thread that runs it.
GatherResult gather(const Vec3& position, const Vec3& normal, const Strata& strata, const RadianceFunction& radiance,
                    std::uint64_t salt = 0);

/// Like gather(), with an explicit seed (finite-difference tests keep one seed for neighbouring points). With
/// `second_order`, also the Hessian and the occlusion bound (GatherResult), else those stay zero: they cost about
/// as much again as the rest of the reduction. With `extra_rays` > 0 (adaptive hemisphere sampling, gather_plan()),
/// that many more rays follow the stratified ones, in the cells adaptive_extra_rays() picks, drawn from the same
/// seed; each such cell enters every estimate as the mean of its rays.
GatherResult gather_seeded(const Vec3& position, const Vec3& normal, const Strata& strata,
                           const RadianceFunction& radiance, std::uint64_t seed, bool second_order = false,
                           int extra_rays = 0);

}  // namespace wardray::cache
