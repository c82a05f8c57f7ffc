// Tests of the atmosphere statements: sky_sphere, fog and rainbow as POV-Ray reads them, declared ones too.
#include <cmath>
#include <numbers>
#include <string>

#include "tests/parser/test_util.h"

namespace wardray::parser {
namespace {

using test::parse_ok;

constexpr double kDeg = std::numbers::pi / 180.0;

bool has_warning(const Scene& s, const std::string& text) {
    for (const auto& w : s.warnings)
        if (w.message.find(text) != std::string::npos) return true;
    return false;
}

TEST(SkySphere, DeclaredIsCopiedThenExtendedAndTransformed) {
    const Scene s = parse_ok(R"(
        #version 3.7;
        #declare S = sky_sphere { pigment { rgb 1 } emission rgb 0.5 }
        sky_sphere { S pigment { rgbt <1, 0, 0, 0.5> } rotate 90*y }
    )");
    ASSERT_TRUE(s.sky_sphere.has_value());
    ASSERT_EQ(s.sky_sphere->pigments.size(), 2u);
    EXPECT_DOUBLE_EQ(s.sky_sphere->emission.g, 0.5);
    EXPECT_DOUBLE_EQ(s.sky_sphere->pigments[1].color.transmit, 0.5);
    EXPECT_FALSE(s.sky_sphere->transform.is_identity());
    EXPECT_FALSE(s.sky_sphere->legacy_layering);
    EXPECT_TRUE(s.warnings.empty() || !has_warning(s, "not rendered"));
}

TEST(SkySphere, PigmentsStartBlackNotFromTheDefaultAndOldVersionsLayerTheOldWay) {
    const Scene s = parse_ok(R"(
        #version 3.6;
        #default { pigment { rgb <0, 1, 0> } }
        sky_sphere { pigment { } }
    )");
    ASSERT_TRUE(s.sky_sphere.has_value());
    EXPECT_EQ(s.sky_sphere->pigments[0].color, (Color{}));
    EXPECT_TRUE(s.sky_sphere->legacy_layering);
    // No #version at all counts as 3.62.
    EXPECT_TRUE(parse_ok("sky_sphere { pigment { rgb 1 } }").sky_sphere->legacy_layering);
    const Scene two = parse_ok("#version 3.7; sky_sphere { pigment { rgb 1 } } sky_sphere { pigment { rgb 0 } }");
    EXPECT_TRUE(has_warning(two, "Only one sky-sphere allowed"));
    EXPECT_EQ(two.sky_sphere->pigments[0].color, (Color{}));
}

TEST(SkySphere, EmptyOrOfTheWrongKindIsAnError) {
    auto r = test::parse_fail("sky_sphere { emission 1 }\n");
    EXPECT_EQ(r.diagnostics[0].message, "Empty sky_sphere statement.");
    r = test::parse_fail("#declare F = fog { distance 1 }\nsky_sphere { F }\n");
    EXPECT_EQ(r.diagnostics[0].message, "'F' is a fog, not a sky_sphere");
}

TEST(Fog, ReadsGroundFogItemsAndTurnsItsUpVector) {
    const Scene s = parse_ok(R"(
        fog { fog_type 2 distance 5 color rgbf <1, 0.5, 0, 0.5> fog_offset 1 fog_alt 2
              up <0, 2, 0> rotate 90*z turbulence <1, 2, 3> turb_depth 0.25 octaves 20 omega 0.4 lambda 3 }
    )");
    ASSERT_EQ(s.fogs.size(), 1u);
    const Fog& f = s.fogs[0];
    EXPECT_EQ(f.type, 2);
    EXPECT_DOUBLE_EQ(f.distance, 5);
    EXPECT_DOUBLE_EQ(f.color.filter, 0.5);
    EXPECT_DOUBLE_EQ(f.offset, 1);
    EXPECT_DOUBLE_EQ(f.alt, 2);
    // up y turned 90° about z (left-handed) is −x, normalised.
    EXPECT_NEAR(f.up.x, -1.0, 1e-12);
    EXPECT_NEAR(f.up.y, 0.0, 1e-12);
    ASSERT_TRUE(f.turbulence.has_value());
    EXPECT_EQ(f.turbulence->amount, (Vec3{1, 2, 3}));
    EXPECT_EQ(f.turbulence->octaves, 10);  // POV-Ray clamps octaves to 10
    EXPECT_DOUBLE_EQ(f.turbulence->omega, 0.4);
    EXPECT_DOUBLE_EQ(f.turbulence->lambda, 3);
    EXPECT_DOUBLE_EQ(f.turb_depth, 0.25);
    EXPECT_FALSE(has_warning(s, "not rendered"));
}

TEST(Fog, DeclaredFogsBareDistancesAndTranslationsAsPovRayReadsThem) {
    const Scene s = parse_ok(R"(
        #declare D = 7;
        #declare F = fog { distance 3 color rgb 1 }
        fog { F fog_type 2 fog_alt 1 translate y }
        fog { D rgb 0.5 }
    )");
    ASSERT_EQ(s.fogs.size(), 2u);
    EXPECT_DOUBLE_EQ(s.fogs[0].distance, 3);
    EXPECT_EQ(s.fogs[0].type, 2);
    EXPECT_EQ(s.fogs[0].up, (Vec3{0, 1, 0}));
    EXPECT_DOUBLE_EQ(s.fogs[1].distance, 7);
    EXPECT_DOUBLE_EQ(s.fogs[1].color.r, 0.5);
    EXPECT_TRUE(has_warning(s, "A fog's up vector can't be translated."));
    EXPECT_TRUE(has_warning(s, "Should use distance keyword."));
}

TEST(Rainbow, IsSetUpAsPovRayDoes) {
    const Scene s = parse_ok(R"(
        rainbow { angle 42 width 4 distance 1e5 jitter 0.01 direction <0, 0, 2> up <0, 1, 1>
                  arc_angle 120 color_map { [0 rgb 1] [1 rgb 0] } }
    )");
    ASSERT_EQ(s.rainbows.size(), 1u);
    const Rainbow& r = s.rainbows[0];
    EXPECT_NEAR(r.angle, 40.0 * kDeg, 1e-12);  // the inner edge: angle less half the width
    EXPECT_NEAR(r.width, 4.0 * kDeg, 1e-12);
    EXPECT_NEAR(r.arc_angle, 60.0 * kDeg, 1e-12);
    EXPECT_NEAR(r.falloff_angle, r.arc_angle, 1e-12);  // falloff follows arc_angle when only that is given
    EXPECT_DOUBLE_EQ(r.falloff_width, 0.0);
    EXPECT_DOUBLE_EQ(r.distance, 1e5);
    EXPECT_DOUBLE_EQ(r.jitter, 0.01);
    EXPECT_NEAR(r.antisolar.z, 1.0, 1e-12);
    // Up made perpendicular to the direction; right = up × direction.
    EXPECT_NEAR(r.up.y, 1.0, 1e-12);
    EXPECT_NEAR(r.up.z, 0.0, 1e-12);
    EXPECT_NEAR(r.right.x, 1.0, 1e-12);
    ASSERT_TRUE(r.pigment.has_value());
    EXPECT_EQ(r.pigment->color_map.size(), 2u);
    // Without arc_angle and falloff_angle the bow has no bounds: POV-Ray keeps 180 as if in radians.
    const Scene d = parse_ok("rainbow { angle 40 width 2 direction z color_map { [0 rgb 1] [1 rgb 1] } }");
    EXPECT_DOUBLE_EQ(d.rainbows[0].arc_angle, 180.0);
    EXPECT_DOUBLE_EQ(d.rainbows[0].distance, 1e7);
}

TEST(Rainbow, BadVectorsAndAnglesAreErrors) {
    auto r = test::parse_fail("rainbow { angle 40 width 2 color_map { [0 rgb 1] [1 rgb 1] } }\n");
    EXPECT_EQ(r.diagnostics[0].message, "Rainbow's direction vector is zero.");
    r = test::parse_fail("rainbow { direction y up y }\n");
    EXPECT_EQ(r.diagnostics[0].message, "Rainbow's up and direction vector are co-linear.");
    r = test::parse_fail("rainbow { direction z arc_angle 40 falloff_angle 60 }\n");
    EXPECT_EQ(r.diagnostics[0].message, "Arc angle is smaller than falloff angle in rainbow.");
    r = test::parse_fail("rainbow { direction z arc_angle 400 }\n");
    EXPECT_EQ(r.diagnostics[0].message, "Illegal arc angle in rainbow (Use value from 0 to 360 degrees).");
}

}  // namespace
}  // namespace wardray::parser
