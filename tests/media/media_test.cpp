// media/ against POV-Ray's closed forms: constant fog, the sky over the background, interior fade.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "media/atmosphere.h"
#include "media/fog.h"
#include "media/sky.h"
#include "media/transmittance.h"

namespace wardray::media {
namespace {

constexpr double kTol = 1e-12;

void expect_near(const Vec3& a, const Vec3& b, double tol = kTol) {
    EXPECT_NEAR(a.x, b.x, tol);
    EXPECT_NEAR(a.y, b.y, tol);
    EXPECT_NEAR(a.z, b.z, tol);
}

scene::Fog fog(double distance, const Color& c) {
    scene::Fog f;
    f.distance = distance;
    f.color = c;
    return f;
}

TEST(ConstantFog, BlendsTowardTheFogColourByExpOfDepthOverDistance) {
    const Fogs medium({fog(2.0, {0.5, 0.25, 1.0})}, 2);
    const Vec3 behind{1.0, 1.0, 0.0};
    const double a = std::exp(-1.0);  // depth 2 at distance 2
    expect_near(medium.along_segment(behind, Segment{{}, {0, 0, 1}, 2.0}),
                Vec3{0.5, 0.25, 1.0} * (1.0 - a) + behind * a);
    // A ray that escapes sees only the fog; one of length 0 only what is behind.
    expect_near(medium.along_segment(behind, Segment{{}, {0, 0, 1}, std::numeric_limits<double>::infinity()}),
                Vec3{0.5, 0.25, 1.0});
    expect_near(medium.along_segment(behind, Segment{{}, {0, 0, 1}, 0.0}), behind);
}

TEST(ConstantFog, TransmitBoundsTheAttenuationAndZeroDistanceIsNoFog) {
    const Fogs thin({fog(1.0, {1.0, 1.0, 1.0, 0.0, 0.75})}, 2);
    // exp(−100) is below transmit 0.75, so 0.75 of the light behind passes.
    expect_near(thin.along_segment({0, 0, 0}, Segment{{}, {1, 0, 0}, 100.0}), Vec3{0.25, 0.25, 0.25});
    const Fogs none({fog(0.0, {1.0, 0.0, 0.0})}, 2);
    expect_near(none.along_segment({0.3, 0.3, 0.3}, Segment{{}, {1, 0, 0}, 5.0}), Vec3{0.3, 0.3, 0.3});
}

TEST(Atmosphere, OnlyAFoggySceneHasOne) {
    scene::Scene scene;
    EXPECT_EQ(make_atmosphere(scene), nullptr);
    scene.fogs.push_back(fog(1.0, {1, 1, 1}));
    EXPECT_NE(make_atmosphere(scene), nullptr);
}

TEST(Sky, BackgroundAloneAndASolidSkySphereOverIt) {
    scene::Scene scene;
    // POV-Ray compat (measured with POV-Ray 3.7, +FE): a 3.7 background's transmit darkens it, its filter is
    // ignored (rgbft <0.1, 0.2, 0.3, 0.5, 0.5> renders as <0.05, 0.1, 0.15>).
    scene.background = {0.1, 0.2, 0.3, 0.5, 0.5};
    expect_near(Sky(scene).radiance({0, 1, 0}), Vec3{0.05, 0.1, 0.15});
    scene::SkySphere sphere;
    scene::Pigment half;
    half.color = {1.0, 0.0, 0.0, 0.0, 0.5};  // half transmitting: half its colour, half the background
    sphere.pigments.push_back(half);
    scene.sky_sphere = sphere;
    expect_near(Sky(scene).radiance({0, 1, 0}), Vec3{0.5, 0.0, 0.0} + Vec3{0.05, 0.1, 0.15} * 0.5);  // POV-Ray: 0.525
}

TEST(Transmittance, FilterColourIsColourTimesFilterPlusTransmit) {
    expect_near(filter_colour({0.5, 1.0, 0.0, 0.5, 0.25}), Vec3{0.5, 0.75, 0.25});
}

TEST(Transmittance, InteriorFadeFollowsPovRaysTwoForms) {
    scene::Interior interior;
    interior.fade_distance = 2.0;
    interior.fade_color = {0.2, 0.4, 1.0};
    // fade_power 2 at twice fade_distance: fade_color + (1 − fade_color)/(1 + 2²).
    interior.fade_power = 2.0;
    expect_near(interior_fade(interior, 4.0), Vec3{0.2 + 0.8 / 5.0, 0.4 + 0.6 / 5.0, 1.0});
    // fade_power ≥ 1000: exp(−(1 − fade_color)·d/fade_distance).
    interior.fade_power = 1000.0;
    expect_near(interior_fade(interior, 4.0), Vec3{std::exp(-1.6), std::exp(-1.2), 1.0});
}

}  // namespace
}  // namespace wardray::media
