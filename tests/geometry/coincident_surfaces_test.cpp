// Tests of geometry/coincident_surfaces: which surfaces lying on one another are reported, and which are not.
#include <gtest/gtest.h>

#include <string>

#include "geometry/coincident_surfaces.h"
#include "parser/parser.h"

namespace wardray::geometry {
namespace {

// How many pairs of places the scene text has with coincident surfaces that can change the picture.
std::size_t pairs_in(const std::string& text) {
    parser::ParseOptions options;
    const parser::ParseResult r = parser::parse_string(text, "c.pov", options);
    EXPECT_TRUE(r.ok()) << text;
    if (!r.ok()) return 0;
    std::size_t total = 0;
    find_coincident_surfaces(*r.scene, 10, &total);
    return total;
}

TEST(CoincidentSurfaces, FacesOnOnePlaneWithDifferentTexturesAreFound) {
    // A box's top on a floor plane's surface, seen from above: POV-Ray's speckle of board and square.
    EXPECT_EQ(pairs_in("plane { y, 0 pigment { rgb 1 } }\n"
                       "box { <0, -1, 0>, <1, 0, 1> pigment { rgb x } }\n"),
              1u);
    // Moved by a small amount, or with the same texture, there is nothing to choose between.
    EXPECT_EQ(pairs_in("plane { y, 0 pigment { rgb 1 } }\n"
                       "box { <0, -1, 0>, <1, -0.001, 1> pigment { rgb x } }\n"),
              0u);
    EXPECT_EQ(pairs_in("#declare T = texture { pigment { rgb x } }\n"
                       "plane { y, 0 texture { T } }\nbox { <0, -1, 0>, <1, 0, 1> texture { T } }\n"),
              0u);
    // After transforms that round differently: a box placed by rotation and translation.
    EXPECT_EQ(pairs_in("plane { y, 0.3 pigment { rgb 1 } }\n"
                       "box { <0, -1, 0>, <1, 0, 1> rotate 90*y translate 0.1*y translate 0.2*y pigment { rgb x } }\n"),
              1u);
}

TEST(CoincidentSurfaces, TouchingOpaqueSolidsHideTheirContact) {
    // A box resting on the floor: opposite faces, both opaque, nothing to see.
    EXPECT_EQ(pairs_in("plane { y, 0 pigment { rgb 1 } }\nbox { <0, 0, 0>, <1, 1, 1> pigment { rgb x } }\n"), 0u);
    // A clear box on the floor: a ray through it meets its bottom and the floor at one distance.
    EXPECT_EQ(pairs_in("plane { y, 0 pigment { rgb 1 } }\n"
                       "box { <0, 0, 0>, <1, 1, 1> pigment { rgbf <1, 1, 1, 0.9> } }\n"),
              1u);
    // Side by side, faces that only share an edge.
    EXPECT_EQ(pairs_in("box { <0, 0, 0>, <1, 1, 1> pigment { rgb x } }\nbox { <1, 0, 0>, <2, 1, 1> pigment { rgb y } }\n"),
              0u);
}

TEST(CoincidentSurfaces, ACutterFlushWithTheFaceItCutsIsFound) {
    // The classic hole: the cylinder ends exactly in the box's faces.
    EXPECT_EQ(pairs_in("difference { box { -1, 1 } cylinder { -y, y, 0.5 } pigment { rgb 1 } }\n"), 1u);
    EXPECT_EQ(pairs_in("difference { box { -1, 1 } cylinder { -1.01*y, 1.01*y, 0.5 } pigment { rgb 1 } }\n"), 0u);
}

TEST(CoincidentSurfaces, ClippedPartsCountOnlyWhereTheyAreKept) {
    // Mitred rails: the planes coincide, but each keeps only its own side of the mitre.
    EXPECT_EQ(pairs_in("#declare Rail = intersection { box { <-10, 0, -1>, <10, 1, 1> }\n"
                       "  plane { -x, 0 rotate 45*y translate -9*x } plane { x, 0 rotate -45*y translate 9*x }\n"
                       "  translate -9*z pigment { wood } }\n"
                       "union { object { Rail } object { Rail rotate 90*y } object { Rail rotate 180*y }\n"
                       "  object { Rail rotate 270*y } }\n"),
              0u);
    // Two planes clipped to boxes that do not overlap.
    EXPECT_EQ(pairs_in("plane { z, 0 clipped_by { box { -2, 2 } } pigment { rgb x } translate 10*x }\n"
                       "plane { z, 0 clipped_by { box { -2, 2 } } pigment { rgb y } }\n"),
              0u);
    EXPECT_EQ(pairs_in("plane { z, 0 clipped_by { box { -2, 2 } } pigment { rgb x } translate 1*x }\n"
                       "plane { z, 0 clipped_by { box { -2, 2 } } pigment { rgb y } }\n"),
              1u);
}

TEST(CoincidentSurfaces, RoundSurfacesAndDiscs) {
    EXPECT_EQ(pairs_in("sphere { <1, 1, 0>, 0.3 pigment { rgb x } }\nsphere { <1, 1, 0>, 0.3 pigment { rgb y } }\n"),
              1u);
    EXPECT_EQ(pairs_in("sphere { <1, 1, 0>, 0.3 pigment { rgb x } }\nsphere { <1, 1, 0>, 0.31 pigment { rgb y } }\n"),
              0u);
    // Two pencils: one cylinder inside the other's length, the same radius.
    EXPECT_EQ(pairs_in("cylinder { 0, 30*z, 0.5 pigment { rgb x } }\ncylinder { 0, 32*z, 0.5 pigment { rgb y } }\n"),
              1u);
    // Discs whose rims only touch do not overlap.
    EXPECT_EQ(pairs_in("disc { 0, y, 1 pigment { rgb x } }\ndisc { 2*x, y, 1 pigment { rgb y } }\n"), 0u);
    EXPECT_EQ(pairs_in("disc { 0, y, 1 pigment { rgb x } }\ndisc { 1.5*x, -y, 1 pigment { rgb y } }\n"), 1u);
}

TEST(CoincidentSurfaces, WarningsNameBothPlaces) {
    parser::ParseOptions options;
    const parser::ParseResult r = parser::parse_string(
        "plane { y, 0 pigment { rgb 1 } }\nbox { <0, -1, 0>, <1, 0, 1> pigment { rgb x } }\n", "c.pov", options);
    ASSERT_TRUE(r.ok());
    const auto warnings = coincident_surface_warnings(*r.scene);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_EQ(warnings[0].severity, Severity::Warning);
    EXPECT_EQ(warnings[0].loc.line, 1u);
    EXPECT_NE(warnings[0].message.find("the box at c.pov:2:1"), std::string::npos) << warnings[0].message;
}

}  // namespace
}  // namespace wardray::geometry
