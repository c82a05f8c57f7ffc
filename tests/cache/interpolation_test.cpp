// Tests of records and interpolation: radius rules, validity, exactness, gradient benefit, behind test, signs.
#include "cache/interpolation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "cache/hemisphere_sampler.h"
#include "cache/irradiance_record.h"
#include "test_scenes.h"

namespace wardray::cache {
namespace {

IrradianceRecord flat_record(const Vec3& p, const Vec3& e, double radius) {
    IrradianceRecord r;
    r.position = p;
    r.normal = {0, 1, 0};
    r.irradiance = e;
    r.radius = radius;
    return r;
}

LookupParams params(double error_bound = 1.8) {
    LookupParams lp;
    lp.error_bound = error_bound;
    return lp;
}

TEST(LookupParams, FollowPovRaySettings) {
    const scene::RadiositySettings s;  // POV-Ray's defaults
    const LookupParams final0 = lookup_params(s, 0, true);
    EXPECT_DOUBLE_EQ(final0.error_bound, 1.8);
    EXPECT_EQ(final0.reuse_count, 5.0);
    EXPECT_TRUE(final0.accept_any);
    const LookupParams pre1 = lookup_params(s, 1, false);
    EXPECT_DOUBLE_EQ(pre1.error_bound, 1.8 * 0.5 * 2.0);
    EXPECT_EQ(pre1.reuse_count, 2.0);
    EXPECT_FALSE(pre1.accept_any);
    EXPECT_DOUBLE_EQ(lookup_params(s, 0, true, 0.1).error_bound, 1.8 + 0.15);
    EXPECT_EQ(lookup_params(s, 3, true).reuse_count, 1.0);
}

// wardray's pretrace bound (--gi-pretrace-bound=final): POV-Ray's default factor is the final pass's bound, smaller
// factors keep their proportion to it, larger ones stop there; what the block's parser let through stays as it is.
TEST(LookupParams, PretraceFactorIsTheFinalBoundAtPovRaysDefault) {
    EXPECT_DOUBLE_EQ(pretrace_low_error_factor(kPovLowErrorFactor), 1.0);
    EXPECT_DOUBLE_EQ(pretrace_low_error_factor(0.25), 0.5);
    EXPECT_DOUBLE_EQ(pretrace_low_error_factor(0.1), 0.2);
    EXPECT_DOUBLE_EQ(pretrace_low_error_factor(0.8), 1.0);
    EXPECT_DOUBLE_EQ(pretrace_low_error_factor(3.0), 1.0);
    EXPECT_DOUBLE_EQ(pretrace_low_error_factor(0.0), 0.0);
    EXPECT_DOUBLE_EQ(pretrace_low_error_factor(-1.0), -1.0);
    EXPECT_TRUE(std::isnan(pretrace_low_error_factor(std::nan(""))));
    scene::RadiositySettings s;
    s.low_error_factor = pretrace_low_error_factor(s.low_error_factor);
    EXPECT_DOUBLE_EQ(lookup_params(s, 0, false).error_bound, lookup_params(s, 0, true).error_bound);
}

TEST(Validity, ErrorTermDoublesRotationAsPovRay) {
    const IrradianceRecord r = flat_record({0, 0, 0}, {1, 1, 1}, 2.0);
    EXPECT_DOUBLE_EQ(record_error(r, {1, 0, 0}, {0, 1, 0}), 0.5);
    const Vec3 tilted = normalize(Vec3{0.6, 0.8, 0});
    EXPECT_NEAR(record_error(r, {0, 0, 0}, tilted), 2.0 * std::sqrt(0.2), 1e-12);
    EXPECT_TRUE(is_valid(r, {3.5, 0, 0}, {0, 1, 0}, 1.8));
    EXPECT_FALSE(is_valid(r, {3.7, 0, 0}, {0, 1, 0}, 1.8));
    EXPECT_FALSE(is_valid(r, {0, 0, 0}, {0, -1, 0}, 10.0));  // facing away
}

TEST(Validity, BehindTestRejectsRecordsInFrontAndIsScaleFree) {
    for (const double scale : {1e-3, 1.0, 1e4}) {
        const IrradianceRecord in_front = flat_record(Vec3{0.1, 0.3, 0} * scale, {1, 1, 1}, 1.0 * scale);
        const IrradianceRecord behind = flat_record(Vec3{0.1, -0.3, 0} * scale, {1, 1, 1}, 1.0 * scale);
        const Vec3 p{0, 0, 0};
        EXPECT_FALSE(is_valid(in_front, p, {0, 1, 0}, 1.8)) << scale;
        EXPECT_TRUE(is_valid(behind, p, {0, 1, 0}, 1.8)) << scale;
        InterpolationAccumulator acc(p, {0, 1, 0}, params());
        EXPECT_FALSE(acc.add(in_front));
        EXPECT_TRUE(acc.add(behind));
    }
}

TEST(Interpolation, ExactAtTheRecordsOwnPointAndNormal) {
    IrradianceRecord r = flat_record({1, 2, 3}, {0.3, 0.6, 0.9}, 0.5);
    r.rotational = {Vec3{0.1, 0, 0.2}, Vec3{-0.3, 0, 0}, Vec3{0, 0, 0.4}};
    r.translational = {Vec3{0.5, 0, 0.1}, Vec3{0, 0, -0.2}, Vec3{0.3, 0, 0.3}};
    InterpolationAccumulator acc(r.position, r.normal, params());
    ASSERT_TRUE(acc.add(r));
    EXPECT_EQ(acc.result().irradiance, r.irradiance);
    EXPECT_TRUE(acc.result().sufficient);
}

TEST(Interpolation, ReproducesALinearFieldFromExactGradients) {
    // E(p) = a + G·p on the floor: with ∇t E = G every record extrapolates exactly, so the average is exact.
    const Vec3 a{0.5, 0.7, 0.9};
    const ChannelGradients g{Vec3{0.2, 0, -0.1}, Vec3{-0.05, 0, 0.1}, Vec3{0.1, 0, 0.1}};
    const auto field = [&](const Vec3& p) { return a + Vec3{dot(g[0], p), dot(g[1], p), dot(g[2], p)}; };
    std::vector<IrradianceRecord> records;
    for (int i = 0; i < 5; ++i) {
        for (int k = 0; k < 5; ++k) {
            IrradianceRecord r = flat_record({0.3 * i, 0, 0.3 * k}, {}, 0.4);
            r.irradiance = field(r.position);
            r.translational = g;
            records.push_back(r);
        }
    }
    for (const Vec3& q : {Vec3{0.45, 0, 0.45}, Vec3{0.1, 0, 0.9}, Vec3{1.1, 0, 0.2}}) {
        InterpolationAccumulator with(q, {0, 1, 0}, params());
        for (const IrradianceRecord& r : records) with.add(r);
        ASSERT_GT(with.result().records, 1);
        const Vec3 diff = with.result().irradiance - field(q);
        EXPECT_LT(max_abs_component(diff), 1e-12);
    }
}

TEST(Interpolation, GradientsLowerTheErrorAgainstBruteForce) {
    // Records 0.15 apart on the room's floor in front of the back wall's bright patch; queries between them.
    const test::RoomScene room;
    const scene::RadiositySettings settings;
    std::vector<IrradianceRecord> records;
    for (int i = 0; i < 4; ++i) {
        for (int k = 0; k < 4; ++k) {
            const Vec3 p{-0.9 + 0.15 * i, 0.0, 2.3 + 0.15 * k};
            const GatherResult g = gather(p, {0, 1, 0}, strata_for_count(65536), room.radiance_at(p));
            records.push_back(make_record(p, {0, 1, 0}, g, 0, {0.02, 0.12}));
        }
    }
    // Queries inside the grid, off-centre, and just outside it (the cache's frontier, where an average of records
    // cannot cancel the first-order change).
    const Vec3 queries[] = {{-0.71, 0, 2.49}, {-0.64, 0, 2.41}, {-0.79, 0, 2.71}, {-0.86, 0, 2.56},
                            {-0.96, 0, 2.45}, {-0.40, 0, 2.52}, {-0.70, 0, 2.80}, {-0.66, 0, 2.25}};
    double error_with = 0.0, error_without = 0.0;
    int better = 0;
    for (const Vec3& q : queries) {
        const Vec3 truth = gather(q, {0, 1, 0}, strata_for_count(262144), room.radiance_at(q)).irradiance;
        LookupParams on = lookup_params(settings, 0, true), off = on;
        off.gradients = false;
        InterpolationAccumulator with(q, {0, 1, 0}, on), without(q, {0, 1, 0}, off);
        for (const IrradianceRecord& r : records) {
            with.add(r);
            without.add(r);
        }
        ASSERT_GT(with.result().records, 0);
        const double ew = length(with.result().irradiance - truth);
        const double eo = length(without.result().irradiance - truth);
        error_with += ew;
        error_without += eo;
        better += ew < eo ? 1 : 0;
        std::printf("  (%.2f, %.2f): %d records, error with gradients %.4f, without %.4f\n", q.x, q.z,
                    with.result().records, ew, eo);
    }
    std::printf("interpolation error, sum over %zu points: with gradients %.4f, without %.4f (%d better)\n",
                std::size(queries), error_with, error_without, better);
    EXPECT_LT(error_with, 0.8 * error_without);
    EXPECT_GE(better, 6);
}

// Weighing a record by its packed geometry (as lookups do) and adding it afterwards gives what add() gives, bit for
// bit, and weigh_near() agrees with weigh() on the records within error_bound × R_i.
TEST(Interpolation, WeighThenAddWeightedEqualsAdd) {
    SplitMix64 rng(5);
    auto u = [&](double lo, double hi) { return lo + (hi - lo) * rng.uniform(); };
    for (int qi = 0; qi < 200; ++qi) {
        const Vec3 p{u(-1, 1), u(-1, 1), u(-1, 1)};
        const Vec3 n = normalize(Vec3{u(-0.3, 0.3), 1.0, u(-0.3, 0.3)});
        LookupParams lp = params(u(0.2, 2.0));
        lp.smooth_coverage = qi % 2 == 0;
        InterpolationAccumulator whole(p, n, lp), split(p, n, lp);
        int valid = 0;
        for (int i = 0; i < 50; ++i) {
            IrradianceRecord r = flat_record(p + Vec3{u(-1, 1), u(-0.2, 0.2), u(-1, 1)}, {u(0, 1), u(0, 1), 1}, u(0.1, 1));
            r.normal = normalize(Vec3{u(-1, 1), 1.0, u(-1, 1)});
            r.translational[0] = {u(-1, 1), 0.1, 0.2};
            r.rotational[2] = {0.3, u(-1, 1), 0.1};
            const bool added = whole.add(r);
            RecordWeight w;
            const RecordGeometry g = geometry_of(r);
            ASSERT_EQ(split.weigh(g, w), added);
            const Vec3 d = p - r.position;
            const double reach = lp.error_bound * r.radius;
            if (dot(d, d) < reach * reach) {
                RecordWeight near;
                ASSERT_EQ(split.weigh_near(g, near), added);
                if (added) {
                    ASSERT_TRUE(near.weight == w.weight && near.coverage == w.coverage);
                }
            }
            if (added) {
                split.add_weighted(r, w);
                EXPECT_TRUE(is_valid(r, p, n, lp.error_bound));
            }
            valid += added ? 1 : 0;
        }
        const Interpolation a = whole.result(), b = split.result();
        ASSERT_TRUE(a.irradiance == b.irradiance && a.weight_sum == b.weight_sum && a.coverage == b.coverage);
        ASSERT_EQ(a.records, valid);
    }
}

TEST(Interpolation, ExtrapolationNeverGoesNegative) {
    IrradianceRecord r = flat_record({0, 0, 0}, {0.1, 0.0, 0.2}, 1.0);
    r.translational = {Vec3{-5, 0, 0}, Vec3{-5, 0, 0}, Vec3{5, 0, 0}};
    r.rotational = {Vec3{0, 0, -5}, Vec3{0, 0, -5}, Vec3{0, 0, -5}};
    for (const double x : {-0.9, -0.3, 0.3, 0.9}) {
        const Vec3 e = extrapolate(r, {x, 0, 0}, normalize(Vec3{0.2, 1, 0}));
        EXPECT_GE(e.x, 0.0);
        EXPECT_GE(e.y, 0.0);
        EXPECT_GE(e.z, 0.0);
        InterpolationAccumulator acc({x, 0, 0}, {0, 1, 0}, params());
        acc.add(r);
        EXPECT_GE(acc.result().irradiance.x, 0.0);
    }
}

TEST(Interpolation, RotationalTermSignFollowsTheNormal) {
    // The rotational term uses n_i × n: turning the normal towards +x about z changes E by a·∇r E with a = −z.
    IrradianceRecord r = flat_record({0, 0, 0}, {1, 1, 1}, 1.0);
    r.rotational = {Vec3{0, 0, -1}, Vec3{0, 0, -1}, Vec3{0, 0, -1}};
    const Vec3 n = normalize(Vec3{0.01, 1, 0});
    EXPECT_NEAR(extrapolate(r, {0, 0, 0}, n).x, 1.0 + dot(cross(r.normal, n), r.rotational[0]), 1e-15);
    EXPECT_GT(extrapolate(r, {0, 0, 0}, n).x, 1.0);
}

TEST(Record, RadiusFollowsHarmonicMeanWithinTheLimits) {
    GatherResult g;
    g.irradiance = {1, 1, 1};
    g.harmonic_mean_distance = 0.5;
    EXPECT_DOUBLE_EQ(make_record({0, 0, 0}, {0, 1, 0}, g, 0, {0.1, 1.0}).radius, 0.5);
    EXPECT_DOUBLE_EQ(make_record({0, 0, 0}, {0, 1, 0}, g, 0, {0.6, 1.0}).radius, 0.6);
    EXPECT_DOUBLE_EQ(make_record({0, 0, 0}, {0, 1, 0}, g, 0, {0.1, 0.3}).radius, 0.3);
    // POV-Ray's reuse limits: fractions of the distance to the camera, doubled per bounce.
    const scene::RadiositySettings s;
    const RadiusLimits l0 = radius_limits(s, 0, 10.0), l1 = radius_limits(s, 1, 10.0);
    EXPECT_DOUBLE_EQ(l0.min, 0.15);
    EXPECT_DOUBLE_EQ(l0.max, 2.0);
    EXPECT_DOUBLE_EQ(l1.max, 4.0);
    EXPECT_DOUBLE_EQ(radius_limits(s, 0, 10.0, 0.5, 1.0).min, 0.5);
    EXPECT_DOUBLE_EQ(radius_limits(s, 0, 10.0, 0.5, 1.0).max, 1.0);
}

TEST(Record, GradientCapsTheRadiusAndIsLimitedWhenClamped) {
    GatherResult g;
    g.irradiance = {1.0, 2.0, 1.0};
    g.harmonic_mean_distance = 1.0;
    g.translational = {Vec3{4, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 0, 0}};
    // Largest relative gradient is 4 (red): R ≤ 1/4.
    EXPECT_DOUBLE_EQ(make_record({0, 0, 0}, {0, 1, 0}, g, 0, {0.01, 10.0}).radius, 0.25);
    RecordOptions no_cap;
    no_cap.gradient_radius_cap = false;
    EXPECT_DOUBLE_EQ(make_record({0, 0, 0}, {0, 1, 0}, g, 0, {0.01, 10.0}, no_cap).radius, 1.0);
    // Clamped up from 0.25 to 0.5: the translational gradient is halved.
    const IrradianceRecord clamped = make_record({0, 0, 0}, {0, 1, 0}, g, 0, {0.5, 10.0});
    EXPECT_DOUBLE_EQ(clamped.radius, 0.5);
    EXPECT_DOUBLE_EQ(clamped.translational[0].x, 2.0);
    RecordOptions off;
    off.gradients = false;
    EXPECT_EQ(make_record({0, 0, 0}, {0, 1, 0}, g, 0, {0.01, 10.0}, off).translational[0], Vec3{});
}

TEST(Record, GeometryFloorLowersMinimumReuseNearGeometryDownToTheFootprint) {
    // A gather next to geometry (harmonic mean distance 0.1) where POV-Ray's minimum_reuse asks for 0.6: with the
    // geometry floor the radius may go down to half the harmonic distance, never below the pixel footprint, at
    // depth 0 only; a radius the gather itself sets above the floor stays; off, POV-Ray's floor holds.
    GatherResult g;
    g.irradiance = {1, 1, 1};
    g.harmonic_mean_distance = 0.1;
    RecordOptions floor;
    floor.geometry_floor = true;
    const Vec3 p{0, 0, 0}, n{0, 1, 0};
    EXPECT_DOUBLE_EQ(make_record(p, n, g, 0, {0.6, 10.0, 0.01}, floor).radius, 0.1);
    g.harmonic_mean_distance = 0.04;
    EXPECT_DOUBLE_EQ(make_record(p, n, g, 0, {0.6, 10.0, 0.01}, floor).radius, 0.04);
    // A gradient cap (E/|grad E| = 0.01) under the new floor (kGeometryFloorFraction × 0.04) is clamped up to it,
    // with the gradient scaled down as any clamp scales it.
    g.translational = {Vec3{100, 0, 0}, Vec3{}, Vec3{}};
    const IrradianceRecord capped = make_record(p, n, g, 0, {0.6, 10.0, 0.001}, floor);
    EXPECT_DOUBLE_EQ(capped.radius, kGeometryFloorFraction * 0.04);
    EXPECT_NEAR(capped.translational[0].x, 100.0 * 0.01 / capped.radius, 1e-4);
    g.translational = {};
    // Never below the footprint, never above POV-Ray's floor, not deeper than depth 0, and not without the option.
    EXPECT_DOUBLE_EQ(make_record(p, n, g, 0, {0.6, 10.0, 0.05}, {}).radius, 0.6);
    g.harmonic_mean_distance = 0.004;
    EXPECT_DOUBLE_EQ(make_record(p, n, g, 0, {0.6, 10.0, 0.05}, floor).radius, 0.05);
    EXPECT_DOUBLE_EQ(make_record(p, n, g, 0, {0.6, 10.0, 0.9}, floor).radius, 0.6);
    EXPECT_DOUBLE_EQ(make_record(p, n, g, 1, {0.6, 10.0, 0.05}, floor).radius, 0.6);
    // Far from geometry the floor is POV-Ray's, and the footprint comes from radius_limits().
    g.harmonic_mean_distance = 5.0;
    EXPECT_DOUBLE_EQ(make_record(p, n, g, 0, {0.6, 10.0, 0.05}, floor).radius, 5.0);
    const scene::RadiositySettings s;
    EXPECT_DOUBLE_EQ(radius_limits(s, 0, 10.0, 0.02).footprint, 0.02);
    EXPECT_DOUBLE_EQ(radius_limits(s, 0, 10.0).footprint, 0.0);
}

TEST(Record, NeighbourClampingBoundsRadiiByDistance) {
    IrradianceRecord a = flat_record({0, 0, 0}, {1, 1, 1}, 5.0);
    IrradianceRecord b = flat_record({1, 0, 0}, {1, 1, 1}, 0.5);
    EXPECT_TRUE(neighbour_clamp(a, b));
    EXPECT_DOUBLE_EQ(a.radius, 1.5);
    EXPECT_DOUBLE_EQ(b.radius, 0.5);
    EXPECT_FALSE(neighbour_clamp(b, a));
}

TEST(Record, DegenerateGathersGiveFiniteRecords) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    for (const double hm : {0.0, inf, std::nan("")}) {
        GatherResult g;
        g.harmonic_mean_distance = hm;
        g.translational = {Vec3{1e300, 0, 0}, Vec3{}, Vec3{}};
        for (const RadiusLimits l : {RadiusLimits{0.0, 0.0}, RadiusLimits{0.0, inf}, RadiusLimits{0.1, 1.0}}) {
            const IrradianceRecord r = make_record({0, 0, 0}, {0, 1, 0}, g, 0, l);
            EXPECT_TRUE(std::isfinite(r.radius) && r.radius > 0.0) << hm;
            EXPECT_TRUE(is_finite(r.translational[0]));
            InterpolationAccumulator acc({0.01, 0, 0}, {0, 1, 0}, params());
            acc.add(r);
            EXPECT_TRUE(is_finite(acc.result().irradiance));
        }
    }
    // Zero-radius limits and a record at the query point: still finite.
    InterpolationAccumulator acc({0, 0, 0}, {0, 0, 0}, params());
    acc.add(flat_record({0, 0, 0}, {1, 1, 1}, 1e-300));
    EXPECT_TRUE(is_finite(acc.result().irradiance));
}

}  // namespace
}  // namespace wardray::cache
