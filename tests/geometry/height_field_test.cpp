// Tests of HeightFieldShape: random grids against brute force over every triangle (nearest crossing, inside),
// POV-Ray's unit-square geometry, water level, smooth normals at grid points, and the parser's function image.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "geometry/instance.h"
#include "parser/parse.h"
#include "test_util.h"

namespace wardray::geometry {
namespace {

using test::Random;

// A w x h grid of heights: smooth hills plus noise, so both gentle and steep cells occur.
std::shared_ptr<scene::HeightGrid> random_grid(Random& r, int w, int h) {
    auto g = std::make_shared<scene::HeightGrid>();
    g->width = w;
    g->height = h;
    const double a = r.uniform(1, 6), b = r.uniform(1, 6), noise = r.uniform(0, 8000);
    for (int z = 0; z < h; ++z)
        for (int x = 0; x < w; ++x) {
            const double v = 30000 + 25000 * std::sin(a * x / w + b * z / h) + r.uniform(-noise, noise);
            g->heights.push_back(static_cast<std::uint16_t>(std::clamp(v, 0.0, 65535.0)));
        }
    return g;
}

// Brute force in unit-square space: the nearest crossing with any of the grid's triangles (exact tests) inside
// POV-Ray's box [0, 1] x [lo, hi] x [0, 1].
double brute_nearest(const scene::HeightGrid& g, double water, const LocalRay& ray) {
    const Vec3 s{1.0 / (g.width - 1), 1.0 / 65536.0, 1.0 / (g.height - 1)};
    double lo = 65535, hi = 0;
    for (auto v : g.heights) lo = std::fmin(lo, v), hi = std::fmax(hi, v);
    lo = std::fmax(lo, 65536.0 * water) - 0.001;
    hi += 0.001;
    double b0 = 0, b1 = 0;
    if (!slab_interval({0, lo * s.y, 0}, {1, hi * s.y, 1}, ray.origin, ray.direction, b0, b1)) return INFINITY;
    b0 = std::fmax(b0, 1e-6);
    auto vertex = [&](int x, int z) { return Vec3{x * s.x, g.at(x, z) * s.y, z * s.z}; };
    double best = INFINITY;
    auto triangle = [&](const Vec3& a, const Vec3& b, const Vec3& c) {
        const Vec3 e1 = b - a, e2 = c - a, pv = cross(ray.direction, e2);
        const double det = dot(e1, pv);
        if (det == 0.0) return;
        const Vec3 tv = ray.origin - a, qv = cross(tv, e1);
        const double u = dot(tv, pv) / det, v = dot(ray.direction, qv) / det, t = dot(e2, qv) / det;
        if (u >= 0 && v >= 0 && u + v <= 1 && t >= b0 && t <= b1) best = std::fmin(best, t);
    };
    for (int z = 0; z + 1 < g.height; ++z)
        for (int x = 0; x + 1 < g.width; ++x) {
            triangle(vertex(x, z), vertex(x + 1, z), vertex(x, z + 1));
            triangle(vertex(x + 1, z + 1), vertex(x, z + 1), vertex(x + 1, z));
        }
    return best;
}

TEST(HeightField, NearestCrossingAgreesWithBruteForce) {
    Random rng(11);
    int hits = 0, misses = 0, disagreements = 0;
    for (int trial = 0; trial < 400; ++trial) {
        scene::HeightField hf;
        hf.grid = random_grid(rng, rng.integer(2, 40), rng.integer(2, 40));
        hf.water_level = rng.chance(0.3) ? rng.uniform(0.0, 0.6) : 0.0;
        hf.smooth = rng.chance(0.5);
        const auto shape = HeightFieldShape::create(hf);
        ASSERT_TRUE(shape);
        const Vec3 target{rng.uniform(-0.1, 1.1), rng.uniform(0.0, 1.0), rng.uniform(-0.1, 1.1)};
        const Vec3 origin = target + rng.direction() * rng.uniform(0.5, 4.0);
        const LocalRay ray{origin, (target - origin) * rng.uniform(0.2, 5.0)};
        const double expected = brute_nearest(*hf.grid, hf.water_level, ray);
        const SurfaceHits got = shape->intersect_all(ray, 0.0, INFINITY);
        if (!std::isfinite(expected)) {
            // Only POV-Ray's edge tolerance may add a crossing the exact test does not see.
            disagreements += !got.empty();
            ++misses;
            continue;
        }
        ++hits;
        ASSERT_FALSE(got.empty()) << "trial " << trial;
        if (std::fabs(got[0].t - expected) > 1e-9 * std::fmax(1.0, expected)) ++disagreements;
        // Every crossing lies on the surface, and the normal points up out of the field.
        for (const SurfaceHit& h : got) {
            const Vec3 p = ray.origin + h.t * ray.direction;
            EXPECT_NEAR(shape->implicit(p), 0.0, 1e-9) << "trial " << trial;
            EXPECT_GT(h.normal.y, 0.0);
            if (!hf.smooth) {
                EXPECT_EQ(h.entering, dot(h.normal, ray.direction) < 0.0);
            }
        }
    }
    EXPECT_GT(hits, 150);
    EXPECT_GT(misses, 30);
    EXPECT_LE(disagreements, (hits + misses) / 100);
}

TEST(HeightField, InsideAgreesWithTheHeightBelowThePoint) {
    Random rng(12);
    for (int trial = 0; trial < 50; ++trial) {
        scene::HeightField hf;
        hf.grid = random_grid(rng, rng.integer(2, 30), rng.integer(2, 30));
        hf.water_level = rng.chance(0.5) ? rng.uniform(0.0, 0.7) : 0.0;
        const auto shape = HeightFieldShape::create(hf);
        ASSERT_TRUE(shape);
        const Bounds b = *shape->bounds();
        for (int k = 0; k < 200; ++k) {
            const Vec3 p{rng.uniform(0.0, 0.999), rng.uniform(-0.1, 1.1), rng.uniform(0.0, 0.999)};
            const double above = shape->implicit(p);
            if (std::fabs(above) < 1e-6) continue;
            // POV-Ray compat: with a water level the triangles' corners are raised to it for the inside test, so
            // only points clearly below the water or above every height are checked then.
            if (hf.water_level > 0.0 && p.y >= b.lower.y && p.y < b.upper.y) continue;
            const bool expected = p.y < b.upper.y && (above < 0.0 || p.y < b.lower.y);
            EXPECT_EQ(shape->inside(p), expected) << "trial " << trial << " point " << p.x << " " << p.y << " " << p.z;
        }
        // Outside the unit square nothing is inside.
        EXPECT_FALSE(shape->inside({-0.01, 0.0, 0.5}));
        EXPECT_FALSE(shape->inside({0.5, 0.0, 1.0}));
    }
}

TEST(HeightField, UnitSquareGeometryAndWaterLevel) {
    // A 3 x 2 grid: heights 0, 32768, 65535 along x, the same on both rows.
    scene::HeightField hf;
    auto g = std::make_shared<scene::HeightGrid>();
    g->width = 3;
    g->height = 2;
    g->heights = {0, 32768, 65535, 0, 32768, 65535};
    hf.grid = g;
    const auto flat = HeightFieldShape::create(hf);
    ASSERT_TRUE(flat);
    // Straight down at x = 0.75 (half way along the second cell): the height is (32768 + 65535) / 2 / 65536.
    const SurfaceHits down = flat->intersect_all({{0.75, 2.0, 0.5}, {0.0, -1.0, 0.0}}, 0.0, INFINITY);
    ASSERT_EQ(down.size(), 1u);
    EXPECT_NEAR(2.0 - down[0].t, (32768.0 + 65535.0) / 2.0 / 65536.0, 1e-12);
    // The flat normal of that cell in unit space: slope (65535 - 32768) / 65536 per half unit of x.
    const Vec3 n = normalize(down[0].normal);
    const double slope = (65535.0 - 32768.0) / 65536.0 / 0.5;
    EXPECT_NEAR(n.x, -slope / std::sqrt(1 + slope * slope), 1e-12);
    EXPECT_NEAR(n.z, 0.0, 1e-12);
    // With water_level 0.6 the part below 0.6 is not drawn: a ray down at x = 0.25 (height 0.25) misses.
    hf.water_level = 0.6;
    const auto wet = HeightFieldShape::create(hf);
    EXPECT_TRUE(wet->intersect_all({{0.25, 2.0, 0.5}, {0.0, -1.0, 0.0}}, 0.0, INFINITY).empty());
    EXPECT_EQ(wet->intersect_all({{0.75, 2.0, 0.5}, {0.0, -1.0, 0.0}}, 0.0, INFINITY).size(), 1u);
    // Below the water level is inside.
    EXPECT_TRUE(wet->inside({0.25, 0.55, 0.5}));
    EXPECT_FALSE(wet->inside({0.25, 0.65, 0.5}));
}

TEST(HeightField, SmoothNormalsAreTheGridNormalsAtGridPoints) {
    // A plane tilted along z: every vertex normal is the plane's normal, so the smooth normal is too.
    scene::HeightField hf;
    auto g = std::make_shared<scene::HeightGrid>();
    g->width = 4;
    g->height = 5;
    for (int z = 0; z < 5; ++z)
        for (int x = 0; x < 4; ++x) g->heights.push_back(static_cast<std::uint16_t>(10000 * z));
    hf.grid = g;
    hf.smooth = true;
    const auto shape = HeightFieldShape::create(hf);
    ASSERT_TRUE(shape);
    const SurfaceHits h = shape->intersect_all({{0.4, 2.0, 0.3}, {0.0, -1.0, 0.0}}, 0.0, INFINITY);
    ASSERT_EQ(h.size(), 1u);
    // POV-Ray compat: the grid-space normal (0, 1, -10000) normalised is stored as 16-bit integers, which keeps
    // only 3 of its y component (0, 3, -32766); unit space scales it by (3, 65536, 4).
    const double gy = 1.0 / std::sqrt(1.0 + 1e8), gz = -10000.0 * gy;
    const Vec3 q{0.0, double(static_cast<short>(32767 * gy)), double(static_cast<short>(32767 * gz))};
    const Vec3 expected = normalize(Vec3{0.0, q.y * 65536.0, q.z * 4.0});
    const Vec3 n = normalize(h[0].normal);
    EXPECT_NEAR(n.z, expected.z, 1e-12);
    EXPECT_NEAR(n.x, 0.0, 1e-12);
}

TEST(HeightField, FunctionImageSamplesTheUnitSquareFromTheTop) {
    // POV-Ray's function image: pixel (i, j) holds f(i/(W-1), j/(H-1)); row j = 0 is the image top, which is z = 1.
    parser::ParseOptions options;
    const parser::ParseResult r = parser::parse_string(
        "global_settings { assumed_gamma 1 }\nheight_field { function 3, 2 { 0.25 * x + 0.5 * y } smooth "
        "water_level 0.1 }",
        "hf.pov", options);
    ASSERT_TRUE(r.ok());
    const auto& hf = std::get<scene::HeightField>(r.scene->objects.front().shape);
    ASSERT_TRUE(hf.grid);
    EXPECT_TRUE(hf.smooth);
    EXPECT_DOUBLE_EQ(hf.water_level, 0.1);
    // z = 0 is the image's bottom row (y = 1): f = 0.25 x + 0.5.
    auto expect_height = [&](int x, int z, double f) {
        const auto stored = static_cast<unsigned>(static_cast<float>(f) * 65535.0f);
        const auto h = static_cast<unsigned>(static_cast<float>(stored) / 65535.0f * 65535.0f);
        EXPECT_EQ(hf.grid->at(x, z), h) << x << "," << z;
    };
    expect_height(0, 0, 0.5);
    expect_height(2, 0, 0.75);
    expect_height(1, 1, 0.125);
}

TEST(HeightField, FunctionImageHeightsAreCutAsPovRayStoresThem) {
    // POV-Ray 3.7's heights, measured with trace() straight down onto a grid point of `function 3, 3 { ... }`
    // (y * 65536): its 16-bit function image cuts value * 65535 instead of rounding it (wallstucco.pov's walls).
    struct Case {
        const char* v;
        unsigned float_fn, grey_pigment, colour_pigment;
    };
    const Case cases[] = {{"0.002503075", 164, 163, 121},
                          {"0.032539975", 2132, 2131, 1584},
                          {"0.03504305", 2296, 2296, 1706},
                          {"0.513130375", 33628, 33627, 25002}};
    for (const Case& c : cases) {
        const std::string v = c.v;
        parser::ParseOptions options;
        options.pigment_value = [](const scene::Pigment& p, const Vec3&, int) { return p.color; };
        const parser::ParseResult r = parser::parse_string(
            "global_settings { assumed_gamma 1 }\n"
            "height_field { function 3, 3 { " + v + " } }\n"
            "height_field { function 3, 3 { pigment { rgb " + v + " } } }\n"
            "height_field { function 3, 3 { pigment { rgb <" + v + ", 0.7 * " + v + ", 0.3 * " + v + "> } } }",
            "hf.pov", options);
        ASSERT_TRUE(r.ok()) << c.v;
        const unsigned expected[3] = {c.float_fn, c.grey_pigment, c.colour_pigment};
        for (int k = 0; k < 3; ++k) {
            const auto& hf = std::get<scene::HeightField>(r.scene->objects[k].shape);
            ASSERT_TRUE(hf.grid);
            EXPECT_EQ(hf.grid->at(1, 1), expected[k]) << "value " << c.v << ", height field " << k;
        }
    }
}

TEST(HeightField, CellTrianglesAreTestedPastTheCellAsPovRayDoes) {
    // POV-Ray tests a cell's triangles over the whole ray within the box and keeps a crossing up to 0.0001 of a cell
    // outside the triangle, even where it lies over the next cell. Here cell (0, 0) rises steeply (0 to 30146 and
    // 39976 over one z step) to a flat ramp in x; a ray along +z just above the edge z = 1 never meets the surface
    // but meets cell (0, 0)'s upper plane 3.75e-5 cells past the edge. POV-Ray 3.7's trace() from
    // <0.1, (31129 + d) / 65536, 0.25> along +z hits at unit z 0.500001251, 0.500006254, 0.500012508, 0.500018761
    // for d = 0.1, 0.5, 1, 1.5 (wallstucco.pov's brick wall casts such shadows on itself).
    parser::ParseOptions options;
    const parser::ParseResult r = parser::parse_string(
        "global_settings { assumed_gamma 1 }\n"
        "height_field { function 2, 3 { select(y - 0.75, 0.46 + 0.15 * x, 0) } }",
        "hf.pov", options);
    ASSERT_TRUE(r.ok());
    const auto& hf = std::get<scene::HeightField>(r.scene->objects.front().shape);
    ASSERT_TRUE(hf.grid);
    ASSERT_EQ(hf.grid->at(0, 1), 30146u);
    ASSERT_EQ(hf.grid->at(1, 1), 39976u);
    ASSERT_EQ(hf.grid->at(1, 2), 39976u);
    const auto shape = HeightFieldShape::create(hf);
    ASSERT_TRUE(shape);
    const double edge = 30146.0 + 0.1 * (39976.0 - 30146.0);
    const double d[4] = {0.1, 0.5, 1.0, 1.5}, pov_z[4] = {0.500001251, 0.500006254, 0.500012508, 0.500018761};
    for (int k = 0; k < 4; ++k) {
        const SurfaceHits h =
            shape->intersect_all({{0.1, (edge + d[k]) / 65536.0, 0.25}, {0.0, 0.0, 1.0}}, 0.0, INFINITY);
        ASSERT_FALSE(h.empty()) << "d = " << d[k];
        EXPECT_NEAR(0.25 + h[0].t, pov_z[k], 1e-9) << "d = " << d[k];
    }
}

TEST(HeightField, ClippedQuadricIsCulledByTheClipBoxAsPovRayDoes) {
    // hfclip.pov: an infinite cylinder quadric clipped by a height field. The field's inside reaches down without
    // end, but POV-Ray tests a clipped top-level object only on rays that meet its bounding box (the clip's box,
    // narrowed to the cylinder's own x and z extent): trace() from POV-Ray 3.7 finds the wall at y = 0.5 and
    // nothing at y = -0.5, and min_extent is <-1, 0.0156, -1> for this field (heights 0.0078 to 0.9883, scale 2).
    parser::ParseOptions options;
    const parser::ParseResult r = parser::parse_string(
        "global_settings { assumed_gamma 1 }\n"
        "quadric { <1, 0, 1>, <0, 0, 0>, <0, 0, 0>, -1\n"
        "  clipped_by { height_field { function 9, 9 { 0.0078 + 0.98 * x } translate <-0.5, 0, -0.5> "
        "scale <6, 2, 6> } } }",
        "hfclip.pov", options);
    ASSERT_TRUE(r.ok());
    const scene::Object& o = r.scene->objects.front();
    auto culled = ShapeInstance::create(o, 0);
    ASSERT_TRUE(culled);
    culled->cull_by_bounds();
    ASSERT_TRUE(culled->world_bounds());
    EXPECT_DOUBLE_EQ(culled->world_bounds()->lower.x, -1.0);
    EXPECT_DOUBLE_EQ(culled->world_bounds()->upper.z, 1.0);
    const auto wall = culled->nearest({0, 0.5, -5}, {0, 0, 1}, 0.0, 1e30);
    ASSERT_TRUE(wall);
    EXPECT_NEAR(wall->t, 4.0, 1e-9);
    EXPECT_FALSE(culled->nearest({0, -0.5, -5}, {0, 0, 1}, 0.0, 1e30));
    // Below the field its inside still holds, so a CSG child (never culled) keeps the wall there.
    const auto child = ShapeInstance::create(o, 0);
    ASSERT_TRUE(child);
    EXPECT_TRUE(child->nearest({0, -0.5, -5}, {0, 0, 1}, 0.0, 1e30));
}

// Every instance holds an AnyShape, as large as its largest kind: a height field keeps its placement on the heap
// so that a scene of 20,000 spheres does not carry 20,000 transforms it never uses (the instance was 712 bytes).
TEST(HeightField, AnInstanceDoesNotCarryItsPlacementInline) {
    EXPECT_LE(sizeof(HeightFieldShape), 160u);
    EXPECT_LE(sizeof(AnyShape), 192u);
    EXPECT_LE(sizeof(ShapeInstance), 560u);
}

}  // namespace
}  // namespace wardray::geometry
