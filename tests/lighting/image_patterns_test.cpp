// Issue 17's image and file patterns against POV-Ray 3.7: density_file (spiral.df3), waves and ripples with
// number_of_waves, palette images (use_index bump maps, material maps, filter/transmit per entry), tiles, the
// #default normal and spline components inside functions.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/constants.h"
#include "parser/parse.h"
#include "texture/image_map.h"
#include "texture/noise.h"
#include "texture/normal.h"
#include "texture/pattern.h"
#include "texture/pigment.h"

namespace wardray::texture {
namespace {

parser::ParseOptions options_with_povray_include() {
    parser::ParseOptions options;
    options.library_paths.push_back("/usr/share/povray-3.7/include");
    options.read_paths.push_back(WARDRAY_SOURCE_DIR "/scenes");  // the stand-in image files are read from there
    options.set_number_of_waves = [](int count) { set_number_of_waves(count); };
    return options;
}

scene::Scene parse(const std::string& text, parser::ParseOptions options = options_with_povray_include()) {
    const parser::ParseResult r = parser::parse_string(text, "test.pov", options);
    for (const auto& d : r.diagnostics) ADD_FAILURE() << d.message;
    EXPECT_TRUE(r.ok());
    return r.ok() ? *r.scene : scene::Scene{};
}

struct Case {
    const char* pigment;
    double expected[4];
};

// POV-Ray 3.7.0.10 with global_settings { number_of_waves 3 }: #debug vstr(3, eval_pigment(pigment { ... }, P),
// ",", 0, 12) at the four points below (grey, so one channel each). POV-Ray evaluates while parsing with its
// default 10 wave sources (the same values as with number_of_waves 10); the setting is the render's.
const Vec3 kPoints[4] = {{0.31, 0.52, 0.47}, {0.55, 0.43, 0.62}, {0.48, 0.61, 0.41}, {0.7, 0.2, 0.9}};
const Case kCases[] = {
    {"density_file df3 \"spiral.df3\" Ramp()", {0.509803950787, 0.737254917622, 0.831372559071, 0.0}},
    {"density_file df3 \"spiral.df3\" interpolate 1 Ramp()", {0.471960783005, 0.651274502277, 0.810882329941, 0.0}},
    {"density_file df3 \"spiral.df3\" interpolate 1 Ramp() scale 0.8 translate 0.1",
     {0.024264706299, 0.470680147409, 0.757291674614, 0.0}},
    {"ripples Ramp() frequency 3", {0.046278689057, 0.287090182304, 0.711666285992, 0.551770031452}},
    {"waves Ramp() frequency 2 phase 0.3", {0.976381897926, 0.161040380597, 0.190563723445, 0.312449604273}},
};

TEST(ImagePatterns, DensityFileAndParseTimeWavesMatchPovRay) {
    set_number_of_waves(3);  // a previous render's count must not leak into a parse
    for (const Case& c : kCases) {
        SCOPED_TRACE(c.pigment);
        const scene::Scene s = parse(
            "global_settings { assumed_gamma 1 number_of_waves 3 }\n#macro Ramp() color_map { [0 rgb 0] [1 rgb 1] } "
            "#end\nsphere { 0, 1 pigment { " + std::string(c.pigment) + " } }\n");
        ASSERT_EQ(s.objects.size(), 1u);
        EXPECT_EQ(s.global.number_of_waves, 3);
        for (int i = 0; i < 4; ++i)
            EXPECT_NEAR(evaluate_pigment(s.objects[0].texture->pigment, kPoints[i], 2).r, c.expected[i], 2e-6)
                << "point " << i;
    }
}

TEST(ImagePatterns, FewerWavesAreTheFirstOfPovRaysSources) {
    set_number_of_waves(10);
    const std::vector<WaveSource> ten = wave_sources();
    set_number_of_waves(3);
    ASSERT_EQ(wave_sources().size(), 3u);
    for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_EQ(wave_sources()[i].center, ten[i].center);
        EXPECT_EQ(wave_sources()[i].frequency, ten[i].frequency);
    }
    set_number_of_waves(10);
}

TEST(ImagePatterns, NumberOfWavesIsAtLeastOne) {
    parser::ParseOptions options = options_with_povray_include();
    const parser::ParseResult r = parser::parse_string("global_settings { number_of_waves 0 }", "test.pov", options);
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r.scene->global.number_of_waves, 1);
    ASSERT_FALSE(r.diagnostics.empty());
    EXPECT_NE(r.diagnostics.front().message.find("number_of_waves must be greater than 0"), std::string::npos);
    set_number_of_waves(10);
}

// A 3 x 1 palette image: indices 0, 1, 2 with grey levels 0, 0.5, 1 (rows from the top).
std::shared_ptr<scene::ImageData> palette_strip(const std::filesystem::path&, bool& encoded, std::string&) {
    auto image = std::make_shared<scene::ImageData>();
    image->width = 3;
    image->height = 1;
    image->rgb = {0, 0, 0, 0.5f, 0.5f, 0.5f, 1, 1, 1};
    image->index = {0, 1, 2};
    image->palette_size = 4;
    encoded = true;
    return image;
}

const std::string kAnyFile = "\"" WARDRAY_SOURCE_DIR "/scenes/default.pov\"";

parser::ParseOptions palette_options() {
    parser::ParseOptions options;
    options.read_image = palette_strip;
    options.read_paths.push_back(WARDRAY_SOURCE_DIR "/scenes");
    return options;
}

TEST(ImagePatterns, ImageMapFilterAndTransmitPerPaletteEntry) {
    const scene::Scene s = parse("global_settings { assumed_gamma 1 }\nsphere { 0, 1 pigment { image_map { png " +
                                     kAnyFile + " transmit all 0.3 filter 1, 0.6 transmit 2, 0.9 } } }",
                                 palette_options());
    const scene::Pigment& p = s.objects.at(0).texture->pigment;
    const Color left = evaluate_pigment(p, {0.1, 0.5, 0.0}, 2), middle = evaluate_pigment(p, {0.5, 0.5, 0.0}, 2),
                right = evaluate_pigment(p, {0.9, 0.5, 0.0}, 2);
    EXPECT_FLOAT_EQ(left.filter, 0.0f);
    EXPECT_FLOAT_EQ(left.transmit, 0.3f);
    EXPECT_FLOAT_EQ(middle.filter, 0.6f);
    EXPECT_FLOAT_EQ(middle.transmit, 0.3f);
    EXPECT_FLOAT_EQ(right.transmit, 0.9f);
}

TEST(ImagePatterns, FilterOfAPaletteEntryOutOfRangeIsAnError) {
    parser::ParseOptions options = palette_options();
    const parser::ParseResult r = parser::parse_string(
        "sphere { 0, 1 pigment { image_map { png " + kAnyFile + " filter 4, 0.5 } } }", "test.pov", options);
    EXPECT_FALSE(r.ok());
}

TEST(ImagePatterns, MaterialMapPicksTheTextureOfTheIndex) {
    const scene::Scene s = parse("global_settings { assumed_gamma 1 }\nsphere { 0, 1 texture { material_map { png " + kAnyFile +
                                     " texture { pigment { rgb 1 } } texture { pigment { rgb 2 } } } scale 2 } }",
                                 palette_options());
    const scene::Texture& t = s.objects.at(0).texture;
    ASSERT_TRUE(t.material_map.has_value());
    ASSERT_EQ(t.texture_map.size(), 2u);
    const auto index_at = [&](double x) {
        return material_map_index(*t.material_map, warp_point(t.map_pattern, {x, 1.0, 0.0}), 2);
    };
    EXPECT_EQ(index_at(0.2), 0);
    EXPECT_EQ(index_at(1.0), 1);
    // Index 2 equals the count of two materials: POV-Ray's list walk stops at the last one.
    EXPECT_EQ(index_at(1.8), 1);
}

TEST(ImagePatterns, BumpMapTiltsTowardsLowerTexels) {
    // The heights rise to the right: POV-Ray's bump normal tilts towards -x, more with use_index (heights 0, 1, 2
    // times bump_size rather than grey levels).
    const scene::Scene s = parse("global_settings { assumed_gamma 1 }\n"
                                 "sphere { 0, 1 normal { bump_map { png " + kAnyFile + " bump_size 0.5 } } }\n"
                                 "sphere { 0, 1 normal { bump_map { png " + kAnyFile + " bump_size 0.5 use_index } } }",
                                 palette_options());
    const Vec3 n{0.0, 0.0, -1.0};
    const Vec3 grey = perturb_normal(s.objects.at(0).texture->normal, n, {0.5, 0.5, 0.0}, 2);
    const Vec3 index = perturb_normal(s.objects.at(1).texture->normal, n, {0.5, 0.5, 0.0}, 2);
    EXPECT_NEAR(length(grey), 1.0, 1e-9);
    EXPECT_LT(grey.x, 0.0);
    EXPECT_LT(index.x, grey.x);
    // The plane through (0, h1, 0), (-1, h2, 1), (1, h3, 1) for the middle texel, whose neighbours below wrap to
    // the row itself: h2 = h1 - 0.5 * 0.5 and h3 = h1 + 0.5 * 0.5, so the bump normal is (-0.5, 2, 0) normalised.
    const Vec3 expected_bump = normalize(Vec3{-0.5, 2.0, 0.0});
    // POV-Ray's frame around the normal: x' = n × y, y' = n, z' = x' × y'.
    const Vec3 xp = normalize(cross(n, Vec3{0, 1, 0})), zp = normalize(cross(xp, n));
    const Vec3 expected = xp * expected_bump.x + n * expected_bump.y - zp * expected_bump.z;
    EXPECT_NEAR(grey.x, expected.x, 1e-6);
    EXPECT_NEAR(grey.y, expected.y, 1e-6);
    EXPECT_NEAR(grey.z, expected.z, 1e-6);
}

TEST(ImagePatterns, TilesIsACheckerOfTwoTexturesTheFirstAtOne) {
    const scene::Scene s = parse("global_settings { assumed_gamma 1 }\nsphere { 0, 1 texture { tiles { texture { pigment { rgb 1 } } tile2 "
                                 "texture { pigment { rgb 0.5 } } texture { pigment { rgbt 1 } } } scale 2 } }");
    const scene::Texture& t = s.objects.at(0).texture;
    EXPECT_EQ(t.map_pattern.type, scene::Pattern::Type::Checker);
    ASSERT_EQ(t.texture_map.size(), 2u);
    EXPECT_EQ(t.texture_map[1].value, 1.0);
    EXPECT_EQ(t.texture_map[1].texture.pigment.color.r, 1.0);
    EXPECT_EQ(t.texture_map[0].texture.pigment.color.r, 0.5);
    // Textures in a row are layers.
    EXPECT_EQ(t.texture_map[0].texture.layers.size(), 1u);
    EXPECT_EQ(pattern_value(t.map_pattern, warp_point(t.map_pattern, {2.5, 0.5, 0.5}), 2), 1.0);
}

TEST(ImagePatterns, DefaultNormalStartsEveryNormal) {
    const scene::Scene s = parse("global_settings { assumed_gamma 1 }\n#default { normal { bumps 0.3 scale 0.5 } }\nsphere { 0, 1 }\n"
                                 "sphere { 0, 1 normal { bump_size 0.7 } }\n"
                                 "sphere { 0, 1 normal { gradient x normal_map { [0 bump_size 0.2] [1 dents] } } }");
    EXPECT_EQ(s.objects.at(0).texture->normal.pattern.type, scene::Pattern::Type::Bumps);
    EXPECT_FLOAT_EQ(s.objects.at(0).texture->normal.amount, 0.3f);
    EXPECT_EQ(s.objects.at(1).texture->normal.pattern.type, scene::Pattern::Type::Bumps);
    EXPECT_FLOAT_EQ(s.objects.at(1).texture->normal.amount, 0.7f);
    const scene::Normal& mapped = s.objects.at(2).texture->normal;
    ASSERT_EQ(mapped.normal_map.size(), 2u);
    EXPECT_EQ(mapped.normal_map[0].normal.pattern.type, scene::Pattern::Type::Bumps);
    EXPECT_FLOAT_EQ(mapped.normal_map[1].normal.amount, 0.3f);
}

TEST(ImagePatterns, SplineComponentsInsideFunctions) {
    // A spline called inside a function with a dot item gives that component (language/splinefunction.pov).
    const parser::ParseResult r = parser::parse_string(
        "global_settings { assumed_gamma 1 }\n#declare S = function { spline { linear_spline 0, <0, 1, 5>, 1, <1, 3, 7> } }\n"
        "#declare F = function { S(x).y + S(x * 2).z }\n"
        "#if (abs(F(0.25, 0, 0) - (1.5 + 6)) > 1e-12) #error \"wrong spline component\" #end\n",
        "test.pov", options_with_povray_include());
    EXPECT_TRUE(r.ok());
    for (const auto& d : r.diagnostics) ADD_FAILURE() << d.message;
}

}  // namespace
}  // namespace wardray::texture
