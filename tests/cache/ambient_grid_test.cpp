// Tests of AmbientGrid: the ambient cube of a cell from its records' normals, cells without records, and the
// cache's grids for --gi-lookup-sampling.
#include "cache/ambient_grid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "cache/irradiance_cache.h"

namespace wardray::cache {
namespace {

IrradianceRecord facing(const Vec3& p, const Vec3& normal, const Vec3& irradiance, int depth = 0) {
    IrradianceRecord r;
    r.position = p;
    r.normal = normal;
    r.irradiance = irradiance;
    r.radius = 1.0;
    r.depth = depth;
    return r;
}

void expect_near(const Vec3& got, const Vec3& want) {
    EXPECT_NEAR(got.x, want.x, 1e-12);
    EXPECT_NEAR(got.y, want.y, 1e-12);
    EXPECT_NEAR(got.z, want.z, 1e-12);
}

TEST(AmbientGrid, EmptyWithoutRecordsOrWidth) {
    RecordOctree tree;
    AmbientGrid grid;
    grid.build(tree, 1.0);
    EXPECT_TRUE(grid.empty());
    Vec3 out{7, 7, 7};
    EXPECT_FALSE(grid.estimate({0, 0, 0}, {0, 1, 0}, out));
    EXPECT_EQ(out.x, 7.0);
    tree.insert(facing({0.5, 0.5, 0.5}, {0, 1, 0}, {1, 1, 1}));
    for (const double width : {0.0, -1.0, std::numeric_limits<double>::infinity(), std::nan("")}) {
        grid.build(tree, width);
        EXPECT_TRUE(grid.empty()) << width;
    }
}

TEST(AmbientGrid, EachFaceIsTheMeanOfTheRecordsFacingIt) {
    RecordOctree tree;
    // One cell, [0, 2)^3: two records facing up, one facing +x, one facing -x at 45 degrees to -y.
    tree.insert(facing({0.5, 0.5, 0.5}, {0, 1, 0}, {1, 2, 3}));
    tree.insert(facing({1.5, 0.5, 0.5}, {0, 1, 0}, {3, 2, 1}));
    tree.insert(facing({0.5, 1.5, 0.5}, {1, 0, 0}, {4, 4, 4}));
    const double h = std::sqrt(0.5);
    tree.insert(facing({0.5, 1.5, 1.5}, {-h, -h, 0}, {8, 0, 0}));
    AmbientGrid grid;
    grid.build(tree, 2.0);
    EXPECT_EQ(grid.cell_count(), 1u);
    Vec3 out;
    ASSERT_TRUE(grid.estimate({1, 1, 1}, {0, 1, 0}, out));
    expect_near(out, {2, 2, 2});
    ASSERT_TRUE(grid.estimate({0.1, 1.9, 0.2}, {1, 0, 0}, out));
    expect_near(out, {4, 4, 4});
    ASSERT_TRUE(grid.estimate({1, 1, 1}, {-1, 0, 0}, out));
    expect_near(out, {8, 0, 0});
    // Between up and +x: half of each face.
    ASSERT_TRUE(grid.estimate({1, 1, 1}, {h, h, 0}, out));
    expect_near(out, {3, 3, 3});
    // No record faces +z: the cell's mean of all four.
    ASSERT_TRUE(grid.estimate({1, 1, 1}, {0, 0, 1}, out));
    expect_near(out, {4, 2, 2});
}

TEST(AmbientGrid, OnlyCellsWithRecordsAnswer) {
    RecordOctree tree;
    tree.insert(facing({0.5, 0.5, 0.5}, {0, 1, 0}, {1, 1, 1}));
    tree.insert(facing({-3.5, 0.5, 10.5}, {0, 1, 0}, {2, 2, 2}));
    AmbientGrid grid;
    grid.build(tree, 1.0);
    EXPECT_EQ(grid.cell_count(), 2u);
    Vec3 out;
    ASSERT_TRUE(grid.estimate({-3.01, 0.99, 10.0}, {0, 1, 0}, out));
    expect_near(out, {2, 2, 2});
    EXPECT_FALSE(grid.estimate({1.5, 0.5, 0.5}, {0, 1, 0}, out));
    EXPECT_FALSE(grid.estimate({-0.5, 0.5, 0.5}, {0, 1, 0}, out));
    EXPECT_FALSE(grid.estimate({std::nan(""), 0.5, 0.5}, {0, 1, 0}, out));
    EXPECT_FALSE(grid.estimate({1e300, 0.5, 0.5}, {0, 1, 0}, out));
}

TEST(AmbientGrid, TheCacheKeepsGridsOfDeeperBouncesOnlyWhenAsked) {
    IrradianceCache cache(2, 2.0);
    cache.add(facing({0.5, 0, 0.5}, {0, 1, 0}, {1, 1, 1}, 0));
    cache.add(facing({0.5, 0, 0.5}, {0, 1, 0}, {2, 2, 2}, 1));
    Vec3 out;
    cache.begin_pass(1);
    EXPECT_FALSE(cache.ambient({0.5, 0, 0.5}, {0, 1, 0}, 1, out));
    cache.end_pass();
    cache.set_ambient_grids(true);
    EXPECT_FALSE(cache.ambient({0.5, 0, 0.5}, {0, 1, 0}, 0, out)) << "depth 0 is never estimated";
    ASSERT_TRUE(cache.ambient({0.5, 0, 0.5}, {0, 1, 0}, 1, out));
    expect_near(out, {2, 2, 2});
    // Within a pass the grids follow the merges, not the tiles' own records.
    cache.begin_pass(1);
    cache.tile(0).add(facing({40.5, 0, 0.5}, {0, 1, 0}, {3, 3, 3}, 1));
    EXPECT_FALSE(cache.tile(0).ambient({40.5, 0, 0.5}, {0, 1, 0}, 1, out));
    cache.merge_tiles({0});
    ASSERT_TRUE(cache.tile(0).ambient({40.5, 0, 0.5}, {0, 1, 0}, 1, out));
    expect_near(out, {3, 3, 3});
    cache.end_pass();
    cache.set_ambient_grids(false);
    EXPECT_FALSE(cache.ambient({0.5, 0, 0.5}, {0, 1, 0}, 1, out));
}

}  // namespace
}  // namespace wardray::cache
