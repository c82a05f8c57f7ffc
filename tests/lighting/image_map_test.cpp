// image_map: texels placed, decoded and interpolated as POV-Ray 3.7's image maps do, on a 2 x 2 test image; and
// image_pattern's value from the same image as POV-Ray's image_pattern takes it.
#include <gtest/gtest.h>

#include <cmath>

#include "parser/parse.h"
#include "texture/pattern.h"
#include "texture/pigment.h"

namespace wardray::lighting {
namespace {

// Rows from the top: red-ish and green over blue and white, stored as 8-bit (encoded) values.
std::shared_ptr<scene::ImageData> two_by_two(const std::filesystem::path&, bool& encoded, std::string&) {
    auto image = std::make_shared<scene::ImageData>();
    image->width = 2;
    image->height = 2;
    image->rgb = {0.5f, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1};
    encoded = true;
    return image;
}

// The pigment `pigment { BLOCK { png "file" ITEMS } }` (an image_map, or an image_pattern) on the test image.
scene::Pigment image_pigment(const std::string& items, const std::string& block = "image_map") {
    parser::ParseOptions options;
    options.read_image = two_by_two;
    options.read_paths.push_back(WARDRAY_SOURCE_DIR "/scenes");  // the stand-in file is read from there
    // The file must exist for the search; the scene itself serves.
    const parser::ParseResult r = parser::parse_string(
        "global_settings { assumed_gamma 1 }\nsphere { 0, 1 pigment { " + block + " { png \"" WARDRAY_SOURCE_DIR
        "/scenes/default.pov\" " + items + " } } }",
        "test.pov", options);
    EXPECT_TRUE(r.ok());
    for (const auto& d : r.diagnostics) ADD_FAILURE() << d.message;
    return r.ok() ? r.scene->objects.at(0).texture->pigment : scene::Pigment{};
}

TEST(ImageMap, PlanarPlacesTheTopRowAtTheTopAndDecodesGamma) {
    const scene::Pigment p = image_pigment("gamma 2.2");
    const Color top_left = texture::evaluate_pigment(p, {0.25, 0.75, 0.0}, 2);
    EXPECT_NEAR(top_left.r, std::pow(0.5, 2.2), 1e-6);
    EXPECT_NEAR(top_left.g, 0.0, 1e-9);
    const Color bottom_right = texture::evaluate_pigment(p, {0.75, 0.25, 0.0}, 2);
    EXPECT_NEAR(bottom_right.b, 1.0, 1e-9);
    // It repeats: one unit to the right is the same texel.
    EXPECT_NEAR(texture::evaluate_pigment(p, {1.25, 0.75, 0.0}, 2).r, top_left.r, 1e-9);
}

TEST(ImageMap, WithoutGammaAnEightBitFileIsSrgb) {
    const scene::Pigment p = image_pigment("");
    EXPECT_NEAR(texture::evaluate_pigment(p, {0.25, 0.75, 0.0}, 2).r, GammaCurve::srgb().decode(0.5), 1e-6);
}

// The top-left texel's red (stored 0.5) of `pigment { image_map { TYPE "file" } }` in a scene that begins with
// `head` and says assumed_gamma 1.
double top_left_red(const std::string& head, const std::string& type) {
    parser::ParseOptions options;
    options.read_image = two_by_two;
    options.read_paths.push_back(WARDRAY_SOURCE_DIR "/scenes");
    const parser::ParseResult r = parser::parse_string(
        head + "global_settings { assumed_gamma 1 }\nsphere { 0, 1 pigment { image_map { " + type + " \"" +
            WARDRAY_SOURCE_DIR "/scenes/default.pov\" } } }",
        "test.pov", options);
    EXPECT_TRUE(r.ok());
    if (!r.ok()) return -1.0;
    return texture::evaluate_pigment(r.scene->objects.at(0).texture->pigment, {0.25, 0.75, 0.0}, 2).r;
}

TEST(ImageMap, AJpegInASceneWithoutVersionIsInTheWorkingGammaAsPovRay362Reads) {
    const double srgb = GammaCurve::srgb().decode(0.5);
    // POV-Ray reads a scene with no #version as 3.62's: an untagged 8-bit file is taken in the working gamma.
    EXPECT_NEAR(top_left_red("", "jpeg"), 0.5, 1e-6);
    EXPECT_NEAR(top_left_red("", "gif"), 0.5, 1e-6);
    EXPECT_NEAR(top_left_red("#version 3.6;\n", "jpeg"), 0.5, 1e-6);
    // With #version 3.7 it is sRGB, and a PNG (which may be tagged; POV-Ray honours its gAMA or sRGB) stays sRGB.
    EXPECT_NEAR(top_left_red("#version 3.7;\n", "jpeg"), srgb, 1e-6);
    EXPECT_NEAR(top_left_red("", "png"), srgb, 1e-6);
}

// Every byte value over 255 and a few that are not: the parser's table for byte values gives each exactly what
// decoding it alone gives.
std::shared_ptr<scene::ImageData> all_bytes(const std::filesystem::path&, bool& encoded, std::string&) {
    auto image = std::make_shared<scene::ImageData>();
    for (int k = 0; k < 256; ++k) image->rgb.push_back(static_cast<float>(k) * (1.0f / 255.0f));
    for (const float v : {0.3f, 1.0f / 3.0f, 0.5f, 1.5f, -0.25f, 0.999f}) image->rgb.push_back(v);
    image->rgb.resize(image->rgb.size() / 3 * 3);
    image->width = static_cast<int>(image->rgb.size() / 3);
    image->height = 1;
    encoded = true;
    return image;
}

TEST(ImageMap, ByteTexelsDecodeByTableAsEachAlone) {
    for (const std::string& gamma : {std::string(""), std::string("gamma 2.2"), std::string("gamma srgb")}) {
        parser::ParseOptions options;
        options.read_image = all_bytes;
        options.read_paths.push_back(WARDRAY_SOURCE_DIR "/scenes");
        const parser::ParseResult r = parser::parse_string(
            "global_settings { assumed_gamma 1 }\nsphere { 0, 1 pigment { image_map { png \"" WARDRAY_SOURCE_DIR
            "/scenes/default.pov\" " + gamma + " } } }",
            "test.pov", options);
        ASSERT_TRUE(r.ok());
        const auto& image = *r.scene->objects.at(0).texture->pigment.image_map->image;
        bool encoded = false;
        std::string error;
        const auto stored = all_bytes({}, encoded, error);
        const GammaCurve file = gamma == "gamma 2.2" ? GammaCurve::power_law(2.2) : GammaCurve::srgb();
        const GammaTranscoding to_working = transcoding(GammaCurve::power_law(1.0), file);
        ASSERT_EQ(image.rgb.size(), stored->rgb.size());
        for (std::size_t i = 0; i < image.rgb.size(); ++i)
            ASSERT_EQ(image.rgb[i], static_cast<float>(to_working.decode(stored->rgb[i]))) << gamma << " " << i;
    }
}

TEST(ImageMap, BilinearAtTheCentreAveragesTheFourTexels) {
    const scene::Pigment p = image_pigment("gamma 1.0 interpolate 2");
    const Color c = texture::evaluate_pigment(p, {0.5, 0.5, 0.0}, 2);
    EXPECT_NEAR(c.r, (0.5 + 0 + 0 + 1) / 4.0, 1e-6);
    EXPECT_NEAR(c.g, (0 + 1 + 0 + 1) / 4.0, 1e-6);
    EXPECT_NEAR(c.b, (0 + 0 + 1 + 1) / 4.0, 1e-6);
}

TEST(ImageMap, OnceIsClearOutsideAndFilterTransmitAllAdd) {
    const scene::Pigment p = image_pigment("once filter all 0.25 transmit all 0.5");
    const Color outside = texture::evaluate_pigment(p, {1.5, 0.5, 0.0}, 2);
    EXPECT_DOUBLE_EQ(outside.transmit, 1.0);
    const Color inside = texture::evaluate_pigment(p, {0.75, 0.75, 0.0}, 2);
    EXPECT_DOUBLE_EQ(inside.filter, 0.25);
    EXPECT_DOUBLE_EQ(inside.transmit, 0.5);
}

TEST(ImageMap, SphericalMapsLatitudeUp) {
    const scene::Pigment p = image_pigment("gamma 1.0 map_type 1");
    // 45 degrees of longitude is the left column; near the north pole the top row, near the south the bottom.
    EXPECT_NEAR(texture::evaluate_pigment(p, {0.1, 1.0, 0.1}, 2).r, 0.5, 1e-6);
    EXPECT_NEAR(texture::evaluate_pigment(p, {0.1, -1.0, 0.1}, 2).b, 1.0, 1e-6);
    EXPECT_NEAR(texture::evaluate_pigment(p, {0.1, -1.0, 0.1}, 2).r, 0.0, 1e-6);
}

TEST(ImagePattern, IsTheGreyLevelOfTheStoredTexel) {
    const scene::Pattern pat = image_pigment("", "image_pattern").pattern;
    ASSERT_EQ(pat.type, scene::Pattern::Type::ImagePattern);
    EXPECT_EQ(pat.params->frequency, 0.0);
    // POV-Ray's greyscale 0.297 r + 0.589 g + 0.114 b of the values as stored (no gamma decoding), clipped to 1.
    EXPECT_NEAR(texture::pattern_value(pat, {0.25, 0.75, 0}, 2), 0.297 * 0.5, 1e-7);
    EXPECT_NEAR(texture::pattern_value(pat, {0.75, 0.75, 0}, 2), 0.589, 1e-7);
    EXPECT_NEAR(texture::pattern_value(pat, {0.25, 0.25, 0}, 2), 0.114, 1e-7);
    EXPECT_DOUBLE_EQ(texture::pattern_value(pat, {0.75, 0.25, 0}, 2), 1.0);
    // The image repeats; use_index still takes the grey level, as POV-Ray's does.
    EXPECT_NEAR(texture::pattern_value(pat, {3.25, -0.75, 0}, 2), 0.114, 1e-7);
    const scene::Pattern index = image_pigment("use_index", "image_pattern").pattern;
    EXPECT_NEAR(texture::pattern_value(index, {0.75, 0.75, 0}, 2), 0.589, 1e-7);
}

TEST(ImagePattern, UseAlphaWithoutAlphaTakesRedAndOnceLeavesZero) {
    const scene::Pattern alpha = image_pigment("use_alpha", "image_pattern").pattern;
    EXPECT_NEAR(texture::pattern_value(alpha, {0.25, 0.75, 0}, 2), 0.5, 1e-7);
    EXPECT_EQ(texture::pattern_value(alpha, {0.75, 0.75, 0}, 2), 0.0);
    const scene::Pattern once = image_pigment("once", "image_pattern").pattern;
    EXPECT_NEAR(texture::pattern_value(once, {0.75, 0.75, 0}, 2), 0.589, 1e-7);
    EXPECT_EQ(texture::pattern_value(once, {1.5, 0.5, 0}, 2), 0.0);
}

// A 2 x 1 palette image whose entry 1 is 40 % opaque (a tRNS chunk): rows from the top, indices 0 and 1.
std::shared_ptr<scene::ImageData> palette_with_alpha(const std::filesystem::path&, bool& encoded, std::string&) {
    auto image = std::make_shared<scene::ImageData>();
    image->width = 2;
    image->height = 1;
    image->rgb = {1, 0, 0, 0, 0, 1};
    image->index = {0, 1};
    image->palette_size = 2;
    image->palette_alpha = {1.0f, 0.4f};
    image->has_alpha = true;
    encoded = true;
    return image;
}

TEST(ImageMap, PaletteAlphaIsEachEntrysTransmitWhichFilterLeaves) {
    parser::ParseOptions options;
    options.read_image = palette_with_alpha;
    options.read_paths.push_back(WARDRAY_SOURCE_DIR "/scenes");  // the stand-in file is read from there
    const parser::ParseResult r = parser::parse_string(
        "global_settings { assumed_gamma 1 }\nsphere { 0, 1 pigment { image_map { png \"" WARDRAY_SOURCE_DIR
        "/scenes/default.pov\" filter 1, 0.25 } } }\nsphere { 0, 1 pigment { image_pattern { png \"" WARDRAY_SOURCE_DIR
        "/scenes/default.pov\" use_alpha } } }",
        "test.pov", options);
    std::string diagnostics;
    for (const auto& d : r.diagnostics) diagnostics += format_diagnostic(d);
    ASSERT_TRUE(r.ok()) << diagnostics;
    EXPECT_TRUE(r.diagnostics.empty()) << diagnostics;  // the alpha is rendered: no warning
    const scene::Pigment& p = r.scene->objects.at(0).texture->pigment;
    const Color opaque = texture::evaluate_pigment(p, {0.25, 0.5, 0}, 2);
    const Color clear = texture::evaluate_pigment(p, {0.75, 0.5, 0}, 2);
    EXPECT_FLOAT_EQ(opaque.transmit, 0.0f);
    EXPECT_FLOAT_EQ(clear.transmit, 0.6f);
    EXPECT_FLOAT_EQ(clear.filter, 0.25f);
    // image_pattern's use_alpha takes the transmit of an image with alpha.
    const scene::Pattern& alpha = r.scene->objects.at(1).texture->pigment.pattern;
    EXPECT_NEAR(texture::pattern_value(alpha, {0.75, 0.5, 0}, 2), 0.6, 1e-7);
    EXPECT_EQ(texture::pattern_value(alpha, {0.25, 0.5, 0}, 2), 0.0);
}

}  // namespace
}  // namespace wardray::lighting
