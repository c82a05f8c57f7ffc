// Tests of the stratified cosine-weighted sampler: layout, distribution and determinism.
#include "cache/hemisphere_sampler.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>
#include <algorithm>
#include <cstdint>

namespace wardray::cache {
namespace {

TEST(Strata, CellsFollowPiRatioAndCount) {
    for (int count : {35, 100, 400, 1600}) {
        const Strata s = strata_for_count(count);
        EXPECT_NEAR(static_cast<double>(s.polar) * s.azimuthal, count, 0.15 * count) << count;
        EXPECT_NEAR(static_cast<double>(s.azimuthal) / s.polar, std::numbers::pi, 1.0) << count;
    }
}

TEST(StratifiedCosineSamples, OneUnitDirectionPerCellInItsStratum) {
    SplitMix64 rng(7);
    const Strata s{6, 19};
    const auto samples = stratified_cosine_samples(s, rng);
    ASSERT_EQ(samples.size(), 6u * 19u);
    for (const HemisphereSample& h : samples) {
        EXPECT_NEAR(length(h.direction), 1.0, 1e-12);
        EXPECT_GE(h.direction.z, 0.0);
        const double sin2 = 1.0 - h.direction.z * h.direction.z;
        EXPECT_GE(sin2, h.polar / 6.0 - 1e-12);
        EXPECT_LE(sin2, (h.polar + 1) / 6.0 + 1e-12);
        double phi = std::atan2(h.direction.y, h.direction.x);
        if (phi < 0) phi += 2 * std::numbers::pi;
        EXPECT_GE(phi, 2 * std::numbers::pi * h.azimuth / 19.0 - 1e-9);
        EXPECT_LE(phi, 2 * std::numbers::pi * (h.azimuth + 1) / 19.0 + 1e-9);
    }
}

TEST(StratifiedCosineSamples, SinSquaredThetaAloneAndPhiAloneAreStratifiedToo) {
    // Correlated multi-jittering: of the M·N equal slices of sin²θ in [0, 1) each holds exactly one sample, and so
    // does each of the M·N equal slices of φ; a plain jittered grid puts N samples in one sin²θ slice of every row.
    for (const std::uint64_t seed : {1u, 2u, 3u}) {
        SplitMix64 rng(seed);
        const Strata s{5, 16};
        const auto samples = stratified_cosine_samples(s, rng);
        const int slices = s.polar * s.azimuthal;
        std::vector<int> by_sin2(slices, 0), by_phi(slices, 0);
        for (const HemisphereSample& h : samples) {
            const double sin2 = 1.0 - h.direction.z * h.direction.z;
            double phi = std::atan2(h.direction.y, h.direction.x);
            if (phi < 0) phi += 2 * std::numbers::pi;
            ++by_sin2[std::min(slices - 1, static_cast<int>(sin2 * slices))];
            ++by_phi[std::min(slices - 1, static_cast<int>(phi / (2 * std::numbers::pi) * slices))];
        }
        for (int i = 0; i < slices; ++i) {
            EXPECT_EQ(by_sin2[i], 1) << "seed " << seed << ", sin²θ slice " << i;
            EXPECT_EQ(by_phi[i], 1) << "seed " << seed << ", φ slice " << i;
        }
    }
}

TEST(StratifiedCosineSamples, EveryCellsSamplesCoverTheCellOverSeeds) {
    // Each sample is uniform within its cell over the shuffles and the jitter: the mean of cell (j, k)'s sin²θ over
    // many seeds is the cell's middle, and so is its φ.
    const Strata s{4, 12};
    double sum_sin2 = 0.0, sum_phi = 0.0;
    const int seeds = 4000;
    for (int seed = 0; seed < seeds; ++seed) {
        SplitMix64 rng(static_cast<std::uint64_t>(seed) * 7919u + 5u);
        const HemisphereSample& h = stratified_cosine_samples(s, rng)[static_cast<std::size_t>(2 * 12 + 7)];
        sum_sin2 += 1.0 - h.direction.z * h.direction.z;
        double phi = std::atan2(h.direction.y, h.direction.x);
        if (phi < 0) phi += 2 * std::numbers::pi;
        sum_phi += phi;
    }
    // Standard errors 0.0011 and 0.0024: the tolerances are about five of them.
    EXPECT_NEAR(sum_sin2 / seeds, 2.5 / 4.0, 0.006);
    EXPECT_NEAR(sum_phi / seeds, 2 * std::numbers::pi * 7.5 / 12.0, 0.012);
}

TEST(StratifiedCosineSamples, EstimatesCosineMomentsOfTheHemisphere) {
    // For cosine-distributed directions E[cos θ] = 2/3 and E[cos² θ] = 1/2.
    SplitMix64 rng(11);
    const auto samples = stratified_cosine_samples(strata_for_count(1600), rng);
    double m1 = 0.0, m2 = 0.0;
    for (const HemisphereSample& h : samples) {
        m1 += h.direction.z;
        m2 += h.direction.z * h.direction.z;
    }
    EXPECT_NEAR(m1 / samples.size(), 2.0 / 3.0, 2e-3);
    EXPECT_NEAR(m2 / samples.size(), 0.5, 2e-3);
}

TEST(SeedFrom, SameInputSameSeedDifferentInputDifferentSeed) {
    const Vec3 p{1.25, -3.0, 0.5}, n{0, 1, 0};
    EXPECT_EQ(seed_from(p, n), seed_from(p, n));
    EXPECT_NE(seed_from(p, n), seed_from({1.25, -3.0, 0.5000001}, n));
    EXPECT_NE(seed_from(p, n, 1), seed_from(p, n, 2));
}

TEST(OrthonormalBasis, IsOrthonormalForAnyNormal) {
    SplitMix64 rng(3);
    for (int i = 0; i < 1000; ++i) {
        const Vec3 n = normalize(Vec3{rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5});
        Vec3 t, b;
        orthonormal_basis(n, t, b);
        EXPECT_NEAR(length(t), 1.0, 1e-12);
        EXPECT_NEAR(length(b), 1.0, 1e-12);
        EXPECT_NEAR(dot(t, n), 0.0, 1e-12);
        EXPECT_NEAR(dot(b, n), 0.0, 1e-12);
        EXPECT_NEAR(dot(t, b), 0.0, 1e-12);
    }
}

}  // namespace
}  // namespace wardray::cache
