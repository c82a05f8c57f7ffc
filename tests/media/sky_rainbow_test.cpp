// The sky sphere (POV-Ray 3.7's and 3.6's layering, emission, transforms) and rainbows against hand-computed
// values from POV-Ray's ComputeSky and ComputeRainbow.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "media/fog.h"
#include "media/rainbow.h"
#include "media/sky.h"

namespace wardray::media {
namespace {

void expect_near(const Vec3& a, const Vec3& b, double tol = 1e-12) {
    EXPECT_NEAR(a.x, b.x, tol);
    EXPECT_NEAR(a.y, b.y, tol);
    EXPECT_NEAR(a.z, b.z, tol);
}

scene::Pigment solid(const Color& c) {
    scene::Pigment p;
    p.color = c;
    return p;
}

// A bottom pigment and a filtering top one over a background, in both layering rules.
scene::Scene two_layer_sky(bool legacy) {
    scene::Scene scene;
    scene.background = {0.2, 0.4, 0.6};
    scene::SkySphere sky;
    sky.pigments.push_back(solid({0.5, 0.5, 1.0, 0.0, 0.5}));  // first: half transmitting
    sky.pigments.push_back(solid({1.0, 0.5, 0.0, 0.4, 0.2}));  // last, seen first: filter .4 transmit .2
    sky.emission = {2.0, 1.0, 1.0};
    sky.legacy_layering = legacy;
    scene.sky_sphere = sky;
    return scene;
}

TEST(Sky, LayersLikeATextureInPovRay37) {
    // Top: opacity .4 → (1,.5,0)·.4·emission; its filter colour (1,.5,0)·.4 + .2 = (.6,.4,.2).
    // Bottom: opacity .5 → (.5,.5,1)·.5·(.6,.4,.2)·emission; its filter (.5,.5,.5)·(.6,.4,.2) passes the background.
    const Vec3 e{2.0, 1.0, 1.0};
    const Vec3 top = Vec3{1.0, 0.5, 0.0} * 0.4 * e;
    const Vec3 f1{0.6, 0.4, 0.2};
    const Vec3 bottom = Vec3{0.5, 0.5, 1.0} * 0.5 * f1 * e;
    const Vec3 bg = Vec3{0.2, 0.4, 0.6} * (f1 * 0.5);
    expect_near(Sky(two_layer_sky(false)).radiance({0, 0, 1}), top + bottom + bg);
}

TEST(Sky, LayersByPovRay36sRuleBeforeVersion37) {
    // ComputeSky before 3.7: col += rgb·trans·(1 − f − t), the product of all five components carried on,
    // trans = |f| + |t| of the product; emission scales the pigments' sum; the background shows through
    // the product's rgb·filter + transmit.
    const Vec3 top{1.0 * 0.4, 0.5 * 0.4, 0.0};
    const double trans = 0.4 + 0.2;  // product after the top: filter .4, transmit .2
    const Vec3 bottom = Vec3{0.5, 0.5, 1.0} * (trans * 0.5);
    const Vec3 prod_rgb{0.5, 0.25, 0.0};
    const double prod_f = 0.4 * 0.0;
    const double prod_t = 0.2 * 0.5;
    const Vec3 bg = Vec3{0.2, 0.4, 0.6} * (prod_rgb * prod_f + Vec3{prod_t, prod_t, prod_t});
    expect_near(Sky(two_layer_sky(true)).radiance({0, 0, 1}), (top + bottom) * Vec3{2.0, 1.0, 1.0} + bg);
}

TEST(Sky, TransformsTurnTheDirectionAsAPoint) {
    scene::Scene scene;
    scene::SkySphere sky;
    scene::Pigment g;
    g.pattern.type = scene::Pattern::Type::Gradient;
    g.pattern.params->gradient = {0.0, 1.0, 0.0};
    g.color_map = {{0.0, {0.0, 0.0, 0.0}}, {1.0, {1.0, 1.0, 1.0}}};
    sky.pigments.push_back(g);
    sky.transform = Transform::rotation({0.0, 0.0, 90.0});  // y turns toward −x
    scene.sky_sphere = sky;
    const Sky s(scene);
    // Looking along −x sees what the untransformed sky shows along +y (a gradient value of 1 wraps to 0,
    // so look at 0.5 of the way up).
    const Vec3 d = normalize(Vec3{-0.5, 0.0, std::sqrt(0.75)});
    expect_near(s.radiance(d), Vec3{0.5, 0.5, 0.5}, 1e-9);
    // A translated sky_sphere shifts its pattern (POV-Ray transforms the direction as a point).
    scene.sky_sphere->transform = Transform::translation({0.0, 0.25, 0.0});
    expect_near(Sky(scene).radiance({0.0, 0.5, std::sqrt(0.75)}), Vec3{0.25, 0.25, 0.25}, 1e-9);
}

// A rainbow of one colour around the antisolar direction +z, 40° out, 10° wide.
scene::Rainbow bow(const Color& c) {
    scene::Rainbow r;
    r.angle = 35.0 * std::numbers::pi / 180.0;
    r.width = 10.0 * std::numbers::pi / 180.0;
    r.distance = 100.0;
    r.arc_angle = 180.0;  // POV-Ray's default: no bound
    r.falloff_angle = 180.0;
    r.antisolar = {0.0, 0.0, 1.0};
    r.up = {0.0, 1.0, 0.0};
    r.right = {1.0, 0.0, 0.0};
    scene::Pigment p;
    p.pattern.type = scene::Pattern::Type::Gradient;
    p.color_map = {{0.0, c}, {1.0, c}};
    r.pigment = p;
    return r;
}

Vec3 at_degrees(double from_antisolar, double around) {
    const double a = from_antisolar * std::numbers::pi / 180.0;
    const double b = around * std::numbers::pi / 180.0;
    return {std::sin(a) * std::sin(b), std::sin(a) * std::cos(b), std::cos(a)};
}

TEST(Rainbow, BlendsItsColourByOneMinusExpOfDepthOverDistanceInsideTheBand) {
    const Rainbows r({bow({1.0, 0.5, 0.0, 0.5, 0.0})}, 2);
    const Vec3 behind{0.2, 0.4, 0.6};
    const double k = std::exp(-50.0 / 100.0);
    const double f = 0.5 * (1.0 - k);  // filter, attenuated
    const Vec3 expected = k * behind * (Vec3{1.0 - f, 1.0 - f, 1.0 - f} + Vec3{1.0, 0.5, 0.0} * f) +
                          (1.0 - k) * Vec3{1.0, 0.5, 0.0};
    expect_near(r.apply(behind, at_degrees(40.0, 30.0), 50.0, 1), expected);
    // Outside the band, and on the sun's side, nothing changes.
    expect_near(r.apply(behind, at_degrees(30.0, 30.0), 50.0, 1), behind);
    expect_near(r.apply(behind, at_degrees(140.0, 30.0), 50.0, 1), behind);
    // Against the sky (BOUND_HUGE away) only the rainbow is seen.
    expect_near(r.apply(behind, at_degrees(40.0, 30.0), kSkyDepth, 1), Vec3{1.0, 0.5, 0.0});
}

TEST(Rainbow, ArcAngleCutsTheBowAndFalloffFadesItAndSeveralAreAveraged) {
    scene::Rainbow cut = bow({1.0, 0.0, 0.0});
    cut.arc_angle = 60.0 * std::numbers::pi / 180.0;  // arc_angle 120 given: 60° either side of up
    cut.falloff_angle = 30.0 * std::numbers::pi / 180.0;
    cut.falloff_width = cut.arc_angle - cut.falloff_angle;
    const Rainbows r({cut}, 2);
    const Vec3 behind{0.0, 0.0, 1.0};
    expect_near(r.apply(behind, at_degrees(40.0, 90.0), kSkyDepth, 1), behind);  // 90° from up: outside
    expect_near(r.apply(behind, at_degrees(40.0, 20.0), kSkyDepth, 1), Vec3{1.0, 0.0, 0.0});
    // 45° from up: halfway through the fall-off, smoothstep 0.5, so half of what is behind passes.
    expect_near(r.apply(behind, at_degrees(40.0, 45.0), kSkyDepth, 1), Vec3{0.5, 0.0, 0.5}, 1e-9);
    // Two bows over the same ray: the mean of each one's result.
    const Rainbows two({bow({1.0, 0.0, 0.0}), bow({0.0, 1.0, 0.0})}, 2);
    expect_near(two.apply(behind, at_degrees(40.0, 0.0), kSkyDepth, 1), Vec3{0.5, 0.5, 0.0});
}

TEST(Rainbow, JitterDependsOnlyOnTheSeed) {
    scene::Rainbow j = bow({1.0, 1.0, 1.0});
    j.jitter = 0.3;
    const Rainbows r({j}, 2);
    // Near the band's edge some seeds jitter the index out of [0, 1), others not; each seed always alike.
    const Vec3 d = at_degrees(35.5, 10.0);
    int inside = 0;
    for (std::uint64_t seed = 0; seed < 64; ++seed) {
        const Vec3 a = r.apply({}, d, kSkyDepth, seed);
        expect_near(a, r.apply({}, d, kSkyDepth, seed), 0.0);
        inside += a.x > 0.5 ? 1 : 0;
    }
    EXPECT_GT(inside, 5);
    EXPECT_LT(inside, 59);
}

}  // namespace
}  // namespace wardray::media
