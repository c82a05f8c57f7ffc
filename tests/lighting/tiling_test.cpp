// The tiling pattern against POV-Ray 3.7: values at chosen points of tilings 1 to 27, measured from POV-Ray's own
// renders, and the parser's reading of the tiling number.
#include <gtest/gtest.h>

#include <string>

#include "parser/parse.h"
#include "texture/pigment.h"
#include "texture/tiling.h"

namespace wardray::texture {
namespace {

struct TilingCase {
    int type;
    double x, z;
    double expected;  ///< POV-Ray's value, a 16-bit level
};

// POV-Ray 3.7.0.10, one pixel of `plane { y, 0 pigment { tiling N color_map { [0 rgb 0] [1 rgb 1] } } finish {
// ambient 1 diffuse 0 } }` seen straight down through an orthographic camera centred on (x, z), 1e-6 wide:
// `povray +W1 +H1 -A +FN16 File_Gamma=1.0`, the PNG's 16-bit level.
const TilingCase kCases[] = {
    {1, 0.3, 0.2, 39321 / 65535.0},     {2, 0.7, 1.1, 21960 / 65535.0},    {3, 0.25, 0.35, 28056 / 65535.0},
    {4, 0.6, 0.9, 60393 / 65535.0},     {5, 0.45, 0.3, 9752 / 65535.0},    {5, -1.2, 2.05, 42972 / 65535.0},
    {6, 1.3, 2.6, 45875 / 65535.0},     {7, 1.0, 0.4, 51962 / 65535.0},    {8, 0.3, 1.5, 21103 / 65535.0},
    {9, 1.2, 0.3, 20089 / 65535.0},     {11, 1.4, 1.7, 8738 / 65535.0},    {13, 0.9, 0.35, 22065 / 65535.0},
    {14, -0.9, 0.35, 26346 / 65535.0},  {15, 2.2, 3.7, 52428 / 65535.0},   {16, 1.9, 0.8, 56411 / 65535.0},
    {17, 1.9, 0.8, 60973 / 65535.0},    {18, 2.5, 0.7, 13107 / 65535.0},   {19, 3.3, 1.2, 43690 / 65535.0},
    {20, 3.3, 1.2, 21374 / 65535.0},    {21, 0.8, 0.5, 43690 / 65535.0},   {22, 1.0, 2.6, 43690 / 65535.0},
    {23, 2.2, 1.3, 46575 / 65535.0},    {24, 2.2, 1.3, 54159 / 65535.0},   {25, 1.7, 0.6, 30006 / 65535.0},
    {26, 0.9, -0.5, 56854 / 65535.0},   {27, 2.3, 1.1, 61326 / 65535.0},
};

scene::Pigment tiling_pigment(const std::string& body) {
    parser::ParseOptions options;
    const parser::ParseResult r = parser::parse_string(
        "global_settings { assumed_gamma 1 }\nplane { y, 0 pigment { " + body + " } }\n", "test.pov", options);
    EXPECT_TRUE(r.ok() && r.scene && r.scene->objects.size() == 1u);
    for (const auto& d : r.diagnostics) ADD_FAILURE() << d.message;
    return r.ok() ? r.scene->objects[0].texture->pigment : scene::Pigment{};
}

TEST(Tiling, ValuesMatchPovRaysRenders) {
    for (const TilingCase& c : kCases) {
        SCOPED_TRACE("tiling " + std::to_string(c.type) + " at " + std::to_string(c.x) + ", " + std::to_string(c.z));
        const scene::Pigment p =
            tiling_pigment("tiling " + std::to_string(c.type) + " color_map { [0 rgb 0] [1 rgb 1] }");
        ASSERT_EQ(p.pattern.type, scene::Pattern::Type::Tiling);
        // One 16-bit level, and POV-Ray's single-precision colours.
        EXPECT_NEAR(evaluate_pigment(p, {c.x, 0.0, c.z}, 2).r, c.expected, 1.0 / 65535.0);
    }
}

TEST(Tiling, OnlyXAndZCountAndEachTilingRepeats) {
    // The square tiling repeats every unit, the hexagons every 3 along x and sqrt(3) along z.
    EXPECT_DOUBLE_EQ(tiling_value(1, 0.3, 0.2), 0.6);
    EXPECT_NEAR(tiling_value(1, 7.3, -4.8), 0.6, 1e-12);
    EXPECT_NEAR(tiling_value(2, 0.7 + 3.0, 1.1 - 1.7320508075688772), tiling_value(2, 0.7, 1.1), 1e-12);
    const scene::Pigment p = tiling_pigment("tiling 9 color_map { [0 rgb 0] [1 rgb 1] }");
    EXPECT_EQ(evaluate_pigment(p, {1.2, 5.0, 0.3}, 2).r, evaluate_pigment(p, {1.2, -3.0, 0.3}, 2).r);
}

TEST(Tiling, NumberIsAnUnsignedCharFromOneTo27) {
    // POV-Ray compat: the number is cut to an unsigned char, then checked.
    EXPECT_EQ(tiling_pigment("tiling 261").pattern.params->tiling_type, 5);
    EXPECT_EQ(tiling_pigment("tiling 27.9").pattern.params->tiling_type, 27);
    for (const char* bad : {"tiling 0", "tiling 28", "tiling -1"}) {
        SCOPED_TRACE(bad);
        parser::ParseOptions options;
        const parser::ParseResult r =
            parser::parse_string(std::string("plane { y, 0 pigment { ") + bad + " } }\n", "test.pov", options);
        EXPECT_FALSE(r.ok());
    }
}

}  // namespace
}  // namespace wardray::texture
