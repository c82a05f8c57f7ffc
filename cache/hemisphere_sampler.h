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

/// One jittered direction per cell: θ_j = asin(sqrt((j + ξ)/M)), φ_k = 2π(k + ξ')/N, cosine-distributed.
std::vector<HemisphereSample> stratified_cosine_samples(const Strata& strata, SplitMix64& rng);

/// An orthonormal frame with `n` as its z axis (Duff et al. 2017's branchless construction).
void orthonormal_basis(const Vec3& n, Vec3& tangent, Vec3& bitangent);

}  // namespace wardray::cache
