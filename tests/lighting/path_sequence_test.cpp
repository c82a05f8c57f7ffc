// The reference's path sequence: a pixel's paths stratify each bounce, every path is uniform over seeds, and the
// reference estimator built on it keeps the expectation of independent paths (an analytic two-bounce integral).
#include "lighting/path_sequence.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <cstdint>
#include <set>
#include <vector>

#include "lighting/indirect_light.h"
#include "seed_estimates.h"

namespace wardray::lighting {
namespace {

TEST(PathSequence, FirstPowerOfTwoPointsPutOneInEachIntervalOfEveryDimension) {
    // Each Sobol dimension's first 2^m points are a (0, m, 1)-net and a nested scrambling keeps that: one point in
    // each interval [k/2^m, (k+1)/2^m), whatever the seed.
    for (const std::uint64_t seed : {1ull, 77ull, 0xDEADBEEFull}) {
        for (int dim = 0; dim < kPathDimensions; ++dim) {
            for (const int m : {4, 8, 10}) {
                const std::uint32_t n = 1u << m;
                std::set<std::uint32_t> cells;
                for (std::uint32_t i = 0; i < n; ++i) {
                    const double u = path_sample(i, dim, seed);
                    ASSERT_GE(u, 0.0);
                    ASSERT_LT(u, 1.0);
                    cells.insert(static_cast<std::uint32_t>(u * n));
                }
                EXPECT_EQ(cells.size(), n) << "dimension " << dim << ", 2^" << m << " points, seed " << seed;
            }
        }
    }
}

TEST(PathSequence, FirstBounceIsAZeroTwoNet) {
    // Dimensions 0 and 1 (a path's first bounce) form a (0, m, 2)-net: one point in every elementary interval of
    // area 2^-m, for all shapes 2^-a by 2^-(m-a).
    const int m = 8;
    const std::uint32_t n = 1u << m;
    for (const std::uint64_t seed : {3ull, 12345ull}) {
        for (int a = 0; a <= m; ++a) {
            std::set<std::uint32_t> cells;
            for (std::uint32_t i = 0; i < n; ++i) {
                const auto x = static_cast<std::uint32_t>(path_sample(i, 0, seed) * (1u << a));
                const auto y = static_cast<std::uint32_t>(path_sample(i, 1, seed) * (1u << (m - a)));
                cells.insert((x << (m - a)) | y);
            }
            EXPECT_EQ(cells.size(), n) << "intervals 2^-" << a << " x 2^-" << (m - a) << ", seed " << seed;
        }
    }
}

TEST(PathSequence, EveryPointIsUniformOverSeeds) {
    // Over seeds, a fixed point (index and pair of dimensions) falls in each of 8 x 8 cells with chance 1/64: the
    // counts of 32768 seeds stay within 5 standard deviations of 512.
    const int seeds = 1 << 15;
    for (const std::uint32_t index : {0u, 1u, 37u, 255u}) {
        for (int dim = 0; dim + 1 < kPathDimensions; dim += 2) {
            std::vector<int> count(64, 0);
            double mean = 0.0;
            for (int s = 0; s < seeds; ++s) {
                const double u = path_sample(index, dim, static_cast<std::uint64_t>(s) * 0x9E3779B97F4A7C15ull + 1);
                const double v = path_sample(index, dim + 1, static_cast<std::uint64_t>(s) * 0x9E3779B97F4A7C15ull + 1);
                ++count[static_cast<int>(u * 8) * 8 + static_cast<int>(v * 8)];
                mean += u / seeds;
            }
            const double expected = seeds / 64.0;
            const double sigma = std::sqrt(expected * (1.0 - 1.0 / 64));
            for (int c = 0; c < 64; ++c)
                EXPECT_NEAR(count[c], expected, 5 * sigma) << "index " << index << ", dims " << dim << ", cell " << c;
            EXPECT_NEAR(mean, 0.5, 5 * std::sqrt(1.0 / 12 / seeds)) << "index " << index << ", dimension " << dim;
        }
    }
}

/// A tracer standing in for a scene with two bounces: a first-bounce ray along `dir` sees f(dir) plus the
/// irradiance of a point whose incoming radiance g depends on both that ray and its own, so the estimate's
/// expectation is known and depends on the bounces' joint distribution. The normal is +z, whose frame
/// (cache::orthonormal_basis) is the identity, so directions read as local ones.
class TwoBounceTracer final : public GatherTracer {
public:
    const IndirectLight* reference = nullptr;
    bool first_bounce_seen = true;  ///< false: only the second bounce's light counts

    Vec3 gather_radiance(const Vec3&, const Vec3& dir, const RayState& state, std::uint64_t path_seed,
                         TraceContext& ctx, double& distance) const override {
        distance = 1.0;
        if (state.gi_depth == 1) {
            // Second bounce: which half of the hemisphere the first ray went to decides what this one sees.
            const bool seen = m_first_y > 0.0 ? dir.x > 0.0 : dir.z > 0.5;
            return {seen ? 1.0 : 0.0, 0.0, 0.0};
        }
        // As Integrator::gather_radiance: one bounce deeper, the path's own seed, its place in the pixel's paths.
        RayState next = state;
        next.gi_depth = state.gi_depth + 1;
        next.path_seed = path_seed;
        m_first_y = dir.y;
        const double f = first_bounce_seen && dir.z > 0.8 ? 1.0 : 0.0;
        return Vec3{f, 0.0, 0.0} + reference->irradiance({0, 0, 0}, {0, 0, 1}, 1.0, next, ctx);
    }

private:
    mutable double m_first_y = 0.0;
};

/// The reference's estimate at the origin, normal +z, with `paths` paths and render seed `seed`, and its variance.
Estimates estimate(int paths, int seeds, bool first_bounce_seen) {
    return over_seeds(seeds, [&](std::uint64_t seed) {
        TwoBounceTracer tracer;
        tracer.first_bounce_seen = first_bounce_seen;
        const auto reference = make_reference_irradiance(tracer, paths, seed);
        tracer.reference = reference.get();
        TraceContext ctx;
        return reference->irradiance({0, 0, 0}, {0, 0, 1}, 1.0, RayState{}, ctx).x;
    });
}

TEST(ReferencePaths, KeepTheExpectationOfIndependentPaths) {
    // Cosine-distributed (sin²θ uniform): P(cos θ > 0.8) = 1 - 0.8² = 0.36 at the first bounce; the second sees
    // P(x > 0) = 1/2 after a first ray with y > 0 (chance 1/2) and P(cos θ > 1/2) = 3/4 otherwise: 0.985 in all.
    // Four paths a pixel: a sequence that were not uniform over seeds would be off by about 0.1 here.
    const int seeds = 20000;
    const Estimates e = estimate(4, seeds, true);
    EXPECT_NEAR(e.mean, 0.985, 5.0 * std::sqrt(e.variance / seeds));
    EXPECT_LT(5.0 * std::sqrt(e.variance / seeds), 0.02) << "the test's tolerance has grown too loose";
}

TEST(ReferencePaths, StratifyTheSecondBounceAcrossAPixelsPaths) {
    // The second bounce's light alone (expectation 0.625): independent paths would give a variance near
    // p(1 - p)/N = 0.234/64 over 64 paths; the pixel's paths sharing one scrambled sequence give far less.
    const int paths = 64, seeds = 2000;
    const Estimates e = estimate(paths, seeds, false);
    // (Its half-spaces are unions of dyadic intervals of the sequence, so 64 stratified paths may hit 0.625 exactly.)
    EXPECT_NEAR(e.mean, 0.625, std::max(1e-12, 5.0 * std::sqrt(e.variance / seeds)));
    const double independent = 0.625 * 0.375 / paths;
    EXPECT_LT(e.variance, 0.5 * independent) << "variance " << e.variance << " against " << independent;
    std::cout << "[ reference] second bounce, 64 paths: variance " << e.variance << ", independent paths "
              << independent << "\n";
}

}  // namespace
}  // namespace wardray::lighting
