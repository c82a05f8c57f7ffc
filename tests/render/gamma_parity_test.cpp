// Gamma parity with POV-Ray: small scenes with assumed_gamma other than 1, or none in a 3.6 scene, rendered by
// both programs; the 8-bit PNGs must agree within one level and the linear HDR files as docs/metrics.md says.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "process.h"
#include "render/film.h"
#include "render/image_metrics.h"
#include "render/image_writers.h"

namespace wardray::test {
namespace {

namespace fs = std::filesystem;

struct GammaCase {
    std::string name;
    std::string header;    ///< #version and global_settings
    std::string switches;  ///< given to both renderers
    bool srgb = true;      ///< some colours as srgb (which needs assumed_gamma)
};

void PrintTo(const GammaCase& c, std::ostream* os) { *os << c.name; }

// Colours across the range, a highlight, a shadow and ambient light: each gamma curve changes all of them.
std::string scene_text(const GammaCase& c) {
    const std::string s = c.srgb ? "srgb" : "rgb";
    return c.header + R"(
camera { location <0, 1.2, -4> look_at <0, 0.6, 0> }
light_source { <3, 5, -4> color rgb 1 }
plane { y, 0 pigment { checker rgb 0.8, )" + s + R"( <0.2, 0.3, 0.6> } finish { ambient 0.1 } }
sphere { <-0.7, 0.6, 0>, 0.6 pigment { rgb <0.9, 0.3, 0.1> } finish { phong 0.6 ambient 0.2 } }
sphere { <0.8, 0.5, 0.3>, 0.5 pigment { )" + s + R"( <0.25, 0.75, 0.5> } finish { ambient 0.05 diffuse 0.8 } }
)";
}

// The raw 8-bit values of a PNG (read_image decodes sRGB; encoding again gives the stored bytes back).
std::vector<unsigned char> png_bytes(const render::Film& film) {
    std::vector<unsigned char> bytes;
    for (float v : film.data()) bytes.push_back(render::encode_srgb8(static_cast<float>(render::srgb_encode(v))));
    return bytes;
}

class GammaParity : public ::testing::TestWithParam<GammaCase> {};

TEST_P(GammaParity, PngWithinOneLevelAndHdrMatchPovRay) {
    const GammaCase& c = GetParam();
    const fs::path dir = fs::path(WARDRAY_TEST_OUTPUT_DIR) / "gamma_parity" / c.name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::ofstream(dir / "scene.pov") << scene_text(c);
    const std::string common = " +W96 +H72 +WT1 " + c.switches;
    for (const char* ext : {"png", "hdr"}) {
        const std::string format = ext == std::string("png") ? " +FN" : " +FH";
        // POV-Ray may only write below its working folder: both run in the test's folder.
        const auto pov = run_command("povray +Iscene.pov +Opovray." + std::string(ext) + format + " -D -V" + common,
                                     dir.string());
        ASSERT_EQ(pov.exit_status, 0) << "POV-Ray failed:\n" << pov.output;
        const auto ours = run_command(shell_quote(WARDRAY_BINARY) + " scene.pov -o wardray." + ext + format + common,
                                      dir.string());
        ASSERT_EQ(ours.exit_status, 0) << "wardray failed:\n" << ours.output;
    }
    std::string error;
    const auto ref_png = render::read_image(dir / "povray.png", error);
    const auto our_png = render::read_image(dir / "wardray.png", error);
    const auto ref_hdr = render::read_image(dir / "povray.hdr", error);
    const auto our_hdr = render::read_image(dir / "wardray.hdr", error);
    ASSERT_TRUE(ref_png && our_png && ref_hdr && our_hdr) << error;

    const std::vector<unsigned char> a = png_bytes(*our_png), b = png_bytes(*ref_png);
    ASSERT_EQ(a.size(), b.size());
    std::size_t within = 0;
    for (std::size_t p = 0; p + 2 < a.size(); p += 3) {
        bool ok = true;
        for (int k = 0; k < 3; ++k) ok = ok && std::abs(int(a[p + k]) - int(b[p + k])) <= 1;
        within += ok;
    }
    const double fraction = static_cast<double>(within) / static_cast<double>(a.size() / 3);
    const auto cmp = render::compare_images(*our_hdr, *ref_hdr);
    ASSERT_TRUE(cmp);
    std::cout << "[ gamma    ] " << c.name << ": PNG within one level " << 100 * fraction << " %, HDR rRMSE "
              << 100 * cmp->rrmse << " %, bad " << 100 * cmp->bad_pixel_fraction << " %\n";
    EXPECT_GE(fraction, 0.99) << "images in " << dir;
    EXPECT_LE(cmp->rrmse, 0.01) << "images in " << dir;
    EXPECT_LE(cmp->bad_pixel_fraction, 0.005) << "images in " << dir;
}

INSTANTIATE_TEST_SUITE_P(
    Scenes, GammaParity,
    ::testing::Values(
        // Antialiasing compares colours after decoding the working gamma: same pixels refined in both.
        GammaCase{"assumed_2_2_in_3_6_antialiased", "#version 3.6;\nglobal_settings { assumed_gamma 2.2 }\n",
                  "+A0.1 -J"},
        GammaCase{"assumed_1_8_file_gamma_1", "#version 3.7;\nglobal_settings { assumed_gamma 1.8 }\n",
                  "-A File_Gamma=1.0"},
        // srgb needs an assumed_gamma: the no-gamma scene gives those colours with rgb.
        GammaCase{"no_gamma_3_6", "#version 3.6;\n", "-A Display_Gamma=1.8", false}),
    [](const ::testing::TestParamInfo<GammaCase>& info) { return info.param.name; });

}  // namespace
}  // namespace wardray::test
