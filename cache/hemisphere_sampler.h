// HemisphereSampler: stratified cosine-weighted directions for gathering irradiance, seeded by position.
#pragma once

#include <cstdint>
#include <vector>

#include "core/vec3.h"

namespace wardray::cache {

/// One gather direction in the local frame (z along the normal) and the cell it stratifies.
struct HemisphereSample {
    Vec3 direction;  ///< unit vector, z >= 0
    int polar = 0;    ///< j, 0..M-1 (θ grows with j)
    int azimuth = 0;  ///< k, 0..N-1
};

/// The M x N cell layout for a ray budget: N ≈ πM and M·N ≈ count (Ward & Heckbert 1992, section 3).
struct Strata {
    int polar = 1;
    int azimuthal = 1;
};
Strata strata_for_count(int count);

/// A deterministic random stream (SplitMix64): the same seed gives the same numbers on every thread and run.
class SplitMix64 {
public:
    explicit SplitMix64(std::uint64_t seed) : m_state(seed) {}
    std::uint64_t next();
    /// Uniform in [0, 1).
    double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }

private:
    std::uint64_t m_state;
};

/// A seed from a position and normal, so a record's samples never depend on which thread made it.
std::uint64_t seed_from(const Vec3& position, const Vec3& normal, std::uint64_t salt = 0);

/// One direction per cell, θ_jk = asin(sqrt((j + (a_k + ξ)/N)/M)), φ_jk = 2π(k + (b_j + ξ')/M)/N with a and b
/// shuffles of 0..N-1 and 0..M-1 (correlated multi-jittered): cosine-distributed, stratified by the cells and
/// also by sin²θ alone and by φ alone into M·N slices each.
std::vector<HemisphereSample> stratified_cosine_samples(const Strata& strata, SplitMix64& rng);

/// One cosine-distributed direction in cell (j, k) of `strata`, uniform within the cell (the adaptive extras).
HemisphereSample sample_in_cell(const Strata& strata, int polar, int azimuth, SplitMix64& rng);

/// How a gather of `count` rays spends them: one per cell of `strata`, then `extra` into the cells whose
/// neighbours differ most (adaptive_extra_rays). Without adaptive sampling extra is 0.
struct GatherPlan {
    Strata strata;
    int extra = 0;
};

/// The share of an adaptive gather's rays that its stratified base pass takes (the rest go where strata differ):
/// 0.9 had less error than 0.75 and 0.6 at the c150 and c300 ladder points of box, radiosity2, stackerday and
/// cornell (docs/reports/radiosity.md, "Adaptive hemisphere sampling"): a coarser base grid loses more in smooth
/// light than the extras gain at edges.
inline constexpr double kAdaptiveBaseShare = 0.9;

/// Gathers of fewer rays stay stratified when adaptive: their extras would be a handful of rays, and what changed
/// was mostly the coarser base grid (cornell's c20 and c40 ladder points, gathers of 5 to 40 rays, had 6-16 % more
/// error with it).
inline constexpr int kAdaptiveMinRays = 100;

/// The plan for a budget of `count` rays: strata_for_count(count) alone, or (adaptive, from kAdaptiveMinRays) a base
/// grid of about kAdaptiveBaseShare of them and the rest as extras, so that both spend the same number of rays.
GatherPlan gather_plan(int count, bool adaptive);

/// Adaptive hemisphere sampling (Ward's super-sampling of ambient divisions, as Radiance's -as): given each cell's
/// base luminance (row-major, polar rows of `strata.azimuthal` cells), how many of `extra` further rays each cell
/// gets. A cell's variance is estimated from the squared luminance differences to its four neighbours (azimuth
/// wraps around); each ray goes to the cell where it removes the most variance of the mean, var / (n (n + 1)) with
/// n rays already there; a small floor spreads rays evenly where no cell differs. Deterministic: ties go to the
/// lower cell index.
std::vector<int> adaptive_extra_rays(const std::vector<double>& luminance, const Strata& strata, int extra);

/// An orthonormal frame with `n` as its z axis (Duff et al. 2017's branchless construction).
void orthonormal_basis(const Vec3& n, Vec3& tangent, Vec3& bitangent);

}  // namespace wardray::cache
