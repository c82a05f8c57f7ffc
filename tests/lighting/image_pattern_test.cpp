// image_pattern against POV-Ray 3.7's image_pattern: the grey level of the image's stored values, the red channel
// with use_alpha (an image without alpha), 0 off a `once` image, and use_index still the grey level.
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "parser/parse.h"
#include "texture/pattern.h"

namespace wardray::texture {
namespace {

// A 3 x 1 image: red, green, blue, written with sRGB (as a PNG file is), which image_pattern does not decode.
std::shared_ptr<const scene::ImageData> rgb_strip(const std::filesystem::path&, bool& encoded, std::string&) {
    auto image = std::make_shared<scene::ImageData>();
    image->width = 3;
    image->height = 1;
    image->rgb = {1, 0, 0, 0, 0.5f, 0, 0, 0, 1};
    encoded = true;
    return image;
}

scene::Pattern image_pattern_of(const std::string& items) {
    parser::ParseOptions options;
    options.read_image = rgb_strip;
    const parser::ParseResult r = parser::parse_string(
        "global_settings { assumed_gamma 1 }\nsphere { 0, 1 pigment { image_pattern { png \"" WARDRAY_SOURCE_DIR
        "/scenes/default.pov\" " + items + " } } }",
        "test.pov", options);
    EXPECT_TRUE(r.ok());
    for (const auto& d : r.diagnostics) ADD_FAILURE() << d.message;
    if (!r.scene || r.scene->objects.empty()) return {};
    return r.scene->objects[0].texture.pigment.pattern;
}

TEST(ImagePattern, IsTheGreyLevelOfTheStoredTexel) {
    const scene::Pattern pat = image_pattern_of("");
    ASSERT_EQ(pat.type, scene::Pattern::Type::ImagePattern);
    EXPECT_EQ(pat.frequency, 0.0);
    // POV-Ray's greyscale 0.297 r + 0.589 g + 0.114 b of the values as stored (no gamma decoding).
    EXPECT_NEAR(pattern_value(pat, {0.1, 0.5, 0}, 2), 0.297, 1e-7);
    EXPECT_NEAR(pattern_value(pat, {0.5, 0.5, 0}, 2), 0.589 * 0.5, 1e-7);
    EXPECT_NEAR(pattern_value(pat, {0.9, 0.5, 0}, 2), 0.114, 1e-7);
    // The image repeats.
    EXPECT_NEAR(pattern_value(pat, {2.1, 7.5, 0}, 2), 0.297, 1e-7);
    // use_index takes the grey level too, as POV-Ray does.
    EXPECT_NEAR(pattern_value(image_pattern_of("use_index"), {0.9, 0.5, 0}, 2), 0.114, 1e-7);
}

TEST(ImagePattern, UseAlphaWithoutAlphaTakesRedAndOnceLeavesZero) {
    const scene::Pattern alpha = image_pattern_of("use_alpha");
    EXPECT_DOUBLE_EQ(pattern_value(alpha, {0.1, 0.5, 0}, 2), 1.0);
    EXPECT_DOUBLE_EQ(pattern_value(alpha, {0.5, 0.5, 0}, 2), 0.0);
    const scene::Pattern once = image_pattern_of("once");
    EXPECT_NEAR(pattern_value(once, {0.1, 0.5, 0}, 2), 0.297, 1e-7);
    EXPECT_EQ(pattern_value(once, {1.5, 0.5, 0}, 2), 0.0);
}

}  // namespace
}  // namespace wardray::texture
