// HemisphereSampler: stratified cosine-weighted hemisphere sampling and deterministic seeding.
#include "cache/hemisphere_sampler.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numbers>

namespace wardray::cache {

Strata strata_for_count(int count) {
    // M·N = count with N = πM gives M = sqrt(count/π).
    const int m = std::max(1, static_cast<int>(std::lround(std::sqrt(std::max(count, 1) / std::numbers::pi))));
    const int n = std::max(1, static_cast<int>(std::lround(static_cast<double>(std::max(count, 1)) / m)));
    return {m, n};
}

std::uint64_t SplitMix64::next() {
    std::uint64_t z = (m_state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

std::uint64_t seed_from(const Vec3& position, const Vec3& normal, std::uint64_t salt) {
    // Hash the exact bit patterns: equal inputs give equal seeds, independent of evaluation order.
    std::uint64_t h = 0x6A09E667F3BCC909ull ^ salt;
    for (const double v : {position.x, position.y, position.z, normal.x, normal.y, normal.z}) {
        SplitMix64 mix(h ^ std::bit_cast<std::uint64_t>(v));
        h = mix.next();
    }
    return h;
}

std::vector<HemisphereSample> stratified_cosine_samples(const Strata& strata, SplitMix64& rng) {
    std::vector<HemisphereSample> samples;
    samples.reserve(static_cast<std::size_t>(strata.polar) * strata.azimuthal);
    for (int j = 0; j < strata.polar; ++j) {
        for (int k = 0; k < strata.azimuthal; ++k) {
            // sin²θ uniform within the stratum makes the density proportional to cos θ.
            const double sin2 = (j + rng.uniform()) / strata.polar;
            const double phi = 2.0 * std::numbers::pi * (k + rng.uniform()) / strata.azimuthal;
            const double sin_theta = std::sqrt(sin2);
            const double cos_theta = std::sqrt(std::max(0.0, 1.0 - sin2));
            samples.push_back({{sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta}, j, k});
        }
    }
    return samples;
}

void orthonormal_basis(const Vec3& n, Vec3& tangent, Vec3& bitangent) {
    const double sign = std::copysign(1.0, n.z);
    const double a = -1.0 / (sign + n.z);
    const double b = n.x * n.y * a;
    tangent = {1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x};
    bitangent = {b, sign + n.y * n.y * a, -n.y};
}

}  // namespace wardray::cache
