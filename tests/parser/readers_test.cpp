// Tests of the statement readers' building blocks: the keyword table they dispatch through and the scene builder.
#include <gtest/gtest.h>

#include <string>

#include "parser/keyword_table.h"
#include "parser/scene_builder.h"

namespace wardray::parser {
namespace {

TEST(KeywordTable, FindsEachKeywordAndNothingElse) {
    const KeywordTable<int> table = {{"sphere", 1}, {"box", 2}, {"sphere_sweep", 3}};
    ASSERT_NE(table.find("box"), nullptr);
    EXPECT_EQ(*table.find("box"), 2);
    ASSERT_NE(table.find("sphere"), nullptr);
    EXPECT_EQ(*table.find("sphere"), 1);
    ASSERT_NE(table.find("sphere_sweep"), nullptr);
    EXPECT_EQ(*table.find("sphere_sweep"), 3);
    EXPECT_EQ(table.find("spher"), nullptr);
    EXPECT_EQ(table.find("Sphere"), nullptr);
    EXPECT_EQ(table.find(""), nullptr);
}

TEST(KeywordTable, LooksUpAWordInsideALongerText) {
    // The readers look up token text in place: a view into the file's text, not a copy.
    const std::string text = "  camera {";
    const KeywordTable<int> table = {{"camera", 7}};
    const std::string_view word(text.data() + 2, 6);
    ASSERT_NE(table.find(word), nullptr);
    EXPECT_EQ(*table.find(word), 7);
    EXPECT_EQ(table.find(std::string_view(text.data() + 2, 5)), nullptr);
}

TEST(SceneBuilder, FinishHandsOverWhatWasPlaced) {
    SceneBuilder builder;
    builder.add_object(Object{});
    builder.add_light(Light{});
    builder.add_light(Light{});
    builder.set_background(Color{0.5, 0.25, 0.0});
    builder.add_fog(Fog{});
    builder.global().assumed_gamma = GammaCurve::power_law(2.2);
    builder.global().assumed_gamma_given = true;
    Diagnostic warning;
    warning.severity = Severity::Warning;
    warning.message = "careful";
    const Scene scene = builder.finish("a.pov", 3.6, {warning});
    EXPECT_EQ(scene.path, "a.pov");
    EXPECT_DOUBLE_EQ(scene.version, 3.6);
    EXPECT_EQ(scene.objects.size(), 1u);
    EXPECT_EQ(scene.lights.size(), 2u);
    EXPECT_EQ(scene.fogs.size(), 1u);
    EXPECT_FALSE(scene.sky_sphere.has_value());
    EXPECT_DOUBLE_EQ(scene.background.g, 0.25);
    EXPECT_EQ(scene.global.assumed_gamma, GammaCurve::power_law(2.2));
    EXPECT_TRUE(scene.global.assumed_gamma_given);
    ASSERT_EQ(scene.warnings.size(), 1u);
    EXPECT_EQ(scene.warnings[0].message, "careful");
}

TEST(SceneBuilder, ALaterCameraReplacesTheFirst) {
    SceneBuilder builder;
    Camera first;
    first.location = Vec3{1.0, 2.0, 3.0};
    Camera second;
    second.location = Vec3{4.0, 5.0, 6.0};
    builder.set_camera(first);
    builder.set_camera(second);
    const Scene scene = builder.finish("b.pov", 3.7, {});
    EXPECT_DOUBLE_EQ(scene.camera.location.x, 4.0);
    EXPECT_TRUE(scene.warnings.empty());
}

}  // namespace
}  // namespace wardray::parser
