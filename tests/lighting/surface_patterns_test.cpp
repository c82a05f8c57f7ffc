// The surface patterns: slope and aoi against the analytic answers of POV-Ray 3.7's slope_pattern and aoi_pattern,
// the parser's reading of slope's forms, and the facets normal's cells.
#include <gtest/gtest.h>

#include <cmath>

#include "core/constants.h"
#include "parser/parse.h"
#include "texture/normal.h"
#include "texture/pattern.h"

namespace wardray::lighting {
namespace {

parser::ParseResult parse_text(const std::string& text) {
    parser::ParseOptions options;
    return parser::parse_string("global_settings { assumed_gamma 1 }\n" + text, "test.pov", options);
}

// The pigment pattern of `sphere { 0, 1 pigment { PATTERN } }`.
scene::Pattern pattern_of(const std::string& pattern) {
    const parser::ParseResult r = parse_text("sphere { 0, 1 pigment { " + pattern + " } }");
    EXPECT_TRUE(r.ok());
    for (const auto& d : r.diagnostics) ADD_FAILURE() << d.message;
    if (!r.scene || r.scene->objects.empty()) return {};
    return r.scene->objects[0].texture->pigment.pattern;
}

double value_at(const scene::Pattern& pat, const Vec3& p, const Vec3& n, const Vec3& dir = {0, 0, 1}) {
    const texture::SurfacePoint surface{p, normalize(n), normalize(dir)};
    return texture::pattern_value(pat, p, 2, &surface);
}

TEST(Slope, IsTheNormalsAngleToTheSlopeVectorMappedToZeroOne) {
    const scene::Pattern pat = pattern_of("slope y");
    ASSERT_EQ(pat.type, scene::Pattern::Type::Slope);
    // asin(n·y) / (π/2) taken from [-1, 1] to [0, 1]; exactly 1 stays just below it.
    EXPECT_DOUBLE_EQ(value_at(pat, {}, {1, 0, 0}), 0.5);
    EXPECT_DOUBLE_EQ(value_at(pat, {}, {1, 1, 0}), 0.75);
    EXPECT_DOUBLE_EQ(value_at(pat, {}, {1, -1, 0}), 0.25);
    EXPECT_DOUBLE_EQ(value_at(pat, {}, {0, 1, 0}), 1.0 - kPovEpsilon);
    // A vector's length does not change the slope alone.
    EXPECT_DOUBLE_EQ(value_at(pattern_of("slope y*3"), {}, {1, 1, 0}), 0.75);
    // Away from a surface (the sky, media) POV-Ray's slope is 0.
    EXPECT_EQ(texture::pattern_value(pat, {}, 2, nullptr), 0.0);
}

TEST(Slope, RangeAndAltitudeAreWeightedByTheVectorsLengths) {
    // slope { y, 0.5, 1 }: (0.75 − 0.5) / 0.5 at 45°.
    EXPECT_DOUBLE_EQ(value_at(pattern_of("slope { y, 0.5, 1.0 }"), {}, {1, 1, 0}), 0.5);
    // Below the range it wraps: (0.25 − 0.5) / 0.5 = −0.5 → 0.5.
    EXPECT_DOUBLE_EQ(value_at(pattern_of("slope { y, 0.5, 1.0 }"), {}, {1, -1, 0}), 0.5);
    // slope { y*3 altitude y }: 3/4 of the slope, 1/4 of the height.
    EXPECT_NEAR(value_at(pattern_of("slope { y*3 altitude y }"), {0, 0.4, 0}, {1, 0, 0}), 0.75 * 0.5 + 0.25 * 0.4,
                1e-15);
    // The altitude's range: (0.4 − 0.2) / (1.2 − 0.2) = 0.2.
    EXPECT_NEAR(value_at(pattern_of("slope { y, 0, 1 altitude y*3, 0.2, 1.2 }"), {0, 0.4, 0}, {1, 0, 0}),
                0.25 * 0.5 + 0.75 * 0.2, 1e-15);
    // The altitude is taken along its unit vector, weighted 5 to 1 here; the sum 1.25 wraps to 0.25.
    EXPECT_NEAR(value_at(pattern_of("slope { y altitude <0, 3, 4> }"), {0, 1, 1}, {1, 0, 0}),
                0.5 / 6.0 + 5.0 / 6.0 * 1.4 - 1.0, 1e-12);
}

TEST(Slope, PointAtMeasuresTheSlopeTowardsAPoint) {
    const scene::Pattern pat = pattern_of("slope { point_at <0, 5, 0> }");
    EXPECT_TRUE(pat.params->slope.point_at);
    EXPECT_DOUBLE_EQ(value_at(pat, {0, 0, 0}, {1, 0, 0}), 0.5);
    EXPECT_DOUBLE_EQ(value_at(pat, {5, 0, 0}, {1, 0, 0}), 0.25);
}

TEST(Slope, ParserWarnsAndFailsAsPovRay) {
    const parser::ParseResult zero = parse_text("sphere { 0, 1 pigment { slope { y, 0.5, 0.5 } } }");
    ASSERT_TRUE(zero.ok());
    ASSERT_EQ(zero.diagnostics.size(), 1u);
    EXPECT_NE(zero.diagnostics[0].message.find("Zero slope range"), std::string::npos);
    EXPECT_EQ(zero.scene->objects[0].texture->pigment.pattern.params->slope.slope_range, 0.0);
    const parser::ParseResult point_at =
        parse_text("sphere { 0, 1 pigment { slope { point_at y altitude x } } }");
    EXPECT_FALSE(point_at.ok());
    const parser::ParseResult zero_length = parse_text("sphere { 0, 1 pigment { slope 0 } }");
    EXPECT_FALSE(zero_length.ok());
}

TEST(Aoi, IsTheAngleBetweenTheNormalAndTheRayOverPi) {
    const scene::Pattern pat = pattern_of("aoi");
    ASSERT_EQ(pat.type, scene::Pattern::Type::Aoi);
    // The normal faces the ray, so a head-on hit is π: just below 1 after the frequency wrap (fmod 1.00001).
    EXPECT_DOUBLE_EQ(value_at(pat, {}, {0, 0, -1}, {0, 0, 1}), 1.0);
    EXPECT_NEAR(value_at(pat, {}, {0, 0, -1}, {std::sqrt(3.0) / 2.0, 0, 0.5}), 2.0 / 3.0, 1e-15);
    EXPECT_NEAR(value_at(pat, {}, {0, 0, -1}, {1, 0, 0}), 0.5, 1e-15);
    EXPECT_EQ(texture::pattern_value(pat, {}, 2, nullptr), 0.0);
}

// The normal of `sphere { 0, 1 normal { NORMAL } }`.
scene::Normal normal_of(const std::string& normal) {
    const parser::ParseResult r = parse_text("sphere { 0, 1 normal { " + normal + " } }");
    EXPECT_TRUE(r.ok());
    for (const auto& d : r.diagnostics) ADD_FAILURE() << d.message;
    if (!r.scene || r.scene->objects.empty()) return {};
    return r.scene->objects[0].texture->normal;
}

TEST(Facets, NormalsOfOneCellTurnToTheSamePoint) {
    const scene::Normal facets = normal_of("facets size 0.25");
    ASSERT_EQ(facets.pattern.type, scene::Pattern::Type::Facets);
    // Without coords the normal, scaled by 1/size, picks the nearest random point: normals close together share a
    // facet, so the result is piecewise constant; it stays within the 3×3×3 cubes around 4·n.
    const Vec3 n0 = normalize(Vec3{0.2, 1.0, -0.1});
    const Vec3 a = texture::perturb_normal(facets, n0, {}, 2);
    EXPECT_NEAR(length(a), 1.0, 1e-12);
    int same = 0, different = 0;
    for (int i = 0; i < 200; ++i) {
        const Vec3 n = normalize(n0 + Vec3{0.002 * (i % 7), 0.0, 0.5 * i / 200.0});
        const Vec3 b = texture::perturb_normal(facets, n, {}, 2);
        (length(b - a) < 1e-15 ? same : different)++;
    }
    EXPECT_GT(same, 5);
    EXPECT_GT(different, 5);
    // The point does not matter without coords.
    EXPECT_EQ(texture::perturb_normal(facets, n0, {3, 4, 5}, 2), a);
}

TEST(Facets, CoordsTiltTheNormalByThePointsCellAndIsOnlyANormal) {
    const scene::Normal facets = normal_of("facets coords 0.5");
    const Vec3 n{0.0, 1.0, 0.0};
    // By the point: the same cell gives the same tilt, which leaves the normal's own component alone.
    const Vec3 a = texture::perturb_normal(facets, n, {0.31, 0.0, 0.52}, 2);
    const Vec3 b = texture::perturb_normal(facets, n, {0.3101, 0.0, 0.5201}, 2);
    EXPECT_EQ(a, b);
    EXPECT_GT(length(a - n), 1e-3);
    EXPECT_FALSE(parse_text("sphere { 0, 1 pigment { facets } }").ok());
    EXPECT_FALSE(parse_text("sphere { 0, 1 texture { facets texture_map { [0 pigment { rgb 1 }] } } }").ok());
}

}  // namespace
}  // namespace wardray::lighting
