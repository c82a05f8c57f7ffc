// Tests of texture/pattern_wraps: which textures that jump exactly on a surface are reported, and which are not.
#include <gtest/gtest.h>

#include <string>

#include "core/diagnostics.h"
#include "parser/parse.h"
#include "texture/pattern_wraps.h"

namespace wardray::texture {
namespace {

// A camera above, in front and to the left: it sees the tops, fronts and left sides of boxes about the origin.
const std::string kCamera = "camera { location <-3, 4, -5> look_at 0 }\n";

// The surfaces of the scene text (seen by kCamera unless it has a camera) on which their texture jumps.
std::vector<PatternWrap> wraps_in(const std::string& text, std::size_t* total = nullptr) {
    parser::ParseOptions options;
    const std::string camera = text.find("camera") == std::string::npos ? kCamera : "";
    const parser::ParseResult r = parser::parse_string(camera + text, "w.pov", options);
    EXPECT_TRUE(r.ok()) << text;
    if (!r.ok()) return {};
    return find_pattern_wraps(*r.scene, 10, total);
}

std::size_t count_in(const std::string& text) { return wraps_in(text).size(); }

const std::string kOnionMap = "color_map { [0 rgb <1, 0.5, 0>] [0.95 rgb <1, 0.5, 0>] [1 rgb <0.3, 0.6, 0>] }";

TEST(PatternWraps, AnOnionWrappingOnASphereIsFound) {
    // The melon: the sphere r = 1 is where the onion goes from 1 back to 0, rind colour to flesh colour.
    const auto found = wraps_in("sphere { 0, 1 pigment { onion " + kOnionMap + " } }\n");
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].part, "pigment");
    EXPECT_EQ(found[0].pattern, "onion");
    EXPECT_EQ(found[0].surface, "sphere");
    EXPECT_EQ(found[0].object.line, 2u);  // after the camera
    // Moved and turned with its texture, and at radius 2 (the next wrap), it still lies on a wrap.
    EXPECT_EQ(count_in("sphere { 0, 1 pigment { onion " + kOnionMap + " } rotate 30*y translate <2, 0, 2> }\n"), 1u);
    EXPECT_EQ(count_in("sphere { 0, 2 pigment { onion " + kOnionMap + " } }\n"), 1u);
    EXPECT_EQ(count_in("sphere { 0, 1 pigment { onion " + kOnionMap + " } scale 3 }\n"), 1u);
}

TEST(PatternWraps, NearMissesAreNotFound) {
    // The scene's own fix: the onion scaled by a small amount; or the sphere a little smaller or off centre.
    EXPECT_EQ(count_in("sphere { 0, 1 pigment { onion " + kOnionMap + " scale 1.0001 } }\n"), 0u);
    EXPECT_EQ(count_in("sphere { 0, 0.9999 pigment { onion " + kOnionMap + " } }\n"), 0u);
    EXPECT_EQ(count_in("sphere { 0.001*x, 1 pigment { onion " + kOnionMap + " } }\n"), 0u);
    // A texture placed after the object is scaled does not scale with it.
    EXPECT_EQ(count_in("sphere { 0, 1 scale 1.5 pigment { onion " + kOnionMap + " } }\n"), 0u);
}

TEST(PatternWraps, AGradientWrappingOnAFlatFaceIsFound) {
    const std::string map = "color_map { [0 rgb 0] [1 rgb 1] }";
    const auto found = wraps_in("box { <0, 0, 0>, <1, 1, 1> pigment { gradient y " + map + " } }\n");
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].pattern, "gradient");
    EXPECT_EQ(found[0].surface, "flat face");
    EXPECT_EQ(count_in("plane { y, 2 pigment { gradient y " + map + " } }\n"), 1u);
    // A face between the wraps, or a gradient across the face (its wrap cuts the face along a line only).
    EXPECT_EQ(count_in("box { <0, 0.25, 0>, <1, 0.75, 1> pigment { gradient y " + map + " } }\n"), 0u);
    EXPECT_EQ(count_in("box { <0.25, 0.25, 0.25>, <1.75, 0.75, 0.75> pigment { gradient x " + map + " } }\n"), 0u);
    // Scaled together with the object, the pattern's wraps stay on its faces.
    EXPECT_EQ(count_in("box { <0, 0.25, 0.25>, <1, 0.75, 0.75> pigment { gradient x " + map + " } scale <2.5, 1, 1> }\n"),
              1u);
}

TEST(PatternWraps, FacesTurnedAwayFromTheCameraAreNotFound) {
    // A box on the floor whose gradient wraps on its bottom face: hidden from a camera above, seen from below.
    const std::string box = "box { <0, 0, 0>, <1, 0.5, 1> pigment { gradient y color_map { [0 rgb 0] [1 rgb 1] } } }\n";
    EXPECT_EQ(count_in(box), 0u);
    EXPECT_EQ(count_in("camera { location <-3, -4, -5> look_at 0 }\n" + box), 1u);
    EXPECT_EQ(count_in("camera { orthographic location <0, -4, 0> look_at 0 }\n" + box), 1u);
    EXPECT_EQ(count_in("camera { orthographic location <0, 4, -1> look_at 0 }\n" + box), 0u);
}

TEST(PatternWraps, AMapEqualAcrossTheWrapShowsNothing) {
    // The same colour at both ends of the map, or a wave that is continuous where the ramp wraps.
    EXPECT_EQ(count_in("sphere { 0, 1 pigment { onion color_map { [0 rgb 1] [0.5 rgb 0] [1 rgb 1] } } }\n"), 0u);
    EXPECT_EQ(count_in("sphere { 0, 1 pigment { onion triangle_wave " + kOnionMap + " } }\n"), 0u);
    EXPECT_EQ(count_in("sphere { 0, 1 pigment { onion sine_wave " + kOnionMap + " } }\n"), 0u);
    EXPECT_EQ(count_in("sphere { 0, 1 pigment { onion color_map { [0 rgb 1] [1 rgb 1] } } }\n"), 0u);
}

TEST(PatternWraps, PatternsPovRayGuardAreNotFound) {
    // POV-Ray's checker and cells add a small epsilon before they round down, so a face on their cell walls shows
    // one cell only.
    EXPECT_EQ(count_in("box { <-3, -1, -3>, <3, 0, 3> pigment { checker rgb 0, rgb 1 } }\n"), 0u);
    EXPECT_EQ(count_in("box { <-3, -1, -3>, <3, 0, 3> pigment { cells } }\n"), 0u);
}

TEST(PatternWraps, NormalsAndTextureMapsAreLookedAt) {
    // wineglass.pov's floor: quilted's normal flips across its cells' faces, though its value does not.
    const auto found = wraps_in("plane { y, 0 normal { quilted 0.45 control0 1 control1 1 scale <0.45, 1, 0.45> } }\n");
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].part, "normal");
    EXPECT_EQ(found[0].pattern, "quilted");
    EXPECT_EQ(count_in("plane { y, 0 pigment { quilted color_map { [0 rgb 0] [1 rgb 1] } } }\n"), 0u);
    const auto mapped = wraps_in("box { 0, 1 texture { gradient z texture_map { [0 pigment { rgb x }] "
                                 "[1 pigment { rgb y }] } } }\n");
    ASSERT_EQ(mapped.size(), 1u);
    EXPECT_EQ(mapped[0].part, "texture_map");
}

TEST(PatternWraps, TheWarningIsAtThePigmentAndNamesTheSurface) {
    parser::ParseOptions options;
    const parser::ParseResult r =
        parser::parse_string("camera { location <0, 0, -5> }\n#declare T = texture {\n  pigment { onion " + kOnionMap + " }\n}\n"
                             "sphere { 0, 1 texture { T } }\nsphere { 0, 2 texture { T } }\n",
                             "w.pov", options);
    ASSERT_TRUE(r.ok());
    const std::vector<Diagnostic> warnings = pattern_wrap_warnings(*r.scene, 1);
    ASSERT_EQ(warnings.size(), 2u);  // one surface, then the count of the rest
    EXPECT_EQ(warnings[0].loc.line, 3u);
    EXPECT_NE(warnings[0].message.find("sphere at w.pov:5:"), std::string::npos) << warnings[0].message;
    EXPECT_NE(warnings[0].message.find("POV-Ray shows either side at random"), std::string::npos);
    EXPECT_NE(warnings[1].message.find("1 more surfaces"), std::string::npos) << warnings[1].message;
}

}  // namespace
}  // namespace wardray::texture
