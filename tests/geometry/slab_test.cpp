// The slab (ray-box) test shared by the scene's Embree entry point and the bounded shapes.
#include <gtest/gtest.h>

#include "geometry/shape.h"

namespace wardray::geometry {
namespace {

const Vec3 kLower{0.0, 0.0, 0.0};
const Vec3 kUpper{1.0, 2.0, 4.0};

TEST(SlabInterval, LineThroughTheBoxEntersAndLeavesAtItsFaces) {
    double s0 = 0.0, s1 = 0.0;
    ASSERT_TRUE(slab_interval(kLower, kUpper, Vec3{-2.0, 0.5, 0.5}, Vec3{1.0, 0.0, 0.0}, s0, s1));
    EXPECT_DOUBLE_EQ(s0, 2.0);
    EXPECT_DOUBLE_EQ(s1, 3.0);
    // Backwards along the axis the faces swap roles; the parameters stay ordered.
    ASSERT_TRUE(slab_interval(kLower, kUpper, Vec3{0.5, 0.5, 6.0}, Vec3{0.0, 0.0, -2.0}, s0, s1));
    EXPECT_DOUBLE_EQ(s0, 1.0);
    EXPECT_DOUBLE_EQ(s1, 3.0);
}

TEST(SlabInterval, ParallelLineOutsideASlabMisses) {
    double s0 = 0.0, s1 = 0.0;
    EXPECT_FALSE(slab_interval(kLower, kUpper, Vec3{0.5, 3.0, 0.5}, Vec3{1.0, 0.0, 0.0}, s0, s1));
    // Inside that slab the parallel axis constrains nothing.
    ASSERT_TRUE(slab_interval(kLower, kUpper, Vec3{0.5, 1.0, 0.5}, Vec3{1.0, 0.0, 0.0}, s0, s1));
    EXPECT_DOUBLE_EQ(s0, -0.5);
    EXPECT_DOUBLE_EQ(s1, 0.5);
}

TEST(SlabInterval, DiagonalLinePastACornerMisses) {
    double s0 = 0.0, s1 = 0.0;
    // Crosses x ∈ [0, 1] for s ∈ [3, 4] but y ∈ [0, 2] only for s ∈ [0, 2].
    EXPECT_FALSE(slab_interval(kLower, kUpper, Vec3{-3.0, 0.0, 1.0}, Vec3{1.0, 1.0, 0.0}, s0, s1));
}

}  // namespace
}  // namespace wardray::geometry
