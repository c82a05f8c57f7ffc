// Image maps and image_pattern from images with an alpha channel (8- and 16-bit RGBA, grey and alpha), written
// here with libpng, against POV-Ray: the alpha is each texel's transmit, 1 − alpha, with filter all and transmit
// all added to it; image_pattern use_alpha takes that transmit.
#include <png.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <vector>

#include "process.h"
#include "render/film.h"
#include "render/image_metrics.h"

namespace wardray::test {
namespace {

namespace fs = std::filesystem;

/// An 8 x 6 PNG of `channels` (2 grey and alpha, 4 RGBA) at `depth` bits: colours and alpha vary over it.
void write_png(const fs::path& path, int channels, int depth) {
    const int w = 8, h = 6;
    std::FILE* f = std::fopen(path.c_str(), "wb");
    ASSERT_NE(f, nullptr);
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(png);
    png_init_io(png, f);
    png_set_IHDR(png, info, w, h, depth, channels == 4 ? PNG_COLOR_TYPE_RGB_ALPHA : PNG_COLOR_TYPE_GRAY_ALPHA,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    const int bytes = depth / 8;
    const unsigned max = depth == 16 ? 65535u : 255u;
    std::vector<png_byte> row(static_cast<std::size_t>(w) * channels * bytes);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            // Alpha from 0 (left) to 1 (right), lower rows more opaque; colours from the position.
            const double values[4] = {(x + 1.0) / w, (h - y) / double(h), 0.5 + 0.5 * ((x + y) % 2),
                                      std::min(1.0, x / (w - 1.0) + 0.1 * y)};
            for (int c = 0; c < channels; ++c) {
                const double v = channels == 2 && c == 1 ? values[3] : values[c];
                const unsigned q = static_cast<unsigned>(v * max + 0.5);
                png_byte* at = &row[(static_cast<std::size_t>(x) * channels + c) * bytes];
                if (bytes == 2) {
                    at[0] = static_cast<png_byte>(q >> 8);
                    at[1] = static_cast<png_byte>(q & 0xff);
                } else {
                    at[0] = static_cast<png_byte>(q);
                }
            }
        }
        png_write_row(png, row.data());
    }
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    std::fclose(f);
}

// A checkered wall behind four panels: plain, transmit all, filter all with bilinear interpolation, and the
// alpha as a pattern (image_pattern use_alpha), each for one file.
std::string scene_for(const std::string& file) {
    return R"(#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -5> look_at <0, 0, 0> angle 60 }
light_source { <-5, 10, -20> color rgb 1 }
plane { z, 1 pigment { checker rgb <0.9, 0.9, 0.2> rgb <0.1, 0.2, 0.6> scale 0.3 } }
#declare F = ")" + file + R"(";
#macro Panel(X, Y) box { <0, 0, 0>, <1, 1, 0.01> scale <2, 1.5, 1> translate <X, Y, 0> #end
Panel(-2.2, 0.1) pigment { image_map { png F } scale <2, 1.5, 1> } }
Panel(0.2, 0.1) pigment { image_map { png F transmit all 0.3 } scale <2, 1.5, 1> } }
Panel(-2.2, -1.7) pigment { image_map { png F filter all 0.5 interpolate 2 } scale <2, 1.5, 1> } }
Panel(0.2, -1.7) pigment { image_pattern { png F use_alpha } color_map { [0 rgb <1, 0, 0>] [1 rgb <0, 1, 0>] }
                           scale <2, 1.5, 1> } }
)";
}

struct AlphaCase {
    const char* name;
    int channels;
    int depth;
};

class ImageAlpha : public ::testing::TestWithParam<AlphaCase> {};

TEST_P(ImageAlpha, TransmitsAsInPovRay) {
    const AlphaCase& c = GetParam();
    const fs::path dir = fs::path(WARDRAY_TEST_OUTPUT_DIR) / "image_alpha" / c.name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    write_png(dir / "alpha.png", c.channels, c.depth);
    std::ofstream(dir / "scene.pov") << scene_for("alpha.png");
    const std::string common = " +FH +W120 +H90 -A +WT1";
    const auto pov = run_command("povray +Iscene.pov +Opovray.hdr -D -V" + common, dir.string());
    ASSERT_EQ(pov.exit_status, 0) << pov.output;
    const auto ours = run_command(shell_quote(WARDRAY_BINARY) + " scene.pov -o wardray.hdr" + common, dir.string());
    ASSERT_EQ(ours.exit_status, 0) << ours.output;
    EXPECT_EQ(ours.output.find("warning"), std::string::npos) << ours.output;
    std::string error;
    const auto reference = render::read_image(dir / "povray.hdr", error);
    const auto image = render::read_image(dir / "wardray.hdr", error);
    ASSERT_TRUE(reference && image) << error;
    const auto cmp = render::compare_images(*image, *reference);
    ASSERT_TRUE(cmp);
    std::cout << "[ alpha    ] " << c.name << ": rRMSE " << 100 * cmp->rrmse << " %, bad pixels "
              << 100 * cmp->bad_pixel_fraction << " %\n";
    EXPECT_LE(cmp->rrmse, 0.01);
    EXPECT_LE(cmp->bad_pixel_fraction, 0.005);
    EXPECT_EQ(cmp->non_finite, 0u);
}

INSTANTIATE_TEST_SUITE_P(Files, ImageAlpha,
                         ::testing::Values(AlphaCase{"rgba8", 4, 8}, AlphaCase{"rgba16", 4, 16},
                                           AlphaCase{"grey_alpha8", 2, 8}),
                         [](const ::testing::TestParamInfo<AlphaCase>& info) { return info.param.name; });

}  // namespace
}  // namespace wardray::test
