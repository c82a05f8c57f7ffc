// Feeds every input the fuzzer once tripped on (tests/fuzz/regressions/) and its seed scenes through the
// fuzzer's own entry point, so a fixed finding stays fixed in the ordinary gcc build.
#include <gtest/gtest.h>

#include <filesystem>
#include <vector>

#include "fuzz_feed.h"

namespace wardray::test {
namespace {

namespace fs = std::filesystem;

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
