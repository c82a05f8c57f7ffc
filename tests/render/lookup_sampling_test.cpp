// --gi-lookup-sampling: the same image for any thread count, and an image that converges where every lookup's does.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iostream>

#include "process.h"
#include "render/film.h"
#include "render/image_metrics.h"

namespace {

namespace fs = std::filesystem;
using wardray::test::run_command;
using wardray::test::shell_quote;

// A closed room lit by one light: most of its light reaches the camera after two bounces, so the gathers' hits at
// depth 1 look the cache up.
const char* kRoom = R"(#version 3.7;
global_settings { assumed_gamma 1.0
  radiosity { count Count error_bound 0.4 pretrace_start 0.08 pretrace_end 0.02 recursion_limit 2 nearest_count 8 } }
camera { location <0, 1.2, -2.6> look_at <0, 0.9, 0> angle 70 }
light_source { <0.6, 2.2, 0.4> color rgb 1.5 }
box { <-2, 0, -3>, <2, 2.5, 2> hollow pigment { rgb 0.75 } finish { diffuse 0.8 } }
box { <-2, 0, -3>, <-1.99, 2.5, 2> pigment { rgb <0.8, 0.2, 0.1> } finish { diffuse 0.8 } }
box { <-0.6, 0, -0.2>, <0.2, 0.9, 0.6> rotate 20 * y pigment { rgb 0.7 } finish { diffuse 0.8 } }
)";

fs::path work_dir(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / "wardray_lookup_sampling" / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

int render(const fs::path& dir, const std::string& args) {
    const auto r = run_command(shell_quote(WARDRAY_BINARY) + " room.pov +W96 +H72 -A " + args, dir.string());
    EXPECT_EQ(r.exit_status, 0) << r.output;
    return r.exit_status;
}

std::string bytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(LookupSampling, SameImageForAnyThreadCount) {
    const fs::path dir = work_dir("threads");
    std::ofstream(dir / "room.pov") << kRoom;
    ASSERT_EQ(render(dir, "Declare=Count=60 --gi-lookup-sampling 4 +WT1 -o one.exr"), 0);
    // The default is K = 4: the same image as asking for it.
    ASSERT_EQ(render(dir, "Declare=Count=60 +WT2 -o two.exr"), 0);
    ASSERT_EQ(render(dir, "Declare=Count=60 --gi-lookup-sampling 1 -o every.exr +WT2"), 0);
    EXPECT_EQ(bytes(dir / "one.exr"), bytes(dir / "two.exr"));
    // The option does something: the deeper lookups are sampled, so the image is not the plain one.
    EXPECT_NE(bytes(dir / "two.exr"), bytes(dir / "every.exr"));
}

// A control variate changes the noise, not the mean: at a count where both renders are close to converged, the
// sampled image is as near the plain one as two plain renders of different seeds are, within a margin.
TEST(LookupSampling, ConvergesWhereEveryLookupConverges) {
    const fs::path dir = work_dir("converges");
    std::ofstream(dir / "room.pov") << kRoom;
    ASSERT_EQ(render(dir, "Declare=Count=400 +WT2 --gi-lookup-sampling 1 -o plain.exr"), 0);
    ASSERT_EQ(render(dir, "Declare=Count=400 +WT2 --gi-lookup-sampling 1 --seed 7 -o seeded.exr"), 0);
    ASSERT_EQ(render(dir, "Declare=Count=400 +WT2 --gi-lookup-sampling 8 -o sampled.exr"), 0);
    std::string error;
    const auto plain = wardray::render::read_image(dir / "plain.exr", error);
    const auto seeded = wardray::render::read_image(dir / "seeded.exr", error);
    const auto sampled = wardray::render::read_image(dir / "sampled.exr", error);
    ASSERT_TRUE(plain && seeded && sampled) << error;
    const auto seeds = wardray::render::compare_images(*seeded, *plain);
    const auto ours = wardray::render::compare_images(*sampled, *plain);
    ASSERT_TRUE(seeds && ours);
    std::cout << "[ sampling ] rRMSE to the plain render: another seed " << 100 * seeds->rrmse
              << " %, one lookup in 8 " << 100 * ours->rrmse << " %\n";
    EXPECT_LT(ours->rrmse, 2.0 * seeds->rrmse + 0.005) << "images in " << dir;
}

}  // namespace
