// Gamma: the transfer functions, their transcoding and the 8-bit values they give, against POV-Ray 3.7's own output.
#include <gtest/gtest.h>

#include <cmath>

#include "core/gamma.h"
#include "render/image_writers.h"
#include "render/output_gamma.h"

namespace wardray {
namespace {

TEST(GammaCurve, PowerLawEncodesWithTheInverseExponent) {
    const GammaCurve g = GammaCurve::power_law(2.2);
    EXPECT_EQ(g.kind, GammaCurve::Kind::PowerLaw);
    EXPECT_NEAR(g.encode(0.5), std::pow(0.5, 1.0 / 2.2), 1e-12);
    EXPECT_NEAR(g.decode(0.5), std::pow(0.5, 2.2), 1e-12);
    EXPECT_NEAR(g.decode(g.encode(0.3)), 0.3, 1e-12);
    EXPECT_NEAR(g.decode(1.5), std::pow(1.5, 2.2), 1e-12);  // values above 1 are not clipped
    EXPECT_EQ(g.encode(-0.2), 0.0);
    EXPECT_EQ(g.decode(-0.2), 0.0);
}

TEST(GammaCurve, PowerLawWithinOnePercentOfOneIsNeutral) {
    EXPECT_TRUE(GammaCurve::power_law(1.0).is_neutral());
    EXPECT_TRUE(GammaCurve::power_law(1.005).is_neutral());
    EXPECT_FALSE(GammaCurve::power_law(1.02).is_neutral());
    EXPECT_EQ(GammaCurve::power_law(1.005).encode(0.25), 0.25);
}

TEST(GammaCurve, SrgbIsIec61966) {
    const GammaCurve s = GammaCurve::srgb();
    EXPECT_NEAR(s.encode(0.0031308), 0.04045, 1e-5);  // where the two pieces meet
    EXPECT_NEAR(s.encode(0.001), 0.01292, 1e-12);
    EXPECT_NEAR(s.encode(1.0), 1.0, 1e-12);
    EXPECT_NEAR(s.decode(0.5), 0.214041, 1e-6);
    EXPECT_NEAR(s.decode(s.encode(0.7)), 0.7, 1e-12);
    EXPECT_NEAR(s.decode(1.5), std::pow(1.555 / 1.055, 2.4), 1e-12);  // the formula goes on above 1
}

TEST(GammaTranscoding, FollowsPovRaysSimplifications) {
    const GammaCurve srgb = GammaCurve::srgb();
    // A neutral working gamma leaves the target alone; matching curves cancel.
    EXPECT_EQ(transcoding(GammaCurve::neutral(), srgb), (GammaTranscoding{GammaCurve::neutral(), srgb}));
    EXPECT_TRUE(transcoding(srgb, srgb).is_neutral());
    EXPECT_TRUE(transcoding(GammaCurve::power_law(2.0), GammaCurve::power_law(1.985)).is_neutral());
    // Two power laws fold into one: 2.2 to 1.0 encodes as x^2.2, 1.5 to 2.0 as x^(1.5/2).
    EXPECT_NEAR(transcoding(GammaCurve::power_law(2.2), GammaCurve::neutral()).encode(0.5), std::pow(0.5, 2.2), 1e-12);
    EXPECT_NEAR(transcoding(GammaCurve::power_law(1.5), GammaCurve::power_law(2.0)).encode(0.5), std::pow(0.5, 0.75),
                1e-12);
    // A power law to sRGB decodes, then encodes; the reverse direction takes sRGB literals into the working gamma.
    const GammaTranscoding t = transcoding(GammaCurve::power_law(2.2), srgb);
    EXPECT_NEAR(t.encode(0.5), srgb.encode(std::pow(0.5, 2.2)), 1e-12);
    EXPECT_NEAR(t.decode(0.5), std::pow(srgb.decode(0.5), 1 / 2.2), 1e-12);
    EXPECT_NEAR(t.encode(t.decode(0.3)), 0.3, 1e-12);
}

// The 8-bit values POV-Ray 3.7.0.10 wrote for flat colours lit by ambient 1 alone (rendered with povray).
TEST(GammaEncode8, MatchesPovRaysPngValues) {
    using render::encode8;
    const GammaCurve srgb = GammaCurve::srgb();
    const auto assumed = [&](double g) { return transcoding(GammaCurve::power_law(g), srgb); };
    EXPECT_EQ(encode8(assumed(1.0), 0.25f), 137);
    EXPECT_EQ(encode8(assumed(1.0), 0.02f), 39);
    EXPECT_EQ(encode8(assumed(2.2), 0.25f), 61);
    EXPECT_EQ(encode8(assumed(2.2), 0.75f), 193);
    EXPECT_EQ(encode8(assumed(2.2), 0.02f), 1);
    EXPECT_EQ(encode8(assumed(1.5), 0.25f), 99);
    EXPECT_EQ(encode8(assumed(1.5), 0.1f), 50);
    // No gamma handling (a 3.6 scene): the display gamma on both sides writes the values as they are.
    EXPECT_EQ(encode8(transcoding(srgb, srgb), 0.9f), 230);
    EXPECT_EQ(encode8(transcoding(srgb, srgb), 0.1f), 26);
    // File_Gamma=1.0 with assumed_gamma 2.2, and File_Gamma=2.2 with assumed_gamma 1.
    EXPECT_EQ(encode8(transcoding(GammaCurve::power_law(2.2), GammaCurve::neutral()), 0.5f), 55);
    EXPECT_EQ(encode8(transcoding(GammaCurve::neutral(), GammaCurve::power_law(2.2)), 0.25f), 136);
    EXPECT_EQ(encode8(assumed(2.2), 1.5f), 255);
    EXPECT_EQ(encode8(assumed(2.2), -1.0f), 0);
    EXPECT_EQ(encode8(assumed(2.2), std::nanf("")), 0);
}

TEST(OutputGamma, ThreeSixScenesUseTheDisplayGammaOnBothSides) {
    scene::GlobalSettings global;
    global.assumed_gamma = GammaCurve::power_law(2.2);
    const GammaCurve file = GammaCurve::power_law(1.8), display = GammaCurve::power_law(1.6);
    const render::OutputGamma on = render::output_gamma(global, file, display);
    EXPECT_EQ(on.working, global.assumed_gamma);
    EXPECT_EQ(on.file, file);
    global.gamma_handling = false;
    const render::OutputGamma off = render::output_gamma(global, file, display);
    EXPECT_EQ(off.working, display);
    EXPECT_EQ(off.file, display);
}

TEST(OutputGamma, AntialiasingComparesDecodedValues) {
    EXPECT_DOUBLE_EQ(render::antialias_gamma_on_working_values(2.5, GammaCurve::neutral()), 2.5);
    EXPECT_DOUBLE_EQ(render::antialias_gamma_on_working_values(2.5, GammaCurve::power_law(2.0)), 1.25);
}

}  // namespace
}  // namespace wardray
