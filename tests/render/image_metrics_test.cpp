// Tests of the image metrics against hand-computed values.
#include "render/image_metrics.h"

#include <gtest/gtest.h>

#include <cmath>

namespace wardray::render {
namespace {

Film constant(int w, int h, const Vec3& c) {
    Film f(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) f.set_pixel(x, y, c);
    return f;
}

TEST(CompareImages, IdenticalImagesHaveNoError) {
    const Film a = constant(5, 4, {0.2, 0.4, 0.6});
    const auto r = compare_images(a, a);
    ASSERT_TRUE(r);
    EXPECT_DOUBLE_EQ(r->rrmse, 0.0);
    EXPECT_DOUBLE_EQ(r->bad_pixel_fraction, 0.0);
    EXPECT_EQ(r->non_finite, 0u);
}

TEST(CompareImages, RelativeRmsOfAUniformOffset) {
    // I = 1.1 R everywhere: rRMSE = 0.1 exactly; luminance differs by 10 % + 0 < 10 % + 1 % of the mean: not bad.
    const auto r = compare_images(constant(4, 4, {1.1, 1.1, 1.1}), constant(4, 4, {1, 1, 1}));
    ASSERT_TRUE(r);
    EXPECT_NEAR(r->rrmse, 0.1, 1e-6);
    EXPECT_DOUBLE_EQ(r->bad_pixel_fraction, 0.0);
}

TEST(CompareImages, BadPixelsAndNonFinite) {
    Film ref = constant(10, 1, {1, 1, 1});
    Film img = ref;
    img.set_pixel(0, 0, {1.2, 1.2, 1.2});  // 20 % off: bad
    img.set_pixel(1, 0, {NAN, 1, 1});      // not finite: bad and counted
    const auto r = compare_images(img, ref);
    ASSERT_TRUE(r);
    EXPECT_DOUBLE_EQ(r->bad_pixel_fraction, 0.2);
    EXPECT_EQ(r->non_finite, 1u);
}

TEST(CompareImages, SizesMustMatch) {
    EXPECT_FALSE(compare_images(constant(2, 2, {}), constant(2, 3, {})).has_value());
}

TEST(DifferenceImage, BlackWhereEqualBrightWhereBad) {
    Film ref = constant(2, 1, {1, 1, 1});
    Film img = ref;
    img.set_pixel(1, 0, {3, 3, 3});
    const Film d = difference_image(img, ref);
    EXPECT_EQ(d.pixel(0, 0), (Vec3{0, 0, 0}));
    EXPECT_GT(d.pixel(1, 0).x, 0.9);  // far past the tolerance: red
}

}  // namespace
}  // namespace wardray::render
