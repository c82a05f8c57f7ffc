// Tests of animations and partial renders: frames and clocks as povray 3.7 makes them, a partial render equal to
// the same region of the full render, frames equal to stills at their clock.
#include "app/animation.h"

#include <gtest/gtest.h>

#include <fstream>

#include "app/app.h"
#include "app/partial_render.h"
#include "render/film.h"

namespace wardray::app {
namespace {

namespace fs = std::filesystem;

std::vector<Frame> frames_of(const AnimationOptions& a, const fs::path& output = "scene.png") {
    auto r = plan_frames(a, output);
    EXPECT_TRUE(std::holds_alternative<std::vector<Frame>>(r))
        << (std::holds_alternative<std::string>(r) ? std::get<std::string>(r) : "");
    return std::holds_alternative<std::vector<Frame>>(r) ? std::get<std::vector<Frame>>(r) : std::vector<Frame>{};
}

// povray 3.7 printed these (#debug of every value) for +KFI1 +KFF3, +KFI0 +KFF10 +SF9 +KI2 +KF4, +KFF4 +KC.
TEST(Animation, FramesAndClocksAsPovRayMakesThem) {
    const auto three = frames_of({.initial_frame = 1, .final_frame = 3});
    ASSERT_EQ(three.size(), 3u);
    EXPECT_EQ(three[0].output, "scene1.png");
    EXPECT_EQ(three[2].output, "scene3.png");
    EXPECT_DOUBLE_EQ(three[1].clock.clock, 0.5);
    EXPECT_DOUBLE_EQ(three[1].clock.clock_delta, 0.5);
    EXPECT_TRUE(three[1].clock.clock_on);
    EXPECT_DOUBLE_EQ(three[1].clock.frame_number, 2);
    EXPECT_DOUBLE_EQ(three[1].clock.final_frame, 3);

    const auto subset = frames_of({.initial_frame = 0, .final_frame = 10, .initial_clock = 2, .final_clock = 4,
                                   .subset_start = 9},
                                  "out/anim.exr");
    ASSERT_EQ(subset.size(), 2u);
    EXPECT_EQ(subset[0].output, fs::path("out/anim09.exr"));
    EXPECT_EQ(subset[1].output, fs::path("out/anim10.exr"));
    EXPECT_NEAR(subset[0].clock.clock, 3.8, 1e-12);
    EXPECT_NEAR(subset[0].clock.clock_delta, 0.2, 1e-12);

    const auto cyclic = frames_of({.final_frame = 4, .cyclic = true});
    ASSERT_EQ(cyclic.size(), 4u);
    EXPECT_DOUBLE_EQ(cyclic[3].clock.clock, 0.75);
    EXPECT_DOUBLE_EQ(cyclic[3].clock.final_frame, 5);  // povray counts the frame it does not render

    EXPECT_EQ(frames_of({.final_frame = 100, .subset_start = 7, .subset_end = 7})[0].output, "scene007.png");
}

TEST(Animation, StillsAndMistakes) {
    const auto still = frames_of({});
    ASSERT_EQ(still.size(), 1u);
    EXPECT_EQ(still[0].output, "scene.png");
    EXPECT_FALSE(still[0].clock.clock_on);
    EXPECT_DOUBLE_EQ(still[0].clock.frame_number, 0);
    const auto clocked = frames_of({.clock = 0.5});
    EXPECT_DOUBLE_EQ(clocked[0].clock.clock, 0.5);
    EXPECT_TRUE(clocked[0].clock.clock_on);
    EXPECT_EQ(frames_of({.initial_frame = 1, .final_frame = 1})[0].output, "scene.png");  // povray: a still
    EXPECT_TRUE(std::holds_alternative<std::string>(plan_frames({.initial_frame = 5, .final_frame = 2}, "a.png")));
    EXPECT_TRUE(std::holds_alternative<std::string>(
        plan_frames({.initial_frame = 1, .final_frame = 5, .subset_start = 7}, "a.png")));
}

// povray 3.7 printed these regions for a 40 × 30 image.
TEST(PartialRender, RowsAndColumnsAsPovRayReadsThem) {
    auto region = [](RegionOptions r) {
        auto v = resolve_region(r, 40, 30);
        EXPECT_TRUE(std::holds_alternative<std::optional<render::PixelRegion>>(v));
        return std::holds_alternative<std::optional<render::PixelRegion>>(v)
                   ? std::get<std::optional<render::PixelRegion>>(v)
                   : std::nullopt;
    };
    EXPECT_EQ(region({}), std::nullopt);
    EXPECT_EQ(region({.start_row = 10, .end_row = 20, .start_column = 5, .end_column = 30}),
              (render::PixelRegion{4, 9, 30, 20}));                                  // rows 10..20, columns 5..30
    EXPECT_EQ(region({.start_row = 0.25, .end_row = 0.5}), (render::PixelRegion{0, 7, 40, 15}));   // rows 8..15
    EXPECT_EQ(region({.start_row = 0.29, .end_row = 0.49}), (render::PixelRegion{0, 8, 40, 14}));  // rows 9..14
    EXPECT_EQ(region({.start_row = 1, .end_row = 1}), (render::PixelRegion{0, 0, 40, 30}));        // rows 1..30
    EXPECT_EQ(region({.start_row = 1.5, .end_row = 2.5}), (render::PixelRegion{0, 0, 40, 2}));     // rows 1..2
    EXPECT_TRUE(std::holds_alternative<std::string>(resolve_region({.start_row = 31}, 40, 30)));
    EXPECT_TRUE(std::holds_alternative<std::string>(resolve_region({.start_row = 20, .end_row = 10}, 40, 30)));
}

const char* kScene = R"(#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -4> look_at <0, 0.5, 0> }
light_source { <3, 5, -4> rgb 1 }
plane { y, 0 pigment { checker rgb 1 rgb <0.2, 0.3, 0.8> scale 0.5 } }
sphere { <clock * 2 - 1, 0.8, 0>, 0.8 pigment { rgb <1, 0.4, 0.2> } finish { specular 0.6 } }
)";

fs::path test_dir(const std::string& name) {
    const fs::path dir = fs::path(WARDRAY_TEST_OUTPUT_DIR) / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::ofstream(dir / "scene.pov") << kScene;
    return dir;
}

render::Film read(const fs::path& path) {
    std::string error;
    auto film = render::read_image(path, error);
    EXPECT_TRUE(film.has_value()) << error;
    return film ? *film : render::Film();
}

TEST(PartialRender, EqualsTheSameRegionOfTheFullRenderByteForByte) {
    const fs::path dir = test_dir("partial_render");
    const std::string scene = (dir / "scene.pov").string();
    const std::vector<std::string> common = {scene, "+W97", "+H61", "+A0.05", "+R3", "-V"};
    auto with = [&](std::vector<std::string> extra) {
        std::vector<std::string> args = common;
        args.insert(args.end(), extra.begin(), extra.end());
        return args;
    };
    ASSERT_EQ(run(with({"-o", (dir / "full.png").string()}), "wardray"), kExitOk);
    ASSERT_EQ(run(with({"+SR13", "+ER0.8", "+SC0.3", "+EC71", "-o", (dir / "part.png").string()}), "wardray"),
              kExitOk);
    const render::Film full = read(dir / "full.png"), part = read(dir / "part.png");
    ASSERT_EQ(part.width(), 97);  // POV-Ray writes the whole frame
    ASSERT_EQ(part.height(), 61);
    int inside = 0, lit = 0;
    for (int y = 0; y < 61; ++y) {
        for (int x = 0; x < 97; ++x) {
            const bool in = y >= 12 && y < 48 && x >= 29 && x < 71;  // rows 13..48, columns 30..71
            const Vec3 p = part.pixel(x, y), f = full.pixel(x, y);
            if (in) {
                ++inside;
                lit += f.x > 0.0;
                ASSERT_EQ(p, f) << "pixel " << x << "," << y;
            } else {
                ASSERT_EQ(p, Vec3{}) << "pixel " << x << "," << y << " outside the region is not black";
            }
        }
    }
    EXPECT_EQ(inside, 36 * 42);
    EXPECT_GT(lit, inside / 2);
}

TEST(Animation, EachFrameIsTheStillAtItsClock) {
    const fs::path dir = test_dir("animation_frames");
    const std::string scene = (dir / "scene.pov").string();
    ASSERT_EQ(run({scene, "+W40", "+H30", "+KFI1", "+KFF3", "-o", (dir / "anim.png").string()}, "wardray"), kExitOk);
    ASSERT_EQ(run({scene, "+W40", "+H30", "+K0.5", "-o", (dir / "still.png").string()}, "wardray"), kExitOk);
    for (const char* name : {"anim1.png", "anim2.png", "anim3.png"})
        EXPECT_TRUE(fs::is_regular_file(dir / name)) << name;
    EXPECT_FALSE(fs::exists(dir / "anim.png"));
    const render::Film second = read(dir / "anim2.png"), still = read(dir / "still.png"),
                       first = read(dir / "anim1.png");
    EXPECT_EQ(second.data(), still.data());
    EXPECT_NE(first.data(), second.data());  // the sphere moved
    // +C: the frames that exist are kept; a removed one is rendered again.
    fs::remove(dir / "anim3.png");
    const auto kept = fs::last_write_time(dir / "anim1.png");
    ASSERT_EQ(run({scene, "+W40", "+H30", "+KFI1", "+KFF3", "+C", "-o", (dir / "anim.png").string()}, "wardray"),
              kExitOk);
    EXPECT_TRUE(fs::is_regular_file(dir / "anim3.png"));
    EXPECT_EQ(fs::last_write_time(dir / "anim1.png"), kept);
}

}  // namespace
}  // namespace wardray::app
