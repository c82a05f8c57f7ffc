// Feeds every input the whole-pipeline fuzzer tripped on (tests/fuzz/render_regressions/) and the seed scenes
// through render_fuzz's entry point (parse, build, render 8x6, every pixel finite), in the ordinary gcc build.
#include <gtest/gtest.h>

#include <filesystem>
#include <vector>

#include "../fuzz/fuzz_feed.h"

namespace wardray::test {
namespace {

namespace fs = std::filesystem;

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
