// The default read permissions beyond the scene's folder: Debian's povray.conf, so `../` files of a scene below
// /tmp or $HOME are read as POV-Ray's configuration permits, and --strict-reads keeps to the scene's folder.
#include "app/read_policy.h"

#include <gtest/gtest.h>

#include <fstream>

#include "app/run.h"

namespace wardray::app {
namespace {

namespace fs = std::filesystem;

TEST(ReadPolicy, TheFoldersAreDebiansPovrayConfEntries) {
    const auto folders = povray_permitted_reads("/home/someone", "/work/here");
    ASSERT_EQ(folders.size(), 6u);
    const std::vector<std::pair<fs::path, bool>> expected = {{"/usr/share/povray-3.7/include", true},
                                                             {"/usr/share/doc/povray/examples", true},
                                                             {"/etc/povray", true},
                                                             {"/home/someone", true},
                                                             {"/tmp", true},
                                                             {"/work/here", false}};
    for (std::size_t i = 0; i < expected.size(); ++i) {
        EXPECT_EQ(folders[i].folder, expected[i].first) << i;
        EXPECT_EQ(folders[i].subfolders, expected[i].second) << i;
    }
    EXPECT_EQ(povray_permitted_reads("", "").size(), 4u);  // no home, no current folder
}

class ReadPolicyScene : public ::testing::Test {
protected:
    void SetUp() override {
        // Below /tmp itself, the folder POV-Ray's configuration permits (not TMPDIR); one per test, since ctest runs
        // the tests side by side and each removes its folder when done.
        m_dir = fs::path("/tmp") / ("wardray_read_policy_test_" +
                                    std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        std::error_code ec;
        fs::remove_all(m_dir, ec);
        fs::create_directories(m_dir / "repo" / "scene", ec);
        if (ec) GTEST_SKIP() << "/tmp is not writable";
        std::ofstream(m_dir / "repo" / "common.inc") << "#declare Common = 3;\n";
    }
    void TearDown() override {
        std::error_code ec;
        fs::remove_all(m_dir, ec);
    }
    Options scene(const std::string& text) {
        std::ofstream(m_dir / "repo" / "scene" / "s.pov")
            << "global_settings { assumed_gamma 1 }\n" << text << "\ncamera { location -z look_at 0 }\n";
        Options o;
        o.scene = m_dir / "repo" / "scene" / "s.pov";
        o.check_only = true;
        return o;
    }
    fs::path m_dir;
};

TEST_F(ReadPolicyScene, AParentFolderBelowTmpIsReadUnlessReadsAreStrict) {
    Options o = scene("#include \"../common.inc\"\n#if (Common != 3) #error \"wrong\" #end");
    EXPECT_TRUE(load_scene(o).has_value());
    o.strict_reads = true;
    EXPECT_FALSE(load_scene(o).has_value());
}

TEST_F(ReadPolicyScene, SystemFilesOutsideThePermittedFoldersStayRefused) {
    EXPECT_FALSE(load_scene(scene("#include \"/etc/hostname\"")).has_value());
    EXPECT_FALSE(load_scene(scene("#include \"../../../etc/hostname\"")).has_value());
}

}  // namespace
}  // namespace wardray::app
