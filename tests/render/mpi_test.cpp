// Rendering across processes (mpirun): the image and the +RFO cache file byte-identical to one process's for
// 2 and 3 ranks, a rank that fails to parse failing the run with no image, and --stats' per-rank figures.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "process.h"

namespace wardray::test {
namespace {

namespace fs = std::filesystem;

const fs::path kBoxScene = fs::path(WARDRAY_SOURCE_DIR) / "scenes" / "radiosity" / "box.pov";

// A direct-light scene with a reflective sphere and antialiasing to decide per block.
const char* kDirectScene = R"(#version 3.7;
global_settings { assumed_gamma 1.0 }
#ifdef (Bad) #error "this rank was told to fail" #end
camera { location <0, 1, -4> look_at <0, 0.5, 0> }
light_source { <3, 5, -4> color rgb 1 }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.2 } }
sphere { <0, 0.7, 0>, 0.7 pigment { rgb <1, 0.3, 0.2> } finish { phong 0.5 reflection 0.3 } }
box { <1, 0, -0.5>, <2, 1, 0.5> pigment { rgb <0.2, 0.5, 1> } }
)";

fs::path fresh_dir(const std::string& name) {
    const fs::path dir = fs::path(WARDRAY_TEST_OUTPUT_DIR) / "mpi" / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

std::string read_file(const fs::path& p) {
    std::ifstream f(p, std::ios::binary);
    std::stringstream s;
    s << f.rdbuf();
    return s.str();
}

std::string wardray() { return shell_quote(WARDRAY_BINARY); }

// `ranks` processes of wardray with `args`, as a user starts them (as root in the test containers, on 2 cores).
ProcessResult mpirun(int ranks, const std::string& args, const fs::path& dir) {
    return run_command(shell_quote(WARDRAY_MPIRUN) + " --oversubscribe --allow-run-as-root -np " +
                           std::to_string(ranks) + " " + wardray() + " " + args,
                       dir.string());
}

// Renders `args` in one plain process and with 2 and 3 ranks, and expects every output file the same byte for byte.
void expect_same_across_ranks(const fs::path& dir, const std::string& args, const std::vector<std::string>& files) {
    const ProcessResult one = run_command(wardray() + " " + args, (dir / "1").string());
    ASSERT_EQ(one.exit_status, 0) << one.output;
    for (const int ranks : {2, 3}) {
        const fs::path here = dir / std::to_string(ranks);
        fs::create_directories(here);
        const ProcessResult many = mpirun(ranks, args, here);
        ASSERT_EQ(many.exit_status, 0) << many.output;
        for (const std::string& file : files) {
            const std::string a = read_file(dir / "1" / file), b = read_file(here / file);
            EXPECT_FALSE(a.empty()) << file;
            EXPECT_TRUE(a == b) << file << " differs between 1 process and " << ranks << " ranks";
        }
        // Only the finished files: nothing left under a temporary name.
        std::size_t entries = 0;
        for ([[maybe_unused]] const auto& e : fs::directory_iterator(here)) ++entries;
        EXPECT_EQ(entries, files.size());
    }
}

TEST(Mpi, RadiosityImageAndCacheFileAreTheOneProcessOnes) {
    // 6 tiles of 16 pixels in waves of 1, 2, 3 in the first pretrace pass, then 2, 4 in the later passes.
    const fs::path dir = fresh_dir("radiosity");
    expect_same_across_ranks(dir,
                             shell_quote(kBoxScene.string()) +
                                 " +W48 +H32 +BS16 +WT1 Declare=Count=30 -Obox.exr +RFO +RFbox.rca",
                             {"box.exr", "box.rca"});
}

TEST(Mpi, RanksOfTwoThreadsDrawingTilesGiveTheOneProcessImage) {
    // Two worker threads per rank draw the waves' tiles from the shared counters at once; the image and the cache
    // file are still the single-threaded single process's.
    const fs::path dir = fresh_dir("radiosity_threads");
    const std::string scene = shell_quote(kBoxScene.string()) + " +W64 +H48 +BS16 Declare=Count=30 -Obox.exr +RFO +RFbox.rca";
    fs::create_directories(dir / "1");
    fs::create_directories(dir / "2");
    const ProcessResult one = run_command(wardray() + " " + scene + " +WT1", (dir / "1").string());
    ASSERT_EQ(one.exit_status, 0) << one.output;
    const ProcessResult many = mpirun(2, scene + " +WT2", dir / "2");
    ASSERT_EQ(many.exit_status, 0) << many.output;
    for (const std::string file : {"box.exr", "box.rca"}) {
        const std::string a = read_file(dir / "1" / file), b = read_file(dir / "2" / file);
        EXPECT_FALSE(a.empty()) << file;
        EXPECT_TRUE(a == b) << file << " differs between 1 process of 1 thread and 2 ranks of 2 threads";
    }
}

TEST(Mpi, DirectLightImageIsTheOneProcessOne) {
    const fs::path dir = fresh_dir("direct");
    std::ofstream(dir / "direct.pov") << kDirectScene;
    expect_same_across_ranks(dir, "../direct.pov +W96 +H72 +BS16 +A0.1 +WT1 -Odirect.exr", {"direct.exr"});
}

TEST(Mpi, AnimationFramesSplitOverRanksAreTheOneProcessFrames) {
    // Issue 20: frames rendered afresh go to the ranks whole (rank 0 writes them all); each is the plain run's.
    const fs::path dir = fresh_dir("frames");
    std::ofstream(dir / "anim.pov") << kDirectScene << "sphere { <2 * clock - 1, 1.8, 0>, 0.3 pigment { rgb 1 } }\n";
    expect_same_across_ranks(dir, "../anim.pov +KFI1 +KFF4 +W64 +H48 +A0.1 +WT1",
                             {"anim1.png", "anim2.png", "anim3.png", "anim4.png"});
    // The frames differ from each other, so a rank writing the wrong frame would show.
    EXPECT_NE(read_file(dir / "1" / "anim1.png"), read_file(dir / "1" / "anim4.png"));
}

TEST(Mpi, RankThatFailsToParseFailsTheRunWithNoImage) {
    const fs::path dir = fresh_dir("parse_failure");
    std::ofstream(dir / "scene.pov") << kDirectScene;
    // Rank 1 alone is told to fail (MPMD: a second program line).
    const ProcessResult r = run_command(shell_quote(WARDRAY_MPIRUN) + " --oversubscribe --allow-run-as-root -np 1 " +
                                            wardray() + " scene.pov +W32 +H24 -Oout.png : -np 1 " + wardray() +
                                            " scene.pov +W32 +H24 -Oout.png Declare=Bad=1",
                                        dir.string());
    EXPECT_EQ(r.exit_status, 1) << r.output;
    EXPECT_NE(r.output.find("rank 1: scene.pov:3:14: error: this rank was told to fail"), std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("wardray: error: rank 1 of 2 could not parse the scene; nothing written"),
              std::string::npos)
        << r.output;
    EXPECT_FALSE(fs::exists(dir / "out.png"));
}

TEST(Mpi, StatsCountRecordsMadeAndReceivedPerRank) {
    const fs::path dir = fresh_dir("stats");
    const ProcessResult r =
        mpirun(2, shell_quote(kBoxScene.string()) + " +W64 +H64 +BS16 +WT1 Declare=Count=40 -F --stats s.json", dir);
    ASSERT_EQ(r.exit_status, 0) << r.output;
    std::ifstream f(dir / "s.json");
    const nlohmann::json stats = nlohmann::json::parse(f);
    const nlohmann::json& p = stats["processes"];
    ASSERT_EQ(p["count"], 2);
    const std::uint64_t total = stats["cache"]["records"];
    std::uint64_t made = 0, sent = 0, received = 0;
    for (const nlohmann::json& rank : p["ranks"]) {
        const std::uint64_t mine = rank["records_made"], theirs = rank["records_received"];
        EXPECT_GT(mine, 0u);
        // Each rank receives every record the other made.
        EXPECT_EQ(mine + theirs, total);
        made += mine;
        sent += rank["bytes_sent"].get<std::uint64_t>();
        received += rank["bytes_received"].get<std::uint64_t>();
    }
    EXPECT_EQ(made, total);
    // Each pass renders each of the 16 tiles once: a wave structure that folds its last tiles into the wave before
    // must neither drop nor repeat one.
    std::uint64_t tiles = 0, wave_tiles = 0;
    for (const nlohmann::json& rank : p["ranks"]) tiles += rank["tiles"].get<std::uint64_t>();
    for (const nlohmann::json& wave : p["waves"]) wave_tiles += wave["tiles"].get<std::uint64_t>();
    ASSERT_GE(stats["passes"].size(), 2u);
    EXPECT_EQ(tiles, 16u * stats["passes"].size());
    EXPECT_EQ(wave_tiles, tiles);
    EXPECT_GT(sent, total * 200);  // a record is about 250 bytes
    EXPECT_EQ(p["bytes_exchanged"], sent);
    // Rank 1 gets what rank 0 sent in every allgather; the image and statistics go to rank 0 only.
    EXPECT_GT(received, 0u);
    // Every wave shows where each rank's time went: its tiles, the exchange and the merge of the records.
    ASSERT_FALSE(p["waves"].empty());
    double merged = 0.0;
    for (const nlohmann::json& wave : p["waves"]) {
        ASSERT_EQ(wave["ranks"].size(), 2u);
        double busy = 0.0;
        for (const nlohmann::json& rank : wave["ranks"]) {
            for (const char* key : {"busy_cpu_seconds", "tiles_seconds", "exchange_seconds", "merge_seconds"})
                EXPECT_GE(rank[key].get<double>(), 0.0) << key;
            busy += rank["busy_cpu_seconds"].get<double>();
            merged += rank["merge_seconds"].get<double>();
        }
        EXPECT_DOUBLE_EQ(busy, wave["busy_sum_cpu_seconds"].get<double>());
    }
    EXPECT_GT(merged, 0.0);
    EXPECT_GT(p["ranks"][0]["merge_seconds"].get<double>(), 0.0);
}

}  // namespace
}  // namespace wardray::test
