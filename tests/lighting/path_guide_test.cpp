// The reference's path guide: its density is what it samples, and guided paths keep the expectation of cosine
// sampling (an analytic two-bounce integral) however well or badly the guide was learned.
#include "lighting/path_guide.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <numbers>
#include <vector>

#include "cache/hemisphere_sampler.h"
#include "lighting/indirect_light.h"
#include "lighting/path_sequence.h"
#include "seed_estimates.h"

namespace wardray::lighting {
namespace {

/// A guide learned from a pilot at the origin whose rays found radiance `bright` inside the cone cos θ > `cone`
/// about `axis` and `dim` elsewhere (directions on a fixed spiral over the sphere).
PathGuide guide_towards(const Vec3& axis, double cone, float bright, float dim) {
    std::vector<GuideSample> samples;
    const int n = 20000;
    for (int i = 0; i < n; ++i) {
        const double z = 1.0 - 2.0 * (i + 0.5) / n;
        const double r = std::sqrt(1.0 - z * z);
        const double phi = i * 2.399963229728653;  // the golden angle
        const Vec3 d{r * std::cos(phi), r * std::sin(phi), z};
        GuideSample s;
        s.p = {0.0f, 0.0f, 0.0f};
        s.dir = {static_cast<float>(d.x), static_cast<float>(d.y), static_cast<float>(d.z)};
        s.radiance = dot(d, axis) > cone ? bright : dim;
        samples.push_back(s);
    }
    return PathGuide::build(samples);
}

TEST(PathGuide, SamplesTheDensityItReports) {
    // Over the guide's own samples, f/pdf averages to ∫f dω for any f it covers: the sphere (4π) and a cap of
    // solid angle 2π(1 − cos α) around the bright cone's axis and around the opposite direction.
    const PathGuide guide = guide_towards(normalize(Vec3{0.3, 0.2, 1.0}), 0.9, 50.0f, 1.0f);
    ASSERT_FALSE(guide.empty());
    const GuideDistribution* d = guide.find({0, 0, 0}, {0, 0, 1});
    ASSERT_NE(d, nullptr);
    const int n = 1 << 16;
    const std::uint64_t seed = 99;
    double sphere = 0.0, cap = 0.0, opposite = 0.0;
    const Vec3 axis = normalize(Vec3{0.3, 0.2, 1.0});
    for (int i = 0; i < n; ++i) {
        double pdf = 0.0;
        const Vec3 w = d->sample(path_sample(static_cast<std::uint32_t>(i), 0, seed),
                                 path_sample(static_cast<std::uint32_t>(i), 1, seed), pdf);
        ASSERT_NEAR(length(w), 1.0, 1e-9);
        ASSERT_GT(pdf, 0.0);
        ASSERT_NEAR(pdf, d->pdf(w), 1e-9 * pdf) << "the sampled bin's density is not the direction's";
        sphere += 1.0 / pdf / n;
        if (dot(w, axis) > 0.8) cap += 1.0 / pdf / n;
        if (dot(w, axis) < -0.5) opposite += 1.0 / pdf / n;
    }
    // The density is zero below the +z axis's horizon (the clamped cosine), so "the sphere" is the upper half.
    EXPECT_NEAR(sphere, 2.0 * std::numbers::pi * 1.0, 0.02 * 2.0 * std::numbers::pi) << "the half the +z axis sees";
    EXPECT_NEAR(cap, 2.0 * std::numbers::pi * 0.2, 0.02 * 2.0 * std::numbers::pi * 0.2);
    EXPECT_EQ(opposite, 0.0) << "samples where the density says nothing can come from";
    // The bright cone is where the samples go: far more than its share of cosine sampling.
    int in_cone = 0;
    for (int i = 0; i < 4096; ++i) {
        double pdf = 0.0;
        in_cone += dot(d->sample(path_sample(static_cast<std::uint32_t>(i), 0, 5),
                                 path_sample(static_cast<std::uint32_t>(i), 1, 5), pdf),
                       axis) > 0.9;
    }
    EXPECT_GT(in_cone, 4096 / 2);
}

TEST(PathGuide, DensityIsNormalisedOverTheSphere) {
    // ∫ pdf dω = 1: uniform directions on a fine equal-area grid, pdf · 4π averaged. The grid's cells do not line up
    // with the guide's columns (equal steps of a pseudo-angle), which costs the quadrature about 4e-4; a bin's
    // solid angle left out of the density would be off by several per cent.
    const PathGuide guide = guide_towards({1, 0, 0}, 0.5, 10.0f, 0.5f);
    const GuideDistribution* d = guide.find({0, 0, 0}, {0, 0, 1});
    ASSERT_NE(d, nullptr);
    const int rows = 400, cols = 1600;
    double integral = 0.0;
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < cols; ++c) {
            const double z = -1.0 + 2.0 * (r + 0.5) / rows;
            const double phi = 2.0 * std::numbers::pi * (c + 0.5) / cols;
            const double s = std::sqrt(1.0 - z * z);
            integral += d->pdf({s * std::cos(phi), s * std::sin(phi), z}) * 4.0 * std::numbers::pi / (rows * cols);
        }
    EXPECT_NEAR(integral, 1.0, 2e-3);
}

/// A tracer standing in for a scene with two bounces at the origin, normal +z: a first-bounce ray along `dir` sees
/// a small bright cap (cos θ > 0.9 about `light`) plus the irradiance of a point whose own rays see the same cap.
class CapTracer final : public GatherTracer {
public:
    const IndirectLight* reference = nullptr;
    Vec3 light = normalize(Vec3{0.5, 0.0, 1.0});

    Vec3 gather_radiance(const Vec3&, const Vec3& dir, const RayState& state, std::uint64_t path_seed,
                         TraceContext& ctx, double& distance) const override {
        distance = 1.0;
        const double seen = dot(dir, light) > 0.9 ? 4.0 : 0.1;
        if (state.gi_depth == 1) return {seen, seen, seen};
        RayState next = state;
        next.gi_depth = state.gi_depth + 1;
        next.path_seed = path_seed;
        return Vec3{seen, seen, seen} + reference->irradiance({0, 0, 0}, {0, 0, 1}, 1.0, next, ctx);
    }
};

/// ∫ L cos θ dω / π for L = 4 inside the cap and 0.1 outside, by a fine quadrature over the hemisphere.
double cap_irradiance(const Vec3& light) {
    const int rows = 1000, cols = 1000;
    double e = 0.0;
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < cols; ++c) {
            // Cosine-warped cells: each carries an equal share of cos θ dω / π.
            const Vec3 d = cosine_direction((r + 0.5) / rows, (c + 0.5) / cols);
            e += (dot(d, light) > 0.9 ? 4.0 : 0.1) / (rows * cols);
        }
    return e;
}

Estimates estimate(const PathGuide* guide, int paths, int seeds) {
    return over_seeds(seeds, [&](std::uint64_t seed) {
        CapTracer tracer;
        const auto reference = make_reference_irradiance(tracer, paths, seed, guide);
        tracer.reference = reference.get();
        TraceContext ctx;
        return reference->irradiance({0, 0, 0}, {0, 0, 1}, 1.0, RayState{}, ctx).x;
    });
}

TEST(PathGuide, GuidedPathsKeepTheExpectationOfCosineSampling) {
    // E = 2 e1 with e1 the cap's irradiance: the first bounce sees the cap, and adds the second's, which sees it
    // again.
    CapTracer probe;
    const double e1 = cap_irradiance(probe.light);
    const double expected = 2.0 * e1;
    const int seeds = 20000;
    const PathGuide right = guide_towards(probe.light, 0.9, 4.0f, 0.1f);
    const PathGuide wrong = guide_towards(normalize(Vec3{-0.7, 0.3, 0.6}), 0.9, 4.0f, 0.1f);
    const Estimates plain = estimate(nullptr, 16, seeds);
    const Estimates guided = estimate(&right, 16, seeds);
    const Estimates misled = estimate(&wrong, 16, seeds);
    for (const auto& [name, e] : {std::pair{"cosine", plain}, {"guided", guided}, {"misled", misled}}) {
        EXPECT_NEAR(e.mean, expected, 5.0 * std::sqrt(e.variance / seeds)) << name;
        EXPECT_LT(5.0 * std::sqrt(e.variance / seeds), 0.02 * expected) << name << ": the tolerance is too loose";
    }
    // A guide towards the light pays: far less variance than cosine sampling.
    EXPECT_LT(guided.variance, 0.5 * plain.variance) << guided.variance << " against " << plain.variance;
    std::cout << "[ guide] variance of 16 paths: cosine " << plain.variance << ", guided " << guided.variance
              << ", misled " << misled.variance << "\n";
}

}  // namespace
}  // namespace wardray::lighting
