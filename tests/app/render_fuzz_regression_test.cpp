// Feeds every input the whole-pipeline fuzzer tripped on (tests/fuzz/render_regressions/) and the seed scenes
// through render_fuzz's entry point (parse, build, render 8x6, every pixel finite), in the ordinary gcc build.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace wardray::test {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> files_under(const fs::path& dir, const char* extension) {
    std::vector<fs::path> files;
    if (!fs::is_directory(dir)) return files;
    for (const auto& e : fs::recursive_directory_iterator(dir))
        if (e.is_regular_file() && (extension == nullptr || e.path().extension() == extension))
            files.push_back(e.path());
    std::sort(files.begin(), files.end());
    return files;
}

std::string read_file(const fs::path& p) {
    std::ifstream f(p, std::ios::binary);
    std::stringstream s;
    s << f.rdbuf();
    return s.str();
}

// One input through the entry point: it must return (a crash or a non-finite pixel aborts) within seconds.
void feed(const fs::path& file) {
    SCOPED_TRACE(file.string());
    const std::string bytes = read_file(file);
    const auto start = std::chrono::steady_clock::now();
    EXPECT_EQ(LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()), 0);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_LT(seconds, 5.0) << "an input this slow is a hang for the fuzzer";
}

const fs::path kSource(WARDRAY_SOURCE_DIR);

TEST(RenderFuzzRegression, EveryFindingRendersFiniteWithoutCrashOrHang) {
    const auto files = files_under(kSource / "tests" / "fuzz" / "render_regressions", nullptr);
    ASSERT_FALSE(files.empty());
    for (const fs::path& f : files) feed(f);
}

TEST(RenderFuzzRegression, EverySeedSceneRendersFinite) {
    const auto seeds = files_under(kSource / "scenes", ".pov");
    ASSERT_GE(seeds.size(), 20u);
    for (const fs::path& f : seeds) feed(f);
}

}  // namespace
}  // namespace wardray::test
