// Feeds every input the fuzzer once tripped on (tests/fuzz/regressions/) and its seed scenes through the
// fuzzer's own entry point, so a fixed finding stays fixed in the ordinary gcc build.
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

// Every regular file of `dir`, recursively for the regression folder, sorted so runs are repeatable.
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

// One input through the entry point: it must return (a crash ends the test binary) within a few seconds.
void feed(const fs::path& file) {
    SCOPED_TRACE(file.string());
    const std::string bytes = read_file(file);
    const auto start = std::chrono::steady_clock::now();
    EXPECT_EQ(LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()), 0);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_LT(seconds, 5.0) << "an input this slow is a hang for the fuzzer";
}

const fs::path kSource(WARDRAY_SOURCE_DIR);

TEST(FuzzRegression, EveryFindingParsesWithoutCrashOrHang) {
    const auto files = files_under(kSource / "tests" / "fuzz" / "regressions", nullptr);
    for (const fs::path& f : files) feed(f);
}

TEST(FuzzRegression, EverySeedSceneParsesWithoutCrashOrHang) {
    std::vector<fs::path> seeds = files_under(kSource / "scenes", ".pov");
    const auto bad = files_under(kSource / "tests" / "bad_input", ".pov");
    seeds.insert(seeds.end(), bad.begin(), bad.end());
    ASSERT_GE(seeds.size(), 40u);
    for (const fs::path& f : seeds) feed(f);
}

}  // namespace
}  // namespace wardray::test
