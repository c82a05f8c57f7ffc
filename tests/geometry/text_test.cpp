// Tests of TextShape: extruded glyph outlines (lines and quadratic arcs, holes by the even-odd rule), their hits,
// normals and inside test, on hand-made glyphs so the expectations are exact.
#include <gtest/gtest.h>

#include <cmath>

#include "geometry/instance.h"
#include "test_util.h"

namespace wardray::geometry {
namespace {

using test::check_shape;
using test::make_object;
using test::Random;
using Point = scene::TextGlyph::Point;

// A square [0, 1]² with a square hole [0.3, 0.7]², contours in TrueType's orientation (outer clockwise).
scene::TextGlyph square_with_hole(const Vec3& offset = {}) {
    scene::TextGlyph g;
    g.contours = {{{0, 0}, {0, 1}, {1, 1}, {1, 0}}, {{0.3, 0.3}, {0.7, 0.3}, {0.7, 0.7}, {0.3, 0.7}}};
    g.offset = offset;
    return g;
}

// A round glyph of radius r about c: four on-curve points on the axes and off-curve corners (quadratic arcs), or,
// with `implied`, a hexagon of off-curve points so that the on-curve points are implied midpoints (POV-Ray starts
// the walk at the first point as if it were on the curve: here the top, away from the x axis the tests use).
scene::TextGlyph round_glyph(double cx, double cy, double r, bool implied) {
    scene::TextGlyph g;
    std::vector<Point> c;
    if (implied) {
        for (int k = 0; k < 6; ++k) {
            const double a = M_PI / 2 - 2 * M_PI * k / 6;
            c.push_back({cx + r * std::cos(a), cy + r * std::sin(a), false});
        }
    } else {
        c = {{cx + r, cy, true},  {cx + r, cy - r, false}, {cx, cy - r, true},  {cx - r, cy - r, false},
             {cx - r, cy, true},  {cx - r, cy + r, false}, {cx, cy + r, true},  {cx + r, cy + r, false}};
    }
    g.contours.push_back(c);
    return g;
}

scene::Text text_of(std::vector<scene::TextGlyph> glyphs, double thickness) {
    scene::Text t;
    t.glyphs = std::move(glyphs);
    t.thickness = thickness;
    return t;
}

TEST(Text, RandomRaysOnLinesArcsAndHoles) {
    check_shape([](Random& r) {
        std::vector<scene::TextGlyph> glyphs{square_with_hole({-1.2, -0.5, 0}),
                                              round_glyph(0.7, 0.0, r.uniform(0.3, 0.6), r.chance(0.5))};
        return text_of(glyphs, r.uniform(0.2, 1.0));
    }, true, 31);
}

TEST(Text, CapHitsAndHoles) {
    const auto inst = ShapeInstance::create(make_object(text_of({square_with_hole()}, 0.5)), 0);
    ASSERT_TRUE(inst);
    // Straight at the front cap (z = 0) through the solid part: the hit faces the ray.
    const auto front = inst->nearest({0.1, 0.5, -2}, {0, 0, 1}, 0.0, 1e30);
    ASSERT_TRUE(front);
    EXPECT_DOUBLE_EQ(front->t, 2.0);
    EXPECT_DOUBLE_EQ(front->normal.z, -1.0);
    // Through the hole nothing is hit.
    EXPECT_FALSE(inst->nearest({0.5, 0.5, -2}, {0, 0, 1}, 0.0, 1e30));
    // From behind, the back cap at z = thickness.
    const auto back = inst->nearest({0.9, 0.2, 3}, {0, 0, -1}, 0.0, 1e30);
    ASSERT_TRUE(back);
    EXPECT_DOUBLE_EQ(back->t, 2.5);
    EXPECT_DOUBLE_EQ(back->normal.z, 1.0);
    EXPECT_TRUE(inst->inside({0.1, 0.5, 0.25}));
    EXPECT_FALSE(inst->inside({0.5, 0.5, 0.25}));  // the hole
    EXPECT_FALSE(inst->inside({0.1, 0.5, 0.6}));   // behind the back cap
    EXPECT_FALSE(inst->inside({1.1, 0.5, 0.25}));
}

TEST(Text, WallsAlongXCrossFourTimesThroughTheHole) {
    const auto inst = ShapeInstance::create(make_object(text_of({square_with_hole()}, 1.0)), 0);
    ASSERT_TRUE(inst);
    const SurfaceHits hits = inst->intersect_all({-1, 0.5, 0.5}, {1, 0, 0}, 0.0, 1e30);
    ASSERT_EQ(hits.size(), 4u);
    const double expected_t[4] = {1.0, 1.3, 1.7, 2.0};
    const double expected_nx[4] = {-1.0, 1.0, -1.0, 1.0};
    for (int i = 0; i < 4; ++i) {
        EXPECT_NEAR(hits[i].t, expected_t[i], 1e-15);
        EXPECT_NEAR(hits[i].normal.x, expected_nx[i], 1e-15);
        EXPECT_EQ(hits[i].entering, i % 2 == 0);
    }
}

TEST(Text, ArcWallsPassThroughOnCurvePointsWithRadialNormals) {
    for (const bool implied : {false, true}) {
        const auto inst = ShapeInstance::create(make_object(text_of({round_glyph(0, 0, 1, implied)}, 1.0)), 0);
        ASSERT_TRUE(inst);
        // Implied on-curve points lie at the midpoints of the off-curve hexagon's edges, two of them on the x axis.
        const double edge = implied ? std::cos(M_PI / 6) : 1.0;
        const SurfaceHits hits = inst->intersect_all({-3, 0, 0.5}, {1, 0, 0}, 0.0, 1e30);
        ASSERT_EQ(hits.size(), 2u) << "implied " << implied;
        EXPECT_NEAR(hits[0].t, 3 - edge, 1e-12);
        EXPECT_NEAR(hits[1].t, 3 + edge, 1e-12);
        EXPECT_NEAR(hits[0].normal.x, -1.0, 1e-12);
        EXPECT_NEAR(hits[1].normal.x, 1.0, 1e-12);
        EXPECT_TRUE(inst->inside({0, 0, 0.5}));
        EXPECT_FALSE(inst->inside({0.99, 0.99, 0.5}));
    }
}

TEST(Text, GlyphsAreAUnion) {
    // Two glyphs side by side: inside either is inside the text; a ray along x meets both.
    const auto inst = ShapeInstance::create(
        make_object(text_of({square_with_hole(), square_with_hole({2, 0, 0})}, 1.0)), 0);
    ASSERT_TRUE(inst);
    EXPECT_TRUE(inst->inside({2.1, 0.5, 0.5}));
    EXPECT_FALSE(inst->inside({1.5, 0.5, 0.5}));
    EXPECT_EQ(inst->intersect_all({-1, 0.1, 0.5}, {1, 0, 0}, 0.0, 1e30).size(), 4u);
    const auto b = inst->world_bounds();
    ASSERT_TRUE(b);
    EXPECT_DOUBLE_EQ(b->upper.x, 3.0);
    EXPECT_DOUBLE_EQ(b->upper.z, 1.0);
}

TEST(Text, EmptyTextIsSkipped) {
    EXPECT_FALSE(ShapeInstance::create(make_object(text_of({}, 1.0)), 0));
    scene::TextGlyph space;  // a space has no contours
    EXPECT_FALSE(ShapeInstance::create(make_object(text_of({space}, 1.0)), 0));
}

}  // namespace
}  // namespace wardray::geometry
