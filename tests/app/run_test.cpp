// Tests of the run's first step: the output file and format resolved as POV-Ray names them, and unsafe jobs refused.
#include "app/run.h"

#include <gtest/gtest.h>

#include <fstream>

#include "app/app.h"

namespace wardray::app {
namespace {

namespace fs = std::filesystem;

Job resolved(const std::vector<std::string>& args) {
    auto parsed = parse_command_line(args);
    EXPECT_TRUE(std::holds_alternative<Options>(parsed));
    const std::optional<Job> job = resolve_job(std::get<Options>(parsed), "wardray");
    EXPECT_TRUE(job.has_value());
    return job ? *job : Job{};
}

TEST(Run, OutputIsTheScenesNameWithTheFormatsExtension) {
    const Job png = resolved({"scenes/small.pov"});
    EXPECT_EQ(png.output, "small.png");
    EXPECT_EQ(png.format, render::ImageFormat::Png);
    const Job hdr = resolved({"+Iscenes/small.pov", "+FH"});
    EXPECT_EQ(hdr.output, "small.hdr");
    EXPECT_EQ(hdr.format, render::ImageFormat::Hdr);
    EXPECT_EQ(resolved({"small.pov", "+FE", "+Ofinal"}).output, "final.exr");
    const Job named = resolved({"small.pov", "-o", "other.hdr"});
    EXPECT_EQ(named.output, "other.hdr");
    EXPECT_EQ(named.format, render::ImageFormat::Hdr);
}

TEST(Run, NoSceneMeansTheBundledDefault) {
    const Job job = resolved({});
    EXPECT_EQ(job.options.scene.filename(), "default.pov");
    EXPECT_TRUE(fs::is_regular_file(job.options.scene)) << job.options.scene;
    EXPECT_EQ(job.output, "default.png");
}

TEST(Run, AnOutputThatIsTheSceneIsRefused) {
    const fs::path dir = fs::path(WARDRAY_TEST_OUTPUT_DIR) / "run_refuse";
    fs::create_directories(dir);
    const fs::path scene = dir / "scene.png";
    std::ofstream(scene) << "camera { }\n";
    const Job job = resolved({scene.string()});
    EXPECT_EQ(job.output, "scene.png");
    Job same = job;
    same.output = scene;
    EXPECT_EQ(refuse_job(same), std::optional<int>(kExitUsage));
    same.options.write_output = false;  // -F writes nothing, so nothing is overwritten
    EXPECT_EQ(refuse_job(same), std::nullopt);
    Job small = resolved({(dir / "other.pov").string(), "+W32", "+H24"});
    EXPECT_EQ(refuse_job(small), std::nullopt);
}

}  // namespace
}  // namespace wardray::app
