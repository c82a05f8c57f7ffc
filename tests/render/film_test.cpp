// Tests of image files: formats, POV-Ray's 8-bit encoding, and writes that never leave partial files.
#include "render/film.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace wardray::render {
namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
    const fs::path dir = fs::path(WARDRAY_TEST_OUTPUT_DIR) / "film_test";
    fs::create_directories(dir);
    return dir / name;
}

Film gradient(int w, int h) {
    Film f(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) f.set_pixel(x, y, {x / double(w), y / double(h), 2.5});
    return f;
}

TEST(Film, FormatFromExtension) {
    EXPECT_EQ(format_from_extension("a.png"), ImageFormat::Png);
    EXPECT_EQ(format_from_extension("a.EXR"), ImageFormat::Exr);
    EXPECT_EQ(format_from_extension("a.hdr"), ImageFormat::Hdr);
    EXPECT_FALSE(format_from_extension("a.tga").has_value());
}

// A film with long runs of equal pixels (run-length encoded in .hdr) beside a gradient.
Film runs_and_gradient(int w, int h) {
    Film f = gradient(w, h);
    for (int y = 0; y < h; y += 2)
        for (int x = 0; x < w; ++x) f.set_pixel(x, y, {0.25, 0.5, 4.0});
    return f;
}

TEST(Film, LinearFormatsRoundTrip) {
    // 17 wide: run-length scanlines; 5 wide: flat scanlines (RLE needs 8 or more); 300 wide: runs over 127.
    for (const auto& [w, h] : {std::pair{17, 9}, std::pair{5, 3}, std::pair{300, 4}})
    for (ImageFormat format : {ImageFormat::Exr, ImageFormat::Hdr}) {
        const Film f = runs_and_gradient(w, h);
        const fs::path p = scratch("round" + std::to_string(w) + extension_of(format));
        ASSERT_FALSE(write_image(f, p, format).has_value());
        std::string error;
        const auto back = read_image(p, error);
        ASSERT_TRUE(back) << error;
        ASSERT_EQ(back->width(), w);
        ASSERT_EQ(back->height(), h);
        for (int y = 0; y < h; ++y) {
            for (int x = 0; x < w; ++x) {
                const Vec3 v = f.pixel(x, y);
                // RGBE shares one exponent per pixel: a channel is exact to 1/128 of the pixel's largest channel.
                // Half floats keep 11 significant bits per channel.
                const double largest = std::max({v.x, v.y, v.z});
                for (int c = 0; c < 3; ++c) {
                    const double tolerance = format == ImageFormat::Hdr ? largest / 128.0 : v[c] / 1024.0 + 1e-7;
                    EXPECT_NEAR(back->pixel(x, y)[c], v[c], tolerance) << x << ',' << y << ',' << c;
                }
            }
        }
    }
}

TEST(Film, PngIsSrgbEncodedAndRoundedAsPovRayDoes) {
    Film f(4, 1);
    f.set_pixel(0, 0, {0.0, 0.5, 1.0});
    f.set_pixel(1, 0, {2.0, -1.0, 0.0031308});
    f.set_pixel(2, 0, {0.2140, 0.2140, 0.2140});  // sRGB 0.5: 127.5 rounds up to 128
    f.set_pixel(3, 0, {NAN, INFINITY, 0.0});
    const fs::path p = scratch("encoded.png");
    ASSERT_FALSE(write_image(f, p, ImageFormat::Png).has_value());
    std::string error;
    const auto back = read_image(p, error);
    ASSERT_TRUE(back) << error;
    auto byte = [&](int x, int c) { return std::lround(srgb_encode(back->pixel(x, 0)[c]) * 255.0); };
    EXPECT_EQ(byte(0, 0), 0);
    EXPECT_EQ(byte(0, 1), static_cast<long>(std::floor(srgb_encode(0.5) * 255.0 + 0.5)));
    EXPECT_EQ(byte(0, 2), 255);
    EXPECT_EQ(byte(1, 0), 255);  // clipped
    EXPECT_EQ(byte(1, 1), 0);
    EXPECT_EQ(byte(2, 0), static_cast<long>(std::floor(srgb_encode(0.2140) * 255.0 + 0.5)));
    EXPECT_EQ(byte(3, 0), 0);  // not a number is written as black, never as garbage
}

TEST(Film, FailedWriteLeavesNoFileAndKeepsTheOldOne) {
    const fs::path missing_dir = scratch("no/such/folder/out.png");
    EXPECT_TRUE(write_image(gradient(2, 2), missing_dir, ImageFormat::Png).has_value());
    EXPECT_FALSE(fs::exists(missing_dir));

    const fs::path dir = scratch("only_final");
    fs::remove_all(dir);
    fs::create_directories(dir);
    ASSERT_FALSE(write_image(gradient(3, 3), dir / "a.png", ImageFormat::Png).has_value());
    std::size_t files = 0;
    for (const auto& e : fs::directory_iterator(dir)) {
        ++files;
        EXPECT_EQ(e.path().filename(), "a.png");  // no temporary left behind
    }
    EXPECT_EQ(files, 1u);
}

}  // namespace
}  // namespace wardray::render
