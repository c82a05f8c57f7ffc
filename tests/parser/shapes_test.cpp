// Tests of the curved-outline shapes' statements: text (font search, POV-Ray's glyph layout), lathe, sor and
// spline prisms.
#include <algorithm>
#include <cmath>

#include "tests/parser/test_util.h"

namespace wardray::parser {
namespace {

using test::parse_fail;
using test::parse_ok;

// Smallest and largest x of a glyph's outline points in text space.
std::pair<double, double> x_range(const TextGlyph& g) {
    double lo = 1e300, hi = -1e300;
    for (const auto& contour : g.contours)
        for (const auto& p : contour) {
            lo = std::min(lo, p.x + g.offset.x);
            hi = std::max(hi, p.x + g.offset.x);
        }
    return {lo, hi};
}

TEST(Text, GlyphsFromTheLibraryFontLaidOutLikePovRay) {
    const Scene s = parse_ok(R"(
        text { ttf "timrom.ttf" "HIH", 0.5, 0 }
        text { ttf "timrom" "HIH" 0.5 <0.25, 0.1, 3> }
    )");
    ASSERT_EQ(s.objects.size(), 2u);
    const Text& plain = std::get<Text>(s.objects[0].shape);
    const Text& spaced = std::get<Text>(s.objects[1].shape);
    ASSERT_EQ(plain.glyphs.size(), 3u);
    EXPECT_DOUBLE_EQ(plain.thickness, 0.5);
    // The first glyph's left edge is at the origin; glyphs follow left to right without overlapping much.
    EXPECT_NEAR(x_range(plain.glyphs[0]).first, 0.0, 1e-12);
    EXPECT_GT(x_range(plain.glyphs[1]).first, x_range(plain.glyphs[0]).second);
    EXPECT_FALSE(plain.glyphs[0].contours.empty());
    // The same glyph (H) at both ends: the same outline, moved.
    EXPECT_EQ(plain.glyphs[0].contours.size(), plain.glyphs[2].contours.size());
    // POV-Ray compat: each character adds the offset to the pen after it; z is never applied.
    for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_NEAR(spaced.glyphs[i].offset.x - plain.glyphs[i].offset.x, 0.25 * i, 1e-12);
        EXPECT_NEAR(spaced.glyphs[i].offset.y - plain.glyphs[i].offset.y, 0.1 * i, 1e-12);
        EXPECT_DOUBLE_EQ(spaced.glyphs[i].offset.z, 0.0);
    }
    // POV-Ray compat: text is turned by 0.001° about each axis before its own transforms.
    const Vec3 p = s.objects[0].transform.point({1, 0, 0});
    EXPECT_NEAR(p.x, 1.0, 1e-9);
    EXPECT_GT(std::fabs(p.y) + std::fabs(p.z), 1e-6);
}

TEST(Text, SpaceHasNoOutlineButAdvances) {
    const Scene s = parse_ok(R"(text { ttf "cyrvetic.ttf" "A A", 1, 0 })");
    const Text& t = std::get<Text>(s.objects[0].shape);
    ASSERT_EQ(t.glyphs.size(), 3u);
    EXPECT_TRUE(t.glyphs[1].contours.empty());
    EXPECT_GT(x_range(t.glyphs[2]).first, x_range(t.glyphs[0]).second + 0.1);
}

TEST(Text, NonAsciiBytesAreSpacesUnlessCharsetUtf8) {
    const Scene ascii = parse_ok("text { ttf \"timrom.ttf\" \"a\xC3\xA9\", 1, 0 }");
    ASSERT_EQ(std::get<Text>(ascii.objects[0].shape).glyphs.size(), 3u);
    EXPECT_TRUE(std::get<Text>(ascii.objects[0].shape).glyphs[1].contours.empty());
    ASSERT_EQ(ascii.warnings.size(), 1u);
    EXPECT_NE(ascii.warnings[0].message.find("replaced by spaces"), std::string::npos);
    const Scene utf8 = parse_ok("global_settings { charset utf8 } text { ttf \"timrom.ttf\" \"a\xC3\xA9\", 1, 0 }");
    EXPECT_EQ(std::get<Text>(utf8.objects[0].shape).glyphs.size(), 2u);
}

TEST(Text, MissingFontIsAnErrorAtTheText) {
    const ParseResult r = parse_fail("text { ttf \"no_such_font.ttf\" \"x\", 1, 0 }");
    EXPECT_NE(test::all_diagnostics(r).find("cannot open font file 'no_such_font.ttf'"), std::string::npos)
        << test::all_diagnostics(r);
}

TEST(Lathe, SplineTypesAndPointChecks) {
    const Scene s = parse_ok(R"(
        lathe { 3, <0, 0>, <1, 0.5>, <0, 1> }
        lathe { bezier_spline 4, <0, 0>, <1, 0>, <1, 1>, <0, 1> sturm }
        lathe { cubic_spline 5 <-1, 0> <0, 0> <1, 1> <0, 2> <-1, 2> }
    )");
    ASSERT_EQ(s.objects.size(), 3u);
    EXPECT_EQ(std::get<Lathe>(s.objects[0].shape).spline, Lathe::Spline::Linear);
    EXPECT_EQ(std::get<Lathe>(s.objects[1].shape).spline, Lathe::Spline::Bezier);
    EXPECT_EQ(std::get<Lathe>(s.objects[2].shape).points.size(), 5u);
    EXPECT_DOUBLE_EQ(std::get<Lathe>(s.objects[2].shape).points[0].x, -1.0);  // the ends may be left of the axis
    parse_fail("lathe { bezier_spline 3, <0, 0>, <1, 0>, <1, 1> }");
    parse_fail("lathe { 3, <0, 0>, <-1, 0.5>, <0, 1> }");
}

TEST(Sor, PointsOpenAndChecks) {
    const Scene s = parse_ok(R"(
        sor { 4, <1, -1>, <1, 0>, <1, 1>, <1, 2> }
        sor { 5, <0, 0>, <1, 0.1>, <0.5, 1>, <0.7, 1.5>, <1, 2> open sturm }
    )");
    ASSERT_EQ(s.objects.size(), 2u);
    EXPECT_FALSE(std::get<Sor>(s.objects[0].shape).open);
    EXPECT_TRUE(std::get<Sor>(s.objects[1].shape).open);
    parse_fail("sor { 3, <1, 0>, <1, 1>, <1, 2> }");
    parse_fail("sor { 4, <1, 0>, <1, 1>, <1, 0.5>, <1, 2> }");  // inner heights must climb
}

TEST(Prism, SplineTypesAndCounts) {
    const Scene s = parse_ok(R"(
        prism { 0, 1, 3, <0, 0>, <1, 0>, <0, 1> }
        prism { quadratic_spline conic_sweep 0.5, 1, 5, <1, 1>, <1, 0>, <0, 1>, <-1, 0>, <1, 0> }
        prism { bezier_spline 0, 1, 4, <0, 0>, <1, 0>, <1, 1>, <0, 0> }
    )");
    ASSERT_EQ(s.objects.size(), 3u);
    EXPECT_EQ(std::get<Prism>(s.objects[0].shape).spline, Prism::Spline::Linear);
    EXPECT_EQ(std::get<Prism>(s.objects[1].shape).spline, Prism::Spline::Quadratic);
    EXPECT_TRUE(std::get<Prism>(s.objects[1].shape).conic);
    EXPECT_EQ(std::get<Prism>(s.objects[2].shape).spline, Prism::Spline::Bezier);
    EXPECT_TRUE(s.warnings.empty()) << s.warnings.front().message;
    parse_fail("prism { cubic_spline 0, 1, 5, <0, 0>, <1, 0>, <1, 1>, <0, 1>, <0, 0> }");
    parse_fail("prism { bezier_spline 0, 1, 5, <0, 0>, <1, 0>, <1, 1>, <0, 1>, <0, 0> }");
}

// A mesh triangle's uv_vectors give its corners uv coordinates for uv_mapping; texture_list gives each corner a
// texture (identifiers, as POV-Ray's Parse_Mesh_Texture reads them).
TEST(Mesh, TriangleUvVectorsAndTexturesAreRead) {
    const ParseResult r = parse_string(R"(global_settings { assumed_gamma 1 }
        #declare A = texture { pigment { rgb x } }
        #declare B = texture { pigment { rgb y } }
        mesh {
          smooth_triangle { <0, 0, 0>, z, <1, 0, 0>, z, <0, 1, 0>, z uv_vectors <0, 0>, <1, 0>, <0, 1> }
          triangle { <1, 0, 0>, <1, 1, 0>, <0, 1, 0> uv_vectors <1, 0> <1, 1> <0, 1> texture { pigment { rgb 1 } } }
          triangle { <1, 0, 0>, <1, 1, 0>, <0, 1, 0> texture_list { A, B, A } }
        })",
                                       "test.pov", test::default_options());
    ASSERT_TRUE(r.ok()) << test::all_diagnostics(r);
    ASSERT_EQ(r.scene->objects.size(), 1u);
    const auto& mesh = std::get<Mesh>(r.scene->objects[0].shape);
    ASSERT_EQ(mesh.faces.size(), 3u);
    EXPECT_EQ(mesh.normals.size(), 3u);
    EXPECT_EQ(mesh.vertices[5].y, 1);
    ASSERT_EQ(mesh.uvs.size(), 6u);
    EXPECT_EQ(mesh.uvs[mesh.faces[1].uv[1]], (Vec3{1, 1, 0}));
    EXPECT_EQ(mesh.faces[2].uv[0], -1);  // no uv_vectors: POV-Ray's (0, 0)
    EXPECT_EQ(mesh.faces[0].tex[0], -1);
    EXPECT_EQ(mesh.faces[1].tex[0], 0);
    EXPECT_EQ(mesh.faces[1].tex[1], -1);
    ASSERT_EQ(mesh.textures.size(), 4u);
    EXPECT_EQ(mesh.textures[mesh.faces[2].tex[1]].pigment.color.rgb(), (Vec3{0, 1, 0}));
    EXPECT_EQ(test::all_diagnostics(r).find("not rendered yet"), std::string::npos);
    parse_fail("mesh { triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 0> uv_vectors <0, 0>, <1, 0> } }");
}

// mesh2: uv_indices pick uv_vectors per face (without them the vertex indices do), texture_list entries are
// chosen by one or three indices after a face.
TEST(Mesh, Mesh2UvIndicesAndTextureList) {
    const ParseResult r = parse_string(R"(global_settings { assumed_gamma 1 }
        mesh2 {
          vertex_vectors { 4, <0, 0, 0>, <1, 0, 0>, <1, 1, 0>, <0, 1, 0> }
          uv_vectors { 2, <0.25, 0.5>, <1, 1> }
          texture_list { 2, texture { pigment { rgb x } } texture { pigment { rgb z } } }
          face_indices { 3, <0, 1, 2>, 1, <0, 2, 3>, 0, 1, 1, <1, 2, 3> }
          uv_indices { 3, <0, 1, 0>, <1, 1, 0>, <0, 0, 0> }
          uv_mapping
        })",
                                       "test.pov", test::default_options());
    ASSERT_TRUE(r.ok()) << test::all_diagnostics(r);
    const auto& mesh = std::get<Mesh>(r.scene->objects[0].shape);
    ASSERT_EQ(mesh.faces.size(), 3u);
    EXPECT_EQ(mesh.faces[0].uv, (std::array<int, 3>{0, 1, 0}));
    EXPECT_EQ(mesh.faces[0].tex, (std::array<int, 3>{1, -1, -1}));
    EXPECT_EQ(mesh.faces[1].tex, (std::array<int, 3>{0, 1, 1}));
    EXPECT_EQ(mesh.faces[2].tex, (std::array<int, 3>{-1, -1, -1}));
    EXPECT_TRUE(r.scene->objects[0].uv_mapping);
    parse_fail("mesh2 { vertex_vectors { 3, 0, x, y } uv_vectors { 1, <0, 0> } face_indices { 1, <0, 1, 2> } }");
    parse_fail("mesh2 { vertex_vectors { 3, 0, x, y } texture_list { 1, texture { } } face_indices { 1, <0, 1, 2>, 3 } }");
}

// uv_mapping on a pigment, a normal and a texture is read, and keeps them out of the object's transforms.
TEST(Mesh, UvMappingStaysInUvSpace) {
    const ParseResult r = parse_string(R"(global_settings { assumed_gamma 1 }
        mesh2 {
          vertex_vectors { 3, <0, 0, 0>, <1, 0, 0>, <1, 1, 0> } uv_vectors { 3, <0, 0>, <1, 0>, <1, 1> }
          face_indices { 1, <0, 1, 2> }
          texture { pigment { uv_mapping checker scale 2 } normal { uv_mapping bumps } }
          translate 5*x
        }
        mesh2 {
          vertex_vectors { 3, <0, 0, 0>, <1, 0, 0>, <1, 1, 0> } face_indices { 1, <0, 1, 2> }
          texture { uv_mapping pigment { checker } scale 3 }
          scale 7
        }
        sphere { 0, 1 pigment { uv_mapping checker } })",
                                       "test.pov", test::default_options());
    ASSERT_TRUE(r.ok()) << test::all_diagnostics(r);
    const Texture& a = r.scene->objects[0].texture;
    EXPECT_TRUE(a.pigment.uv_mapping);
    EXPECT_TRUE(a.normal.uv_mapping);
    EXPECT_EQ(a.pigment.pattern.transform.point({1, 1, 1}), (Vec3{2, 2, 2}));
    const Texture& b = r.scene->objects[1].texture;
    EXPECT_TRUE(b.uv_mapping);
    EXPECT_EQ(b.pigment.pattern.transform.point({1, 1, 1}), (Vec3{3, 3, 3}));
    // A sphere has no uv coordinates here yet: said so.
    EXPECT_NE(test::all_diagnostics(r).find("uv_mapping on sphere is not rendered yet"), std::string::npos);
}

// `pigment { uv_mapping Declared }`: the item after uv_mapping is a pigment of its own (POV-Ray's
// Parse_Item_Into_Blend_List), so it may be a declared pigment (or normal), modified by what follows.
TEST(Mesh, UvMappingTakesADeclaredPigmentOrNormal) {
    const Scene s = parse_ok(R"(
        #declare P = pigment { color rgb <0.8, 0.2, 0.1> }
        #declare N = normal { bumps 0.5 }
        mesh2 {
          vertex_vectors { 3, <0, 0, 0>, <1, 0, 0>, <1, 1, 0> } uv_vectors { 3, <0, 0>, <1, 0>, <1, 1> }
          face_indices { 1, <0, 1, 2> }
          texture { pigment { uv_mapping P } normal { uv_mapping N scale 2 } }
        }
    )");
    const Texture& t = s.objects[0].texture;
    EXPECT_TRUE(t.pigment.uv_mapping);
    EXPECT_EQ(t.pigment.color.r, 0.8);
    EXPECT_EQ(t.pigment.color.g, 0.2);
    EXPECT_TRUE(t.normal.uv_mapping);
    EXPECT_EQ(t.normal.pattern.type, Pattern::Type::Bumps);
    EXPECT_EQ(t.normal.pattern.transform.point({1, 1, 1}), (Vec3{2, 2, 2}));
}

// POV-Ray reads the commas between quartic coefficients as optional (primitiv.pov, hyptorus.pov), and a mesh2 face
// is followed by texture indices only when a float comes next (shapes.inc writes `F1+A, F2+A` with vector F1, F2).
TEST(Mesh, OptionalCommasAndFaceIndicesFromVectorIdentifiers) {
    const Scene s = parse_ok(R"(
        quartic { <1, 0, 0, 0, 2, 0, 0, 2, 0, -2.5, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0
                   1, 0, 0, 2, 0  1.5, 0, 0, 0, 0, 1, 0, -2.5, 0, 0.5> }
        #declare F1 = <0, 1, 2>;
        #declare F2 = <1, 3, 2>;
        mesh2 {
          vertex_vectors { 4, <0, 0, 0>, <1, 0, 0>, <0, 1, 0>, <1, 1, 0> }
          face_indices { 3, F1 + 0, F2, <0, 1, 3> }
        }
    )");
    ASSERT_EQ(s.objects.size(), 2u);
    const auto& q = std::get<Quartic>(s.objects[0].shape);
    EXPECT_EQ(q.coefficients[25], 1.5);
    EXPECT_EQ(q.coefficients[34], 0.5);
    const auto& mesh = std::get<Mesh>(s.objects[1].shape);
    ASSERT_EQ(mesh.faces.size(), 3u);
    EXPECT_EQ(mesh.faces[1].v[1], 3);
    EXPECT_EQ(mesh.faces[2].v[2], 3);
}

// Issue 23: a declared mesh used many times costs its size once; the uses share its arrays (and an object without a
// texture of its own shares the default), while changing one use (a transform) leaves the arrays shared.
TEST(Mesh, UsesOfADeclaredMeshShareItsArrays) {
    const Scene s = parse_ok(R"(
        #declare M = mesh2 {
          vertex_vectors { 4, <0, 0, 0>, <1, 0, 0>, <0, 1, 0>, <1, 1, 0> }
          face_indices { 2, <0, 1, 2>, <1, 3, 2> }
        }
        object { M }
        object { M translate x }
        object { M scale 2 pigment { rgb 1 } }
        #declare M = object { M rotate y * 90 }
        object { M }
    )");
    ASSERT_EQ(s.objects.size(), 4u);
    const auto& first = std::get<Mesh>(s.objects[0].shape);
    for (std::size_t i = 1; i < s.objects.size(); ++i) {
        const auto& other = std::get<Mesh>(s.objects[i].shape);
        EXPECT_TRUE(other.vertices.shares(first.vertices)) << i;
        EXPECT_TRUE(other.faces.shares(first.faces)) << i;
        EXPECT_EQ(other.faces.data(), first.faces.data()) << i;
    }
    EXPECT_TRUE(s.objects[0].texture.shares(s.objects[1].texture));
    EXPECT_FALSE(s.objects[2].texture.shares(s.objects[0].texture));
}

// Triangles that each repeat one declared texture share one entry of the mesh's texture list; a different texture
// gets its own, and a triangle after it that repeats the first again another (only neighbours are compared).
TEST(Mesh, TrianglesRepeatingOneTextureShareOneListEntry) {
    const Scene s = parse_ok(R"(
        #declare T = texture { pigment { rgb x } finish { phong 1 } }
        mesh {
          triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 0> texture { T } }
          triangle { <1, 0, 0>, <1, 1, 0>, <0, 1, 0> texture { T } }
          triangle { <0, 0, 1>, <1, 0, 1>, <0, 1, 1> texture { T } }
          triangle { <0, 0, 2>, <1, 0, 2>, <0, 1, 2> texture { pigment { rgb y } } }
          triangle { <0, 0, 3>, <1, 0, 3>, <0, 1, 3> texture { T } }
        }
    )");
    ASSERT_EQ(s.objects.size(), 1u);
    const auto& mesh = std::get<Mesh>(s.objects[0].shape);
    ASSERT_EQ(mesh.textures.size(), 3u);
    ASSERT_EQ(mesh.faces.size(), 5u);
    const int expected[] = {0, 0, 0, 1, 2};
    for (std::size_t i = 0; i < 5; ++i) EXPECT_EQ(mesh.faces[i].tex[0], expected[i]) << i;
    EXPECT_EQ(mesh.textures[0].pigment.color.rgb(), (Vec3{1, 0, 0}));
    EXPECT_EQ(mesh.textures[1].pigment.color.rgb(), (Vec3{0, 1, 0}));
    EXPECT_EQ(mesh.textures[2], mesh.textures[0]);
}

TEST(BoundedBy, TopLevelCheapShapesLoseTheirBoundsPolynomialsAndCsgKeepThem) {
    // POV-Ray compat (Link_To_Frame): only CSG, polynomials, text and quadrics keep a top-level bounded_by.
    const Scene s = parse_ok(R"(
        sphere { 0, 1 bounded_by { sphere { 0, 0.5 } } }
        quartic { <1,0,0,0,0,0,0,0,0,0, 0,0,0,0,0,0,0,0,0,0, 0,0,0,0,0,0,0,0,0,0, 0,0,0,0,-1>
                  bounded_by { sphere { 0, 0.5 } } translate x }
        union { sphere { 0, 1 } sphere { x, 1 } bounded_by { box { -1, 1 } } }
    )");
    ASSERT_EQ(s.objects.size(), 4u);
    EXPECT_TRUE(s.objects[0].bounded_by.empty());
    ASSERT_EQ(s.objects[1].bounded_by.size(), 1u);
    // Stored relative to the object: the later translate moves both.
    EXPECT_EQ(s.objects[1].bounded_by[0].transform.point({0, 0, 0}).x, 0.0);
    EXPECT_EQ(s.objects[2].bounded_by.size(), 1u);
    EXPECT_EQ(s.objects[3].bounded_by.size(), 1u);
}

}  // namespace
}  // namespace wardray::parser
