// +Q quality levels against POV-Ray at the same level: each level leaves out what POV-Ray 3.7's leaves out.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "process.h"
#include "render/film.h"
#include "render/image_metrics.h"

namespace wardray::test {
namespace {

namespace fs = std::filesystem;

// Something for every level to drop: an area light, a second light's shadows, a reflective checkered floor, a
// bumped sphere, a refracting glass sphere, a layered texture and fog.
const char* kQualityScene = R"(#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -5> look_at <0, 0.6, 0> }
light_source { <3, 5, -4> color rgb 1 area_light <1, 0, 0>, <0, 0, 1>, 4, 4 adaptive 1 }
light_source { <-4, 3, -2> color rgb 0.3 }
plane { y, 0 pigment { checker color rgb 0.9 color rgb 0.3 } finish { reflection 0.3 } }
sphere { <-1.2, 0.7, 0>, 0.7 pigment { color rgb <1, 0.3, 0.2> } normal { bumps 0.6 scale 0.15 } finish { phong 0.8 } }
sphere { <0.4, 0.7, 0.5>, 0.7 pigment { color rgbf <0.7, 0.9, 1, 0.8> } interior { ior 1.4 } finish { reflection 0.1 } }
box { <1.2, 0, -1>, <2.2, 1, 0> texture { pigment { color rgb <0.2, 0.6, 0.3> } }
      texture { pigment { color rgbt <0.9, 0.9, 0.2, 0.6> } } }
fog { distance 30 color rgb <0.5, 0.6, 0.7> }
)";

class Quality : public ::testing::TestWithParam<int> {};

TEST_P(Quality, MatchesPovRayAtTheSameLevel) {
    const int q = GetParam();
    const fs::path dir = fs::path(WARDRAY_TEST_OUTPUT_DIR) / "quality" / std::to_string(q);
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::ofstream(dir / "scene.pov") << kQualityScene;
    const std::string common = " +FH +W160 +H120 -A +WT1 +Q" + std::to_string(q);
    ASSERT_EQ(run_command("povray +Iscene.pov +Opovray.hdr -D -V" + common, dir.string()).exit_status, 0);
    ASSERT_EQ(run_command("povray +Iscene.pov +Opovray9.hdr -D -V +FH +W160 +H120 -A +WT1 +Q9", dir.string())
                  .exit_status,
              0);
    const auto ours = run_command(shell_quote(WARDRAY_BINARY) + " scene.pov -o wardray.hdr" + common, dir.string());
    ASSERT_EQ(ours.exit_status, 0) << ours.output;
    std::string error;
    const auto reference = render::read_image(dir / "povray.hdr", error);
    const auto full = render::read_image(dir / "povray9.hdr", error);
    const auto image = render::read_image(dir / "wardray.hdr", error);
    ASSERT_TRUE(reference && full && image) << error;
    // The level changes the picture (so the comparison below tests the level, not the full render)...
    const auto level_effect = render::compare_images(*reference, *full);
    ASSERT_TRUE(level_effect);
    EXPECT_GT(level_effect->rrmse, 0.05);
    // ...and wardray's picture at that level is POV-Ray's: direct light only, so within 0.5 % rRMSE.
    const auto c = render::compare_images(*image, *reference);
    ASSERT_TRUE(c);
    EXPECT_LT(c->rrmse, 0.005);
    EXPECT_LT(c->bad_pixel_fraction, 0.001);
    EXPECT_EQ(c->non_finite, 0u);
}

INSTANTIATE_TEST_SUITE_P(Levels, Quality, ::testing::Values(0, 3, 4, 5, 6, 8));

// quick_color: up to +Q5 POV-Ray shows it instead of the pigment, at every depth of a pigment map; from +Q6 the
// pigment. A declared pigment keeps its quick colour; the outer pigment of a map without one is evaluated.
const char* kQuickColorScene = R"(#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -6> look_at <0, 0.5, 0> angle 50 }
light_source { <-10, 20, -15> color rgb 1 }
plane { y, 0 pigment { checker rgb 1 rgb 0.2 quick_color rgb <0.3, 0.5, 0.3> } }
sphere { <-1.6, 1, 0>, 1 pigment { bozo color_map { [0 rgb <1, 0, 0>] [1 rgb <1, 1, 0>] } quick_colour rgb <0, 0, 1> } }
#declare P = pigment { rgb <0.9, 0.6, 0.2> quick_color rgb <0.2, 0.8, 0.9> }
sphere { <0.6, 1, 0>, 1 pigment { P } }
box { <1.8, 0, -0.8>, <3.2, 1.6, 0.8>
      pigment { gradient y pigment_map { [0 P] [1 rgb <1, 1, 1> quick_color rgbt <1, 0, 1, 0.5>] } } }
)";

class QuickColor : public ::testing::TestWithParam<int> {};

TEST_P(QuickColor, ShownUpToQualityFiveAsInPovRay) {
    const int q = GetParam();
    const fs::path dir = fs::path(WARDRAY_TEST_OUTPUT_DIR) / "quick_color" / std::to_string(q);
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::ofstream(dir / "scene.pov") << kQuickColorScene;
    const std::string common = " +FH +W160 +H120 -A +WT1 +Q" + std::to_string(q);
    ASSERT_EQ(run_command("povray +Iscene.pov +Opovray.hdr -D -V" + common, dir.string()).exit_status, 0);
    const auto ours = run_command(shell_quote(WARDRAY_BINARY) + " scene.pov -o wardray.hdr" + common, dir.string());
    ASSERT_EQ(ours.exit_status, 0) << ours.output;
    EXPECT_EQ(ours.output.find("warning"), std::string::npos) << ours.output;
    std::string error;
    const auto reference = render::read_image(dir / "povray.hdr", error);
    const auto image = render::read_image(dir / "wardray.hdr", error);
    ASSERT_TRUE(reference && image) << error;
    const auto c = render::compare_images(*image, *reference);
    ASSERT_TRUE(c);
    EXPECT_LT(c->rrmse, 0.005);
    EXPECT_LT(c->bad_pixel_fraction, 0.001);
    EXPECT_EQ(c->non_finite, 0u);
}

INSTANTIATE_TEST_SUITE_P(Levels, QuickColor, ::testing::Values(1, 3, 5, 6));

}  // namespace
}  // namespace wardray::test
