// Runs wardray on every malformed or hostile scene in tests/bad_input/: each must fail cleanly and write nothing.
//
// A case is a top-level `*.pov` file; `NAME.args`, when present, holds extra switches for it (e.g. an absurd
// +W/+H). Files under inc/ are helpers that cases include. The folder is listed when the tests are discovered
// (bad_input_discover.cmake, from CMakeLists.txt), so adding a file adds a case.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "../render/process.h"

namespace wardray::test {
namespace {

namespace fs = std::filesystem;

// Seconds one case may take before it counts as a hang (generous: the test machines are shared and loaded).
constexpr int kTimeoutSeconds = 8;
// Small renders, so a case that wrongly parses spends no time rendering. The default loop limit (10 million
// iterations) ends an endless #while after 10-20 s of parsing; a lower one keeps each case within a second.
const std::string kRenderArgs = "+W32 +H24 -A --max-loop-iterations 200000";

const fs::path kCorpus = fs::path(WARDRAY_SOURCE_DIR) / "tests" / "bad_input";

std::string read_file(const fs::path& p) {
    std::ifstream f(p, std::ios::binary);
    std::stringstream s;
    s << f.rdbuf();
    return s.str();
}

std::vector<std::string> corpus_cases() {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(kCorpus))
        if (e.is_regular_file() && e.path().extension() == ".pov") names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

// A fresh, empty folder for one run.
fs::path work_dir(const std::string& name) {
    const fs::path dir = fs::path(WARDRAY_TEST_OUTPUT_DIR) / "bad_input" / name;
    fs::remove_all(dir);
    fs::create_directories(dir / "run");
    return dir;
}

struct RunResult {
    int exit_status = -1;  ///< 124 when the time limit killed it
    std::string err;       ///< stderr alone
};

// Runs wardray in `dir`/run with a time limit; stdout and stderr go to files beside that folder.
RunResult run_wardray(const std::string& args, const fs::path& dir) {
    const fs::path err = dir / "stderr.txt";
    // Braces, so run_command's own 2>&1 applies to the group and our redirections stand.
    const std::string command = "{ timeout -k 2 " + std::to_string(kTimeoutSeconds) + " " +
                                shell_quote(WARDRAY_BINARY) + " " + args + " >" +
                                shell_quote((dir / "stdout.txt").string()) + " 2>" + shell_quote(err.string()) + "; }";
    RunResult r;
    r.exit_status = run_command(command, (dir / "run").string()).exit_status;
    r.err = read_file(err);
    return r;
}

std::string extra_args(const std::string& scene) {
    const fs::path args = kCorpus / (fs::path(scene).stem().string() + ".args");
    if (!fs::exists(args)) return "";
    std::string text = read_file(args);
    std::replace(text.begin(), text.end(), '\n', ' ');
    return text;
}

// True when `path`, as a diagnostic names it, is a file of the corpus (the scene or something it includes).
bool inside_corpus(const std::string& path) {
    std::error_code ec;
    const fs::path p = fs::weakly_canonical(fs::path(path), ec);
    const fs::path root = fs::weakly_canonical(kCorpus, ec);
    const auto [r, _] = std::mismatch(root.begin(), root.end(), p.begin(), p.end());
    return r == root.end() && fs::is_regular_file(p, ec);
}

// The first `path:line:col: error` of the output whose path is in the corpus, or "" when none is.
std::string located_error(const std::string& err) {
    static const std::regex located(R"(([^\s:][^:\n]*):([0-9]+):([0-9]+): error)");
    for (auto it = std::sregex_iterator(err.begin(), err.end(), located); it != std::sregex_iterator(); ++it) {
        const auto& m = *it;
        if (std::stoul(m[2].str()) >= 1 && std::stoul(m[3].str()) >= 1 && inside_corpus(m[1].str())) return m[0].str();
    }
    return "";
}

std::vector<std::string> files_in(const fs::path& dir) {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
    return names;
}

class BadInput : public ::testing::TestWithParam<std::string> {};

TEST_P(BadInput, FailsWithALocatedErrorAndWritesNothing) {
    const std::string scene = GetParam();
    const fs::path dir = work_dir(fs::path(scene).stem().string());
    const std::string args =
        shell_quote((kCorpus / scene).string()) + " " + kRenderArgs + " " + extra_args(scene);
    const RunResult r = run_wardray(args, dir);
    ASSERT_NE(r.exit_status, 124) << scene << " ran longer than " << kTimeoutSeconds << " s\n" << r.err;
    EXPECT_EQ(r.exit_status, 1) << scene << "\n" << r.err;
    EXPECT_NE(located_error(r.err), "") << scene << ": no path:line:col: error inside the corpus\n" << r.err;
    EXPECT_EQ(files_in(dir / "run"), std::vector<std::string>{}) << scene << " left files behind";
}

std::string case_name(const ::testing::TestParamInfo<std::string>& info) {
    std::string name = fs::path(info.param).stem().string();
    // As CMake's string(MAKE_C_IDENTIFIER), which names the CTest case in discover.cmake.
    for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    // Built as a new string: GCC 12 warns falsely (-Wrestrict) about insert(0, "_").
    if (!name.empty() && std::isdigit(static_cast<unsigned char>(name[0]))) return std::string(1, '_') + name;
    return name;
}

INSTANTIATE_TEST_SUITE_P(Corpus, BadInput, ::testing::ValuesIn(corpus_cases()), case_name);

TEST(BadInputCorpus, HasAtLeastFortyCases) { EXPECT_GE(corpus_cases().size(), 40u); }

const char* kGoodScene = R"(#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1, -4> look_at <0, 0.5, 0> }
light_source { <3, 5, -4> color rgb 1 }
plane { y, 0 pigment { rgb 0.8 } }
sphere { <0, 0.7, 0>, 0.7 pigment { rgb <1, 0.3, 0.2> } }
)";

// A failed run must not replace or damage the image a previous good run wrote to the same name.
TEST(BadInputCorpus, KeepsThePreviousImage) {
    const fs::path dir = work_dir("keep_previous");
    std::ofstream(dir / "good.pov") << kGoodScene;
    ASSERT_EQ(run_wardray("../good.pov +W32 +H24 -A -o out.png", dir).exit_status, 0) << read_file(dir / "stderr.txt");
    const std::string before = read_file(dir / "run" / "out.png");
    ASSERT_FALSE(before.empty());
    for (const char* scene :
         {"infinite_while.pov", "binary_garbage.pov", "unclosed_block.pov", "image_size_array.pov"}) {
        const RunResult r = run_wardray(shell_quote((kCorpus / scene).string()) + " " + kRenderArgs + " " +
                                      extra_args(scene) + " -o out.png",
                                  dir);
        EXPECT_EQ(r.exit_status, 1) << scene << "\n" << r.err;
        EXPECT_EQ(read_file(dir / "run" / "out.png"), before) << scene;
        EXPECT_EQ(files_in(dir / "run"), std::vector<std::string>{"out.png"}) << scene;
    }
}

// An image too large for this machine is refused before anything is allocated or written.
TEST(BadInputCorpus, AbsurdImageSizeOfAGoodSceneFailsCleanly) {
    const fs::path dir = work_dir("absurd_size");
    std::ofstream(dir / "good.pov") << kGoodScene;
    ASSERT_EQ(run_wardray("../good.pov +W32 +H24 -A -o out.png", dir).exit_status, 0) << read_file(dir / "stderr.txt");
    const std::string before = read_file(dir / "run" / "out.png");
    const RunResult r = run_wardray("../good.pov +W65536 +H65536 -A -o out.png", dir);
    ASSERT_NE(r.exit_status, 124) << r.err;
    EXPECT_EQ(r.exit_status, 1) << r.err;
    EXPECT_NE(r.err.find("error"), std::string::npos) << r.err;
    EXPECT_EQ(read_file(dir / "run" / "out.png"), before);
    EXPECT_EQ(files_in(dir / "run"), std::vector<std::string>{"out.png"});
}

}  // namespace
}  // namespace wardray::test
