// Parity with POV-Ray: the same .pov file rendered by both, compared as linear HDR (docs/metrics.md).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

#include "process.h"
#include "render/film.h"
#include "render/image_metrics.h"

namespace wardray::test {
namespace {

namespace fs = std::filesystem;

// Direct light only, no antialiasing: the two renderers should agree almost exactly.
constexpr double kMaxRrmse = 0.01;
constexpr double kMaxBadPixels = 0.005;
constexpr int kWidth = 320;
constexpr int kHeight = 240;

struct ParityCase {
    std::string name;
    fs::path scene;
    std::string switches = "-A";  ///< given to both renderers
    std::string frame{};          ///< an animation's frame: both write povray<frame>.hdr, wardray<frame>.hdr
};

// Names the case in test output instead of dumping its bytes.
void PrintTo(const ParityCase& c, std::ostream* os) { *os << c.scene.string() << ' ' << c.switches; }

// A parity scene renders with -A unless its first line says otherwise: `// parity switches: +A0.0 +R9 -J` (a
// stochastic feature compared converged against converged).
std::string parity_switches(const fs::path& scene) {
    std::ifstream in(scene);
    std::string first;
    std::getline(in, first);
    const std::string tag = "// parity switches:";
    if (first.rfind(tag, 0) != 0) return "-A";
    return first.substr(tag.size());
}

// A stochastic parity scene (photons) says its tolerance on its second line: `// parity tolerance: 0.03 0.05`, the
// rRMSE and the bad-pixel fraction, both renderers converged at the scene's own settings.
void parity_tolerance(const fs::path& scene, double& max_rrmse, double& max_bad_pixels) {
    std::ifstream in(scene);
    std::string line;
    std::getline(in, line);
    std::getline(in, line);
    const std::string tag = "// parity tolerance:";
    if (line.rfind(tag, 0) != 0) return;
    std::istringstream values(line.substr(tag.size()));
    values >> max_rrmse >> max_bad_pixels;
}

std::vector<ParityCase> parity_scenes() {
    const fs::path root(WARDRAY_SOURCE_DIR);
    // POV-Ray's antialiasing (method 1) with jitter off samples the same positions in both renderers.
    std::vector<ParityCase> cases{{"default", root / "scenes" / "default.pov"},
                                  {"default_antialiased", root / "scenes" / "default.pov", "+A0.1 +R3 -J"},
                                  {"transforms_antialiased", root / "scenes" / "parity" / "transforms.pov",
                                   "+A0.0 +R2 -J"},
                                  // Frame 4 of 2..6, clock 0.5..2.5: the values each frame gets and its name.
                                  {"animation_frame", root / "scenes" / "parity" / "animation.pov",
                                   "-A +KFI2 +KFF6 +KI0.5 +KF2.5 +SF4 +EF4", "4"},
                                  {"animation_cyclic", root / "scenes" / "parity" / "animation.pov",
                                   "-A +KFF10 +KC +SF10 +EF10", "10"},
                                  // A partial render: the full-size image with the rest black, as POV-Ray writes it.
                                  {"partial_render", root / "scenes" / "parity" / "transforms.pov",
                                   "+A0.0 +R2 -J +SR0.25 +ER150 +SC37 +EC0.8"},
                                  // Method 2, recursive from the pixel corners, down to +R levels.
                                  {"transforms_recursive_aa", root / "scenes" / "parity" / "transforms.pov",
                                   "+A0.1 +AM2 +R3 -J"},
                                  {"fisheye_recursive_aa", root / "scenes" / "parity" / "camera_fisheye.pov",
                                   "+A0.1 +AM2 +R2 -J"}};
    std::vector<fs::path> parity;
    for (const auto& e : fs::directory_iterator(root / "scenes" / "parity"))
        if (e.path().extension() == ".pov") parity.push_back(e.path());
    std::sort(parity.begin(), parity.end());
    for (const fs::path& p : parity) cases.push_back({p.stem().string(), p, parity_switches(p)});
    return cases;
}

class PovrayParity : public ::testing::TestWithParam<ParityCase> {};

TEST_P(PovrayParity, DirectLightMatchesPovRay) {
    // Debian's povray.ini sets its own image size, so both renderers get one explicitly.
    const ParityCase& c = GetParam();
    const fs::path dir = fs::path(WARDRAY_TEST_OUTPUT_DIR) / "parity" / c.name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    // POV-Ray's I/O restrictions allow writing only below the current folder: run both renderers there.
    fs::copy_file(c.scene, dir / c.scene.filename());
    const std::string size = " +W" + std::to_string(kWidth) + " +H" + std::to_string(kHeight);
    const std::string scene = shell_quote(c.scene.filename().string());

    const auto pov = run_command("povray +I" + scene + " +Opovray.hdr +FH -D -V +WT2 " + c.switches + size,
                                 dir.string());
    ASSERT_EQ(pov.exit_status, 0) << "POV-Ray failed:\n" << pov.output;
    const auto ours = run_command(
        shell_quote(WARDRAY_BINARY) + " +I" + scene + " +Owardray.hdr +FH -D +WT2 " + c.switches + size, dir.string());
    ASSERT_EQ(ours.exit_status, 0) << "wardray failed:\n" << ours.output;
    for (const char* name : {"povray", "wardray"})
        if (!c.frame.empty()) fs::rename(dir / (name + c.frame + ".hdr"), dir / (std::string(name) + ".hdr"));

    std::string error;
    const auto reference = render::read_image(dir / "povray.hdr", error);
    ASSERT_TRUE(reference) << error;
    const auto image = render::read_image(dir / "wardray.hdr", error);
    ASSERT_TRUE(image) << error;
    const auto cmp = render::compare_images(*image, *reference);
    ASSERT_TRUE(cmp) << "image sizes differ";

    std::ostringstream figures;
    figures << std::fixed << std::setprecision(4) << c.name << ": rRMSE " << 100 * cmp->rrmse << " %, bad pixels "
            << 100 * cmp->bad_pixel_fraction << " %, non-finite " << cmp->non_finite;
    RecordProperty("rrmse", std::to_string(cmp->rrmse));
    RecordProperty("bad_pixel_fraction", std::to_string(cmp->bad_pixel_fraction));
    std::cout << "[ parity   ] " << figures.str() << "\n";

    double max_rrmse = kMaxRrmse, max_bad_pixels = kMaxBadPixels;
    parity_tolerance(c.scene, max_rrmse, max_bad_pixels);
    const bool pass =
        cmp->rrmse <= max_rrmse && cmp->bad_pixel_fraction <= max_bad_pixels && cmp->non_finite == 0;
    if (!pass) {
        // Leave the image, the reference and a difference image beside each other for a person to look at.
        render::write_image(render::difference_image(*image, *reference), dir / "difference.png",
                            render::ImageFormat::Png);
        render::write_image(*image, dir / "wardray.png", render::ImageFormat::Png);
        render::write_image(*reference, dir / "povray.png", render::ImageFormat::Png);
    }
    EXPECT_LE(cmp->rrmse, max_rrmse) << figures.str() << "; images in " << dir;
    EXPECT_LE(cmp->bad_pixel_fraction, max_bad_pixels) << figures.str() << "; images in " << dir;
    EXPECT_EQ(cmp->non_finite, 0u);
}

INSTANTIATE_TEST_SUITE_P(Scenes, PovrayParity, ::testing::ValuesIn(parity_scenes()),
                         [](const ::testing::TestParamInfo<ParityCase>& info) { return info.param.name; });

}  // namespace
}  // namespace wardray::test
