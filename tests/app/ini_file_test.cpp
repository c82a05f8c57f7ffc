// Tests of POV-Ray INI files on the command line: keys, switch lines, sections, comments, order, errors.
#include "app/ini_file.h"

#include <gtest/gtest.h>

#include <fstream>

#include "app/app.h"
#include "app/options.h"

namespace wardray::app {
namespace {

namespace fs = std::filesystem;

fs::path write_ini(const std::string& name, const std::string& text) {
    const fs::path dir = fs::path(WARDRAY_TEST_OUTPUT_DIR) / "ini_files";
    fs::create_directories(dir);
    std::ofstream(dir / name) << text;
    return dir / name;
}

std::variant<Options, UsageError> parse(const std::vector<std::string>& args) {
    return parse_command_line(args);
}

Options parse_ok(const std::vector<std::string>& args) {
    auto r = parse(args);
    EXPECT_TRUE(std::holds_alternative<Options>(r))
        << (std::holds_alternative<UsageError>(r) ? std::get<UsageError>(r).message : "");
    return std::holds_alternative<Options>(r) ? std::get<Options>(r) : Options{};
}

UsageError parse_error(const std::vector<std::string>& args) {
    auto r = parse(args);
    EXPECT_TRUE(std::holds_alternative<UsageError>(r));
    return std::holds_alternative<UsageError>(r) ? std::get<UsageError>(r) : UsageError{};
}

TEST(IniFile, KeysCommentsQuotesAndSwitchLines) {
    const fs::path ini = write_ini("keys.ini",
                                   "; a comment line\n"
                                   "Input_File_Name=\"my scene.pov\"   ; a comment after a value\n"
                                   "  Width = 200\n"
                                   "height=150\n"
                                   "Antialias=On\n"
                                   "Antialias_Threshold=0.2\n"
                                   "+kf0.5 +kff20 +kc declare=fp=2\n"
                                   "Output_File_Name=\"out;name.png\"\n");
    const Options o = parse_ok({ini.string()});
    EXPECT_EQ(o.scene, "my scene.pov");
    EXPECT_EQ(o.width, 200);
    EXPECT_EQ(o.height, 150);
    EXPECT_TRUE(o.antialias);
    EXPECT_DOUBLE_EQ(o.antialias_threshold, 0.2);
    EXPECT_DOUBLE_EQ(o.animation.final_clock, 0.5);
    EXPECT_EQ(o.animation.final_frame, 20);
    EXPECT_TRUE(o.animation.cyclic);
    ASSERT_EQ(o.declares.size(), 1u);
    EXPECT_EQ(o.declares[0].first, "fp");
    EXPECT_EQ(*o.output, "out;name.png");
    EXPECT_TRUE(o.warnings.empty());
}

TEST(IniFile, LaterSettingsWinInCommandLineOrder) {
    const fs::path a = write_ini("a.ini", "Width=100\nHeight=80\n");
    const fs::path b = write_ini("b.ini", "Width=300\n");
    const Options o = parse_ok({"+W50", a.string(), "+H60", b.string(), "scene.pov"});
    EXPECT_EQ(o.width, 300);
    EXPECT_EQ(o.height, 60);
    EXPECT_EQ(o.scene, "scene.pov");
    // +I after an INI file's Input_File_Name replaces it.
    const fs::path named = write_ini("named.ini", "Input_File_Name=first.pov\n");
    EXPECT_EQ(parse_ok({named.string(), "+Isecond.pov"}).scene, "second.pov");
}

TEST(IniFile, SectionsAreChosenWithBrackets) {
    const fs::path ini = write_ini("sections.ini",
                                   "Width=20\n+KFF2\n[Big]\nWidth=50\nHeight=40\n[Other]\nWidth=60\n");
    const Options plain = parse_ok({ini.string()});
    EXPECT_EQ(plain.width, 20);  // only the lines before the first label
    EXPECT_EQ(plain.height, 240);
    const Options big = parse_ok({ini.string() + "[big]"});  // labels compare without case
    EXPECT_EQ(big.width, 50);
    EXPECT_EQ(big.height, 40);
    EXPECT_EQ(big.animation.final_frame, 2);  // the lines before the first label apply too
    const UsageError missing = parse_error({ini.string() + "[Nowhere]"});
    EXPECT_TRUE(missing.in_file);
    EXPECT_NE(missing.message.find("no section [Nowhere]"), std::string::npos) << missing.message;
}

TEST(IniFile, AnIniFileMayNameAnother) {
    const fs::path inner = write_ini("inner.ini", "Width=77\n");
    const fs::path outer = write_ini("outer.ini", "Height=33\n" + inner.string() + "\n");
    const Options o = parse_ok({outer.string()});
    EXPECT_EQ(o.width, 77);
    EXPECT_EQ(o.height, 33);
    const fs::path loop = write_ini("loop.ini", (fs::path(WARDRAY_TEST_OUTPUT_DIR) / "ini_files" / "loop.ini").string());
    EXPECT_NE(parse_error({loop.string()}).message.find("more than 10 deep"), std::string::npos);
}

TEST(IniFile, BadKeysAndValuesAreErrorsAtTheirLine) {
    const fs::path unknown = write_ini("unknown.ini", "Width=20\n\nWidht=20\n");
    const UsageError e1 = parse_error({unknown.string()});
    EXPECT_TRUE(e1.in_file);
    EXPECT_EQ(e1.message, unknown.string() + ":3: error: unknown INI key 'Widht'");
    const fs::path value = write_ini("value.ini", "; size\nHeight=tall\n");
    EXPECT_EQ(parse_error({value.string()}).message,
              value.string() + ":2: error: invalid 'Height=tall': expected a size in pixels, 1..65536");
    const fs::path flag = write_ini("flag.ini", "Antialias=maybe\n");
    EXPECT_NE(parse_error({flag.string()}).message.find(":1: error: invalid 'Antialias=maybe': expected on or off"),
              std::string::npos);
    const fs::path word = write_ini("switch.ini", "+W20 +Zed\n");
    EXPECT_NE(parse_error({word.string()}).message.find(":1: error: invalid switch '+Zed'"), std::string::npos);
    const fs::path label = write_ini("label.ini", "[Open\n");
    EXPECT_NE(parse_error({label.string()}).message.find(":1: error: a section label needs its ']'"),
              std::string::npos);
    const UsageError absent = parse_error({"/nonexistent/none.ini"});
    EXPECT_NE(absent.message.find("cannot read the INI file"), std::string::npos);
}

TEST(IniFile, AMistakeInAnIniFileIsExitStatusOneAndWritesNothing) {
    const fs::path ini = write_ini("stops.ini", "Output_File_Name=" +
                                                    (fs::path(WARDRAY_TEST_OUTPUT_DIR) / "ini_files" / "none.png").string() +
                                                    "\nWidth=-3\n");
    testing::internal::CaptureStderr();
    EXPECT_EQ(run({ini.string()}, "wardray"), kExitScene);
    const std::string err = testing::internal::GetCapturedStderr();
    EXPECT_EQ(err, ini.string() + ":2: error: invalid 'Width=-3': expected a size in pixels, 1..65536\n");
    EXPECT_FALSE(fs::exists(fs::path(WARDRAY_TEST_OUTPUT_DIR) / "ini_files" / "none.png"));
}

TEST(IniFile, DisplayKeysAreQuietAndUnsupportedOnesWarn) {
    const fs::path ini = write_ini("front_end.ini",
                                   "Display=Off\nPause_When_Done=on\nTest_Abort_Count=100\nVerbose=On\n"
                                   "All_Console=On\nBounding_Threshold=3\nVersion=3.7\nBits_Per_Color=8\n"
                                   "Output_File_Name=\nFatal_Error_Command=\n+P +X -GA\n"
                                   "Create_Ini=on\nBits_Per_Color=16\nDither=on\n");
    const Options o = parse_ok({ini.string()});
    ASSERT_EQ(o.warnings.size(), 3u);
    EXPECT_EQ(o.warnings[0], ini.string() + ":12: warning: Create_Ini=on is not supported yet; ignored");
    EXPECT_NE(o.warnings[1].find(":13: warning: Bits_Per_Color=16 is not supported yet"), std::string::npos);
    EXPECT_NE(o.warnings[2].find(":14: warning: Dither=on"), std::string::npos);
    EXPECT_FALSE(o.output.has_value());  // an empty value changes nothing
    // On the command line the display switches are quiet too; +Q5 is rendered (lighting/quality.h), so quiet.
    const Options cl = parse_ok({"+P", "-X", "+Q5", "Bits_Per_Color=16"});
    EXPECT_EQ(cl.quality, 5);
    ASSERT_EQ(cl.warnings.size(), 1u);  // the other keys warn without a file
    EXPECT_NE(cl.warnings[0].find("Bits_Per_Color=16 is not supported yet"), std::string::npos);
}

TEST(IniFile, AnimationAndPartialRenderKeysMatchTheirSwitches) {
    const fs::path ini = write_ini("anim.ini",
                                   "Initial_Frame=2\nFinal_Frame=12\nInitial_Clock=1\nFinal_Clock=3\n"
                                   "Cyclic_Animation=on\nSubset_Start_Frame=4\nSubset_End_Frame=5\n"
                                   "Start_Row=0.25\nEnd_Row=60\nStart_Column=3\nEnd_Column=0.5\n"
                                   "Continue_Trace=on\nQuality=9\nRender_Block_Size=16\n");
    const Options from_ini = parse_ok({ini.string()});
    const Options from_switches = parse_ok({"+KFI2", "+KFF12", "+KI1", "+KF3", "+KC", "+SF4", "+EF5", "+SR0.25",
                                            "+ER60", "+SC3", "+EC0.5", "+C", "+Q9", "+BS16"});
    EXPECT_EQ(from_ini, from_switches);
    EXPECT_EQ(from_ini.animation.initial_frame, 2);
    EXPECT_EQ(from_ini.region.end_row, 60.0);
    EXPECT_EQ(from_ini.render_block_size, 16);
}

TEST(IniFile, PovRaysIniFolderIsSearched) {
    if (!fs::is_regular_file("/usr/share/povray-3.7/ini/quickres.ini")) GTEST_SKIP() << "no POV-Ray ini folder";
    const Options o = parse_ok({"quickres.ini[256x144,16:9 AA 0.3]"});
    EXPECT_EQ(o.width, 256);
    EXPECT_EQ(o.height, 144);
    EXPECT_TRUE(o.antialias);
}

TEST(IniFile, ArgumentsEndingInIniAreIniFiles) {
    EXPECT_TRUE(is_ini_argument("scene.ini"));
    EXPECT_TRUE(is_ini_argument("dir/Scene.INI[Section 1]"));
    EXPECT_FALSE(is_ini_argument("scene.pov"));
    EXPECT_FALSE(is_ini_argument(".ini"));
    EXPECT_EQ(split_ini_words("+W20  \"+Oa b.png\"\t+H3"), (std::vector<std::string>{"+W20", "+Oa b.png", "+H3"}));
}

}  // namespace
}  // namespace wardray::app
