// Tests of adaptive hemisphere sampling (--gi-adaptive): the budget, unbiased estimates, extras at edges, seeds.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <vector>

#include "cache/gather.h"
#include "cache/hemisphere_sampler.h"
#include "gather_checks.h"
#include "test_scenes.h"

namespace wardray::cache {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// An adaptive gather of `count` rays with seed `seed`.
GatherResult adaptive_gather(const Vec3& n, int count, const RadianceFunction& f, std::uint64_t seed) {
    const GatherPlan plan = gather_plan(count, true);
    return gather_seeded({0, 0, 0}, n, plan.strata, f, seed, false, plan.extra);
}

TEST(GatherPlan, AdaptiveSpendsTheSameBudgetAsStratified) {
    for (int count : {5, 20, 35, 100, 200, 400, 1600}) {
        const GatherPlan off = gather_plan(count, false);
        const GatherPlan on = gather_plan(count, true);
        const int budget = off.strata.polar * off.strata.azimuthal;
        EXPECT_EQ(off.extra, 0);
        EXPECT_EQ(on.strata.polar * on.strata.azimuthal + on.extra, budget) << count;
        // The base pass takes about kAdaptiveBaseShare of the budget, the extras the rest; small gathers have none.
        if (count < kAdaptiveMinRays) EXPECT_EQ(on.extra, 0) << count;
        else EXPECT_NEAR(on.extra, (1.0 - kAdaptiveBaseShare) * budget, 0.05 * budget) << count;
        // The traced rays are the budget, counted by the radiance function and by the result.
        int calls = 0;
        const RadianceFunction f = [&calls](const Vec3& d) {
            ++calls;
            return RadianceSample{Vec3{1, 1, 1} * (d.x > 0.2 ? 1.0 : 0.1), 1.0};
        };
        const GatherResult g = gather_seeded({0, 0, 0}, {0, 0, 1}, on.strata, f, 3, true, on.extra);
        EXPECT_EQ(calls, budget) << count;
        EXPECT_EQ(g.ray_count, budget) << count;
    }
}

TEST(AdaptiveExtraRays, SpreadEvenlyWhereNoCellDiffers) {
    const Strata s{5, 16};
    const std::vector<int> rays = adaptive_extra_rays(std::vector<double>(80, 0.7), s, 100);
    int total = 0, lo = 1 << 30, hi = 0;
    for (const int r : rays) {
        total += r;
        lo = std::min(lo, r);
        hi = std::max(hi, r);
    }
    EXPECT_EQ(total, 100);
    EXPECT_LE(hi - lo, 1);
}

TEST(AdaptiveExtraRays, RoundingLevelDifferencesChangeNothing) {
    // Luminance that agrees to 1e-9 (rounding in a scaled scene) gets the same extras as exact agreement, where
    // ties go to the lower index; one real step still draws them.
    const Strata s{4, 12};
    std::vector<double> exact(48, 0.3), rounded(48, 0.3);
    for (std::size_t i = 0; i < rounded.size(); ++i) rounded[i] *= 1.0 + 1e-10 * static_cast<double>(i % 7);
    EXPECT_EQ(adaptive_extra_rays(exact, s, 20), adaptive_extra_rays(rounded, s, 20));
    exact[17] = 3.0;
    const std::vector<int> step = adaptive_extra_rays(exact, s, 20);
    // Cell 17 (row 1, azimuth 5) lies between its neighbours 16 and 18 and between 5 and 29 across θ.
    EXPECT_GT(step[16] + step[18] + step[5] + step[29], 15);
}

TEST(AdaptiveGather, FurnaceGivesItselfExactly) {
    // Constant radiance L: every cell's mean is L, whatever rays it got, so E = L and the distance stays.
    expect_furnace(adaptive_gather(normalize(Vec3{0, 1, 0.2}), 400, furnace_sample, 17));
}

TEST(AdaptiveGather, CosineLobeHasKnownMean) {
    // L = cos θ: E = (1/π) ∫ cos² θ dω = 2/3 (as the stratified gather's test).
    const Vec3 n = normalize(Vec3{0.3, -0.2, 0.9});
    const RadianceFunction lobe = [n](const Vec3& d) { return RadianceSample{Vec3{1, 1, 1} * dot(d, n), kInf}; };
    const GatherResult g = adaptive_gather(n, 1600, lobe, 5);
    EXPECT_NEAR(g.irradiance.x, 2.0 / 3.0, 2e-3);
    EXPECT_EQ(g.harmonic_mean_distance, kInf);
}

TEST(AdaptiveGather, DiskLightMeanOverSeedsIsUnbiased) {
    // A bright disk of half-angle θ0 around the normal over a dark hemisphere: E = sin² θ0. Its edge cuts one row
    // of cells. Were a cell's extras chosen from its own base ray (a cell that differs from its neighbours), the
    // dark cells of that row would be refined more often than the bright ones and the mean would drift by about
    // 0.5 % of E; adaptive_extra_rays() leaves the cell's own value out. sin² θ0 = 0.37 lies inside a row.
    const double exact = 0.37, cos0 = std::sqrt(1.0 - exact);
    const Vec3 n{0, 0, 1};
    const RadianceFunction disk = [&](const Vec3& d) {
        return RadianceSample{Vec3{1, 1, 1} * (d.z > cos0 ? 1.0 : 0.0), 1.0};
    };
    constexpr int kSeeds = 4000, kCount = 200;
    double sum = 0, sum2 = 0;
    for (int s = 0; s < kSeeds; ++s) {
        const double e = adaptive_gather(n, kCount, disk, 1000 + s).irradiance.x;
        sum += e;
        sum2 += (e - exact) * (e - exact);
    }
    const double mean = sum / kSeeds, rms = std::sqrt(sum2 / kSeeds);
    std::printf("disk: mean %.5f (exact %.5f), rms error %.5f\n", mean, exact, rms);
    // Four standard errors of the mean, plus a bias of at most 0.1 % of E.
    EXPECT_NEAR(mean, exact, 4.0 * rms / std::sqrt(kSeeds) + 0.001 * exact);
}

TEST(AdaptiveGather, ExtraRaysLandNextToASharpEdge) {
    // Bright where the world tangent t is positive: the edges lie at local azimuths φ = π/2 and 3π/2.
    const Vec3 n = normalize(Vec3{0.2, 0.5, 0.8});
    Vec3 t, b;
    orthonormal_basis(n, t, b);
    std::vector<Vec3> directions;
    const RadianceFunction half = [&](const Vec3& d) {
        directions.push_back(d);
        return RadianceSample{Vec3{1, 1, 1} * (dot(d, t) > 0.0 ? 1.0 : 0.0), 2.0};
    };
    const GatherPlan plan = gather_plan(400, true);
    const GatherResult g = gather_seeded({0, 0, 0}, n, plan.strata, half, 9, false, plan.extra);
    const std::size_t base = static_cast<std::size_t>(plan.strata.polar) * plan.strata.azimuthal;
    ASSERT_EQ(directions.size(), base + plan.extra);
    ASSERT_GT(plan.extra, 30);
    // A cell next to the edge reaches at most two cell widths of azimuth from it.
    const double reach = 2.0 * 2.0 * std::numbers::pi / plan.strata.azimuthal;
    int near_edge = 0;
    for (std::size_t i = base; i < directions.size(); ++i) {
        const double x = dot(directions[i], t), y = dot(directions[i], b);
        const double from_edge = std::asin(std::min(1.0, std::fabs(x) / std::hypot(x, y)));
        near_edge += from_edge < reach ? 1 : 0;
    }
    EXPECT_GE(near_edge, 0.9 * plan.extra) << near_edge << " of " << plan.extra;
    EXPECT_NEAR(g.irradiance.x, 0.5, 0.02);
}

TEST(AdaptiveGather, SameSeedSameResultOtherSeedOther) {
    const Vec3 n = normalize(Vec3{-0.1, 0.3, 1.0});
    const RadianceFunction f = [](const Vec3& d) {
        return RadianceSample{{d.x > 0.1 ? 2.0 : 0.2, 0.5 + d.y, 1.0}, d.z > 0.5 ? 1.0 : 4.0};
    };
    const GatherResult a = adaptive_gather(n, 300, f, 42);
    const GatherResult b = adaptive_gather(n, 300, f, 42);
    const GatherResult c = adaptive_gather(n, 300, f, 43);
    EXPECT_EQ(a.irradiance, b.irradiance);
    EXPECT_EQ(a.harmonic_mean_distance, b.harmonic_mean_distance);
    EXPECT_EQ(a.translational[0], b.translational[0]);
    EXPECT_EQ(a.rotational[2], b.rotational[2]);
    EXPECT_NE(a.irradiance, c.irradiance);
}

TEST(AdaptiveGather, GradientsStillMatchFiniteDifferences) {
    // Refined cells enter the gradient estimators as their rays' means: both gradients of an adaptive gather still
    // match central differences of a 131072-ray stratified irradiance (one seed for both sides), as in
    // gather_test.cpp, at two of its probes: near a wall, and next to the box's shadow edge.
    const test::RoomScene room;
    const GatherPlan plan = gather_plan(16384, true);
    ASSERT_GT(plan.extra, 1000);
    const Vec3 n{0, 1, 0};
    Vec3 t, b;
    orthonormal_basis(n, t, b);
    for (const Vec3& p : {Vec3{0.0, 0.0, 2.7}, Vec3{0.3, 0.0, 0.85}}) {
        const GatherResult g = gather_seeded(p, n, plan.strata, room.radiance_at(p), 77, false, plan.extra);
        const GatherResult s = gather_seeded(p, n, strata_for_count(16384), room.radiance_at(p), 77);
        const FiniteDifferenceGradients reference(room, p, n, t, b);
        for (int c = 0; c < 3; ++c) {
            const double rot = reference.rotational_error(g, c), trans = reference.translational_error(g, c);
            const double rot_s = reference.rotational_error(s, c), trans_s = reference.translational_error(s, c);
            std::printf("z %.2f ch%d  rotational err %.3f (stratified %.3f)  translational err %.3f (%.3f)\n", p.z, c,
                        rot, rot_s, trans, trans_s);
            // Within gather_test.cpp's 10 %, or, where the gradient is small enough for noise to reach that (green's
            // rotational gradient near the wall: 0.09 stratified), within half again the stratified gather's error.
            EXPECT_LT(rot, std::max(0.10, 1.5 * rot_s)) << p.z << " channel " << c;
            EXPECT_LT(trans, std::max(0.10, 1.5 * trans_s)) << p.z << " channel " << c;
        }
    }
}

}  // namespace
}  // namespace wardray::cache
