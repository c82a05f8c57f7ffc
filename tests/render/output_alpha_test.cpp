// Output_Alpha (+UA): the PNG's alpha channel and associated colours against POV-Ray's own +UA +FN image.
#include <gtest/gtest.h>
#include <png.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <vector>

#include "process.h"

namespace wardray::test {
namespace {

namespace fs = std::filesystem;

// An 8-bit RGBA image read with libpng's simplified API (an RGB file gets alpha 255); empty when unreadable.
struct Rgba8 {
    int width = 0, height = 0;
    int channels = 0;  ///< as stored in the file: 3 or 4
    std::vector<unsigned char> pixels;
};

Rgba8 read_rgba(const fs::path& file) {
    Rgba8 out;
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&image, file.c_str())) return out;
    out.channels = (image.format & PNG_FORMAT_FLAG_ALPHA) ? 4 : 3;
    image.format = PNG_FORMAT_RGBA;
    out.pixels.resize(PNG_IMAGE_SIZE(image));
    if (!png_image_finish_read(&image, nullptr, out.pixels.data(), 0, nullptr)) return {};
    out.width = static_cast<int>(image.width);
    out.height = static_cast<int>(image.height);
    return out;
}

fs::path work_dir(const std::string& name) {
    const fs::path dir = fs::path(WARDRAY_TEST_OUTPUT_DIR) / "alpha" / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

// An opaque sphere with a highlight, a glass sphere (filter, refracting) and a half-transmitting floor over no
// background: the alpha channel has fully transparent, partly transparent and opaque pixels, and edges to antialias.
const char* kAlphaScene = R"(#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1, -4> look_at <0, 0.5, 0> }
light_source { <3, 5, -4> color rgb 1 }
sphere { <-0.8, 0.6, 0>, 0.6 pigment { color rgb <1, 0.3, 0.2> } finish { phong 0.8 } }
sphere { <0.8, 0.6, 0>, 0.6 pigment { color rgbf <0.6, 0.9, 1, 0.7> } interior { ior 1.3 } }
box { <-2, -0.1, -1>, <2, 0, 2> pigment { color rgbt <0.8, 0.8, 0.8, 0.5> } }
)";

TEST(OutputAlpha, PngAlphaAndColoursMatchPovRay) {
    const fs::path dir = work_dir("scene");
    std::ofstream(dir / "scene.pov") << kAlphaScene;
    const std::string common = " +FN +UA +W160 +H120 +A0.1 -J +WT1";
    const auto pov = run_command("povray +Iscene.pov +Opovray.png -D -V" + common, dir.string());
    ASSERT_EQ(pov.exit_status, 0) << pov.output;
    const auto ours = run_command(shell_quote(WARDRAY_BINARY) + " scene.pov -o wardray.png" + common, dir.string());
    ASSERT_EQ(ours.exit_status, 0) << ours.output;
    EXPECT_EQ(ours.output.find("warning"), std::string::npos) << ours.output;
    const Rgba8 ref = read_rgba(dir / "povray.png");
    const Rgba8 img = read_rgba(dir / "wardray.png");
    ASSERT_EQ(ref.channels, 4);
    ASSERT_EQ(img.channels, 4);
    ASSERT_EQ(img.width, ref.width);
    ASSERT_EQ(img.height, ref.height);
    std::size_t transparent = 0, partial = 0, alpha_off = 0, colour_off = 0;
    const std::size_t n = ref.pixels.size() / 4;
    for (std::size_t i = 0; i < n; ++i) {
        const unsigned char* r = &ref.pixels[4 * i];
        const unsigned char* m = &img.pixels[4 * i];
        transparent += r[3] == 0;
        partial += r[3] > 0 && r[3] < 255;
        if (std::abs(r[3] - m[3]) > 2) ++alpha_off;
        // Straight colours are meaningless where nothing is opaque.
        if (r[3] > 0)
            for (int c = 0; c < 3; ++c)
                if (std::abs(r[c] - m[c]) > 3) {
                    ++colour_off;
                    break;
                }
    }
    // The scene exercises all three kinds of pixel.
    EXPECT_GT(transparent, n / 4);
    EXPECT_GT(partial, n / 20);
    // Tolerances: 8-bit levels off by more than 2 (alpha) or 3 (colour) on at most 0.5 % of the pixels.
    EXPECT_LE(alpha_off, n / 200) << "alpha differs on " << alpha_off << " of " << n << " pixels";
    EXPECT_LE(colour_off, n / 200) << "colour differs on " << colour_off << " of " << n << " pixels";
}

TEST(OutputAlpha, WithoutUaThePngHasNoAlphaAndAThreePointSevenBackgroundStaysOpaque) {
    const fs::path dir = work_dir("opaque");
    // POV-Ray 3.7: a background colour without transmit is opaque even with +UA.
    std::ofstream(dir / "scene.pov") << kAlphaScene << "background { color rgb <0.2, 0.3, 0.4> }\n";
    const std::string wardray = shell_quote(WARDRAY_BINARY) + " scene.pov +FN +W40 +H30 -A +WT1";
    ASSERT_EQ(run_command(wardray + " -o plain.png", dir.string()).exit_status, 0);
    ASSERT_EQ(run_command(wardray + " +UA -o alpha.png", dir.string()).exit_status, 0);
    const Rgba8 plain = read_rgba(dir / "plain.png");
    const Rgba8 alpha = read_rgba(dir / "alpha.png");
    EXPECT_EQ(plain.channels, 3);
    ASSERT_EQ(alpha.channels, 4);
    ASSERT_EQ(alpha.pixels.size(), plain.pixels.size());
    // The top-left corner shows the background: opaque, and the colour the render without alpha has.
    EXPECT_EQ(alpha.pixels[3], 255);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(alpha.pixels[c], plain.pixels[c]);
}

}  // namespace
}  // namespace wardray::test
