// Hostile scenes, round two: reads confined to the permitted folders for every way of reading, files that are not
// text, byte-order marks and line ends, the object and memory budgets, and deep nesting built by loops.
#include <chrono>
#include <filesystem>
#include <fstream>

#include "parser/part_list.h"
#include "parser/read_access.h"
#include "tests/parser/test_util.h"

namespace wardray::parser {
namespace {

namespace fs = std::filesystem;

const std::string kRefused = "is not allowed: files are read only from the scene's folder, the include path (+L, "
                             "Library_Path) and the folders given with --read-path DIR";

/// A scene folder and a folder beside it holding a "secret" the scene must not read.
class ReadConfinement : public ::testing::Test {
protected:
    void SetUp() override {
        m_dir = fs::temp_directory_path() /
                ("wardray_reads_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(m_dir);
        fs::create_directories(m_dir / "scene");
        fs::create_directories(m_dir / "outside");
        std::ofstream(m_dir / "outside" / "secret.inc") << "#declare Secret = 42;\n";
    }
    void TearDown() override { fs::remove_all(m_dir); }

    ParseOptions options() {
        ParseOptions o = test::default_options();
        // Records every image the parser asks for: a refused one must never reach the reader.
        o.read_image = [this](const fs::path& file, bool&, std::string& error) -> std::shared_ptr<ImageData> {
            m_images_read.push_back(file);
            error = "test reader";
            return nullptr;
        };
        o.read_height_grid = [this](const fs::path& file, std::string& error, std::string&) {
            m_images_read.push_back(file);
            error = "test reader";
            return std::shared_ptr<const scene::HeightGrid>();
        };
        return o;
    }
    ParseResult parse(const std::string& text, const ParseOptions& o) {
        std::ofstream(m_dir / "scene" / "s.pov") << "global_settings { assumed_gamma 1 }\n" << text;
        return parse_file(m_dir / "scene" / "s.pov", o);
    }
    std::string first_error(const ParseResult& r) {
        for (const Diagnostic& d : r.diagnostics)
            if (d.severity == Severity::Error) return d.message;
        return "";
    }

    fs::path m_dir;
    std::vector<fs::path> m_images_read;
};

TEST_F(ReadConfinement, IncludeOutsideIsRefusedUnlessAReadPathAllowsIt) {
    const ParseResult r = parse("#include \"../outside/secret.inc\"\n", options());
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(first_error(r), "reading '" + (m_dir / "outside" / "secret.inc").string() + "' (include file) " + kRefused);
    EXPECT_EQ(r.diagnostics[0].loc.line, 2u);
    EXPECT_EQ(r.diagnostics[0].loc.column, 10u);
    // Nothing of the file is echoed.
    for (const Diagnostic& d : r.diagnostics) EXPECT_EQ(d.source_line.find("Secret"), std::string::npos);
    ParseOptions o = options();
    o.read_paths.push_back(m_dir / "outside");
    EXPECT_TRUE(parse("#include \"../outside/secret.inc\"\n#if (Secret != 42) #error \"\" #end\n", o).ok());
    // The include path (+L) allows it too.
    o = options();
    o.library_paths.push_back(m_dir / "outside");
    EXPECT_TRUE(parse("#include \"secret.inc\"\n#if (Secret != 42) #error \"\" #end\n", o).ok());
}

TEST_F(ReadConfinement, AbsoluteSystemFilesAreRefusedForEveryWayOfReading) {
    const std::string refused = "reading '/etc/passwd' (";
    EXPECT_EQ(first_error(parse("#include \"/etc/passwd\"\n", options())), refused + "include file) " + kRefused);
    EXPECT_EQ(first_error(parse("#fopen F \"/etc/passwd\" read\n", options())), refused + "#fopen read) " + kRefused);
    EXPECT_EQ(first_error(parse("text { ttf \"/etc/passwd\" \"a\" 1, 0 }\n", options())),
              refused + "font file) " + kRefused);
    EXPECT_EQ(first_error(parse("plane { z, 1 pigment { image_map { png \"/etc/passwd\" } } }\n", options())),
              refused + "image file) " + kRefused);
    EXPECT_EQ(first_error(parse("height_field { png \"/etc/passwd\" }\n", options())),
              refused + "height_field image) " + kRefused);
    EXPECT_EQ(first_error(parse("plane { z, 1 normal { bump_map { png \"/etc/passwd\" } } }\n", options())),
              refused + "image file) " + kRefused);
    EXPECT_EQ(first_error(parse("plane { z, 1 pigment { image_pattern { png \"/etc/passwd\" } } }\n", options())),
              refused + "image file) " + kRefused);
    EXPECT_EQ(first_error(parse("plane { z, 1 texture { material_map { png \"/etc/passwd\" texture { pigment "
                                "{ rgb 1 } } } } }\n",
                                options())),
              refused + "image file) " + kRefused);
    EXPECT_EQ(first_error(parse("box { -1, 1 hollow interior { media { density { density_file df3 "
                                "\"/etc/passwd\" } } } }\n",
                                options())),
              refused + "density file) " + kRefused);
    // Photon and radiosity files are not read or written yet; their names are confined already.
    EXPECT_EQ(first_error(parse("global_settings { photons { count 10 load_file \"/etc/passwd\" } }\n", options())),
              refused + "photons load_file) " + kRefused);
    EXPECT_EQ(first_error(parse("global_settings { radiosity { load_file \"/etc/passwd\" } }\n", options())),
              refused + "radiosity load_file) " + kRefused);
    EXPECT_TRUE(m_images_read.empty());
}

TEST_F(ReadConfinement, PhotonAndRadiositySaveFilesAreConfinedLikeWrites) {
    const std::string refused = "' is not allowed: files are written only inside the scene's folder and the folders "
                                "given as write paths (--write-path DIR)";
    EXPECT_EQ(first_error(parse("global_settings { photons { count 10 save_file \"/etc/w.ph\" } }\n", options())),
              "writing '/etc/w.ph" + refused);
    EXPECT_EQ(first_error(parse("global_settings { radiosity { save_file \"/usr/w.rad\" } }\n", options())),
              "writing '/usr/w.rad" + refused);
    // In the scene's folder they are accepted (with the warning that they are not written).
    const ParseResult ok = parse("global_settings { photons { count 10 save_file \"w.ph\" } radiosity { save_file "
                                 "\"w.rad\" } }\n",
                                 options());
    EXPECT_TRUE(ok.ok()) << test::all_diagnostics(ok);
    EXPECT_FALSE(fs::exists(m_dir / "scene" / "w.ph"));
    EXPECT_FALSE(fs::exists(m_dir / "scene" / "w.rad"));
}

TEST_F(ReadConfinement, ASymbolicLinkInTheSceneFolderIsJudgedByWhereItLeads) {
    std::error_code ec;
    fs::create_symlink(m_dir / "outside" / "secret.inc", m_dir / "scene" / "link.inc", ec);
    if (ec) GTEST_SKIP() << "no symbolic links here";
    const ParseResult r = parse("#include \"link.inc\"\n", options());
    EXPECT_EQ(first_error(r), "reading '" + (m_dir / "outside" / "secret.inc").string() + "' (include file) " + kRefused);
    EXPECT_EQ(first_error(parse("plane { z, 1 pigment { image_map { png \"link.inc\" } } }\n", options())),
              "reading '" + (m_dir / "outside" / "secret.inc").string() + "' (image file) " + kRefused);
    EXPECT_TRUE(m_images_read.empty());
}

TEST_F(ReadConfinement, TheSystemIncludeFolderMayLinkElsewhere) {
    // The include path is the user's (or the system's): its links are followed, as Debian links its fonts.
    std::error_code ec;
    fs::create_directories(m_dir / "lib");
    fs::create_symlink(m_dir / "outside" / "secret.inc", m_dir / "lib" / "linked.inc", ec);
    if (ec) GTEST_SKIP() << "no symbolic links here";
    ParseOptions o = options();
    o.library_paths.push_back(m_dir / "lib");
    EXPECT_TRUE(parse("#include \"linked.inc\"\n#if (Secret != 42) #error \"\" #end\n", o).ok());
}

TEST_F(ReadConfinement, ImagesInTheSceneFolderReachTheReader) {
    std::ofstream(m_dir / "scene" / "tex.png") << "x";
    const ParseResult r = parse("plane { z, 1 pigment { image_map { png \"tex.png\" } } }\n", options());
    ASSERT_EQ(m_images_read.size(), 1u);
    EXPECT_EQ(first_error(r), "cannot read image file '" + m_images_read[0].string() + "': test reader");
}

TEST_F(ReadConfinement, APermittedFolderAllowsTheParentsFilesByTheirRealLocationAndDepth) {
    // A povray.conf entry `read* = DIR` permits DIR and its subfolders, `read = DIR` DIR's own files only.
    fs::create_directories(m_dir / "outside" / "deeper");
    std::ofstream(m_dir / "outside" / "deeper" / "deep.inc") << "#declare Deep = 7;\n";
    ParseOptions o = options();
    o.permitted_reads.push_back({m_dir / "outside", false});
    EXPECT_TRUE(parse("#include \"../outside/secret.inc\"\n#if (Secret != 42) #error \"\" #end\n", o).ok());
    EXPECT_EQ(first_error(parse("#include \"../outside/deeper/deep.inc\"\n", o)),
              "reading '" + (m_dir / "outside" / "deeper" / "deep.inc").string() + "' (include file) " + kRefused);
    o.permitted_reads = {{m_dir, true}};
    EXPECT_TRUE(parse("#include \"../outside/deeper/deep.inc\"\n#if (Deep != 7) #error \"\" #end\n", o).ok());
    // A link inside a permitted folder is judged by where it leads, as in the scene's own folder.
    std::error_code ec;
    fs::create_symlink("/etc/passwd", m_dir / "outside" / "link.inc", ec);
    if (ec) return;
    EXPECT_EQ(first_error(parse("#include \"../outside/link.inc\"\n", o)),
              "reading '/etc/passwd' (include file) " + kRefused);
}

TEST_F(ReadConfinement, ABinaryIncludeIsAnErrorWithAShortEscapedExcerpt) {
    std::string png = "\x89PNG\r\n\x1a\n";
    png += std::string(4000, '\0');
    std::ofstream(m_dir / "scene" / "pic.png", std::ios::binary) << png;
    const ParseResult r = parse("#include \"pic.png\"\n", options());
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(first_error(r), "cannot open include file 'pic.png': it is not a text file (it starts with "
                              "\"\\x89PNG\\x0D\\x0A\\x1A\\x0A\\x00\\x00\\x00\\x00\\x00\\x00\\x00\\x00...\")");
    EXPECT_EQ(first_error(parse("#fopen F \"pic.png\" read\n", options())),
              "'" + (m_dir / "scene" / "pic.png").string() +
                  "' is not a text file (it starts with \"\\x89PNG\\x0D\\x0A\\x1A\\x0A\\x00\\x00\\x00\\x00\\x00\\x00"
                  "\\x00\\x00...\")");
}

TEST(SourceText, BinaryScenesAreReportedAtTheirStartWithoutEchoingThem) {
    const std::string bytes = std::string("\x7F" "ELF\x02\x01\x01", 7) + std::string(100, '\0') + "secret";
    const ParseResult r = parse_string(bytes, "a.out", test::default_options());
    ASSERT_FALSE(r.ok());
    ASSERT_FALSE(r.diagnostics.empty());
    EXPECT_EQ(r.diagnostics[0].severity, Severity::Error);
    EXPECT_EQ(r.diagnostics[0].loc.line, 1u);
    EXPECT_EQ(test::all_diagnostics(r).find("secret"), std::string::npos);
    EXPECT_EQ(binary_excerpt("sphere { 0, 1 }\n// caf\xC3\xA9\n"), std::nullopt);
    EXPECT_EQ(binary_excerpt("\xFF\xFE#\0v\0"), std::optional<std::string>("\\xFF\\xFE#"));
}

TEST(SourceText, ControlBytesInAShownLineAreEscapedAndLongLinesCut) {
    EXPECT_EQ(printable_source_line("sphere { 0, 1 } // caf\xC3\xA9"), "sphere { 0, 1 } // caf\xC3\xA9");
    EXPECT_EQ(printable_source_line("a\x1B[2Jb\xFF"), "a\\x1B[2Jb\\xFF");
    EXPECT_EQ(printable_source_line(std::string(1000, 'x')).size(), 243u);
}

TEST(SourceText, AByteOrderMarkAndEveryLineEndAreAccepted) {
    const ParseResult bom = parse_string("\xEF\xBB\xBF#version 3.7;\nglobal_settings { assumed_gamma 1 }\n"
                                         "sphere { 0, 1 }\n", "t.pov", test::default_options());
    EXPECT_TRUE(bom.ok()) << test::all_diagnostics(bom);
    for (const char* end : {"\n", "\r\n", "\r"}) {
        const std::string e = end;
        const std::string text = "\xEF\xBB\xBF#version 3.7;" + e + "// a comment" + e + "sphere { 0, q }" + e;
        const ParseResult r = parse_string(text, "t.pov", test::default_options());
        ASSERT_FALSE(r.ok());
        EXPECT_EQ(r.diagnostics[0].loc.line, 3u) << "line end " << static_cast<int>(end[0]);
        EXPECT_EQ(r.diagnostics[0].loc.column, 13u);
        EXPECT_EQ(r.diagnostics[0].source_line, "sphere { 0, q }");
    }
}

TEST(Budgets, TheObjectThatCrossesTheLimitIsNamed) {
    ParseOptions o = test::default_options();
    o.max_objects = 10;
    const ParseResult r = parse_string("#for (I, 1, 20)\n  sphere { I * x, 1 }\n#end\n", "t.pov", o);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.diagnostics[0].message, "the scene created more than the limit of 10 objects (an endless loop "
                                        "making objects?); raise it with --max-objects");
    EXPECT_EQ(r.diagnostics[0].loc.line, 2u);
    o.max_objects = 20;
    EXPECT_TRUE(parse_string("#for (I, 1, 20)\n  sphere { I * x, 1 }\n#end\n", "t.pov", o).ok());
    // A copy counts every object it holds.
    o.max_objects = 25;
    const ParseResult copies = parse_string(
        "#declare U = union { #for (I, 1, 10) sphere { I * x, 1 } #end }\nobject { U }\nobject { U }\n", "t.pov", o);
    ASSERT_FALSE(copies.ok());
    EXPECT_EQ(copies.diagnostics[0].loc.line, 3u);
}

TEST(Budgets, AUnionRedeclaredAroundItselfCountsEachNewPartOnce) {
    // `#declare U = union { object { U } sphere { ... } }` 1,400 times (as a user's scene does) copies about a
    // million parts in all, but holds only 1,401: the copies of a value a redeclaration drops are given back.
    ParseOptions o = test::default_options();
    o.max_objects = 250'000;  // the command line's default
    const std::string scene = "#declare U = sphere { 0, 1 }\n#for (I, 1, 1400)\n"
                              "  #declare U = union { object { U } sphere { <I, 0, 0>, 1 } }\n#end\nobject { U }\n";
    const ParseResult r = parse_string(scene, "t.pov", o);
    ASSERT_TRUE(r.ok()) << test::all_diagnostics(r);
    EXPECT_EQ(r.scene->objects.size(), 1401u);
    // Copies placed in the scene are kept, so they still count.
    o.max_objects = 2'000;
    const ParseResult held = parse_string("#declare U = union { #for (I, 1, 100) sphere { I * x, 1 } #end }\n"
                                          "#for (I, 1, 30)\n  #declare Keep = U;\n  #declare U = object { U }\n"
                                          "  object { Keep }\n#end\n", "t.pov", o);
    ASSERT_FALSE(held.ok());
    EXPECT_NE(held.diagnostics[0].message.find("raise it with --max-objects"), std::string::npos);
}

TEST(Budgets, AnEndlessObjectLoopStopsWithinSeconds) {
    ParseOptions o = test::default_options();
    o.max_loop_iterations = 1'000'000'000;
    o.max_objects = 100'000;  // the command line's default (parse.h's 2 million takes about 6 s)
    const auto start = std::chrono::steady_clock::now();
    const ParseResult r = parse_string("#declare I = 0;\n#while (1)\n  sphere { <I, 0, 0>, 1 }\n  #declare I = I + 1;\n"
                                       "#end\n", "t.pov", o);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ASSERT_FALSE(r.ok());
    EXPECT_LT(seconds, 5.0);
    EXPECT_NE(r.diagnostics[0].message.find("raise it with --max"), std::string::npos) << r.diagnostics[0].message;
}

TEST(Budgets, MemoryGrowthPastTheLimitEndsTheParse) {
    ParseOptions o = test::default_options();
    o.max_loop_iterations = 1'000'000'000;
    o.max_memory_bytes = std::size_t{64} << 20;
    const ParseResult r = parse_string(
        "#declare I = 0;\nmesh {\n#while (1)\n  triangle { <I, 0, 0>, <I, 1, 0>, <I, 0, 1> }\n  #declare I = I + 1;\n"
        "#end\n}\n", "t.pov", o);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.diagnostics[0].message,
              "the parse took more than the limit of 64 MB of memory (an endless loop?); raise it with --max-memory MB");
}

TEST(DeepNesting, TwentyThousandUnionsNestedByALoopParseQuickly) {
    const auto start = std::chrono::steady_clock::now();
    const Scene s = test::parse_ok(
        "#declare U = sphere { 0, 1 }\n"
        "#for (I, 1, 20000)\n  #declare U = union { object { U translate 0.0001 * x } }\n#end\n"
        "object { U }\n");
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(s.objects.size(), 1u);
    EXPECT_LT(seconds, 2.0);
}

// A list that takes parts of its own from a chain no other list holds any more moves them (a union of 20,000 parts
// is not copied); from a chain another list still holds it copies them, leaving the other's as they were.
TEST(SharedObjects, AChainNoOtherListHoldsIsMovedNotCopied) {
    ObjectPart part;
    part.object.shape = scene::BicubicPatch{};
    PartList a;
    a.push_back(part);
    const Vec3* points = std::get<scene::BicubicPatch>(a[0].object.shape).points.data();
    { const PartList b(a); }  // shares a's parts, then lets them go
    EXPECT_TRUE(a.shared());
    EXPECT_EQ(std::get<scene::BicubicPatch>(a[0].object.shape).points.data(), points);
    const PartList c(a);
    std::get<scene::BicubicPatch>(a[0].object.shape).points[0].x = 7.0;
    EXPECT_NE(std::get<scene::BicubicPatch>(a[0].object.shape).points.data(), points);
    EXPECT_EQ(std::get<scene::BicubicPatch>(c[0].object.shape).points.data(), points);
    EXPECT_EQ(std::get<scene::BicubicPatch>(c[0].object.shape).points[0].x, 0.0);
}

// The untextured parts of a textured union inside a union share its texture, one value, not a 3 KB copy each; a
// part that then changes its texture gets its own, leaving the others'.
TEST(SharedObjects, PartsOfATexturedUnionShareItsTexture) {
    const Scene s = test::parse_ok(
        "union { union { sphere { 0, 1 } sphere { x, 1 } sphere { y, 1 } pigment { rgb x } }"
        " light_group { union { sphere { z, 1 } sphere { -z, 1 } pigment { rgb y } } } }\n");
    ASSERT_EQ(s.objects.size(), 5u);
    EXPECT_TRUE(s.objects[0].texture.shares(s.objects[1].texture));
    EXPECT_TRUE(s.objects[0].texture.shares(s.objects[2].texture));
    EXPECT_TRUE(s.objects[3].texture.shares(s.objects[4].texture));
    EXPECT_FALSE(s.objects[0].texture.shares(s.objects[3].texture));
    const Scene t = test::parse_ok(
        "#declare U = union { union { sphere { 0, 1 } sphere { x, 1 } pigment { rgb x } } }\n"
        "object { U }\nobject { U pigment { rgb z } }\n");
    ASSERT_EQ(t.objects.size(), 4u);
    EXPECT_EQ(t.objects[0].texture->pigment.color.rgb(), (Vec3{1, 0, 0}));
    EXPECT_EQ(t.objects[2].texture->pigment.color.rgb(), (Vec3{1, 0, 0}));
}

// A transform after a union's texture moves that one texture once: the parts still share one value, equal to the
// pattern transform a single object with the same modifiers gets.
TEST(SharedObjects, TransformedPartsOfATexturedUnionStillShareItsTexture) {
    const Scene s = test::parse_ok(
        "union { sphere { 0, 1 } sphere { x, 1 } sphere { y, 1 } pigment { checker } translate x rotate 30*y }\n"
        "sphere { 0, 1 pigment { checker } translate x rotate 30*y }\n");
    ASSERT_EQ(s.objects.size(), 4u);
    EXPECT_TRUE(s.objects[0].texture.shares(s.objects[1].texture));
    EXPECT_TRUE(s.objects[0].texture.shares(s.objects[2].texture));
    const Vec3 p{0.3, -1.2, 2.5};
    EXPECT_EQ(s.objects[0].texture->pigment.pattern.transform.point(p),
              s.objects[3].texture->pigment.pattern.transform.point(p));
    EXPECT_NE(s.objects[0].texture->pigment.pattern.transform.point(p), p);
}

// Objects a loop writes with equal textures of their own share one texture value; a different one stays apart.
TEST(SharedObjects, EqualTexturesOfObjectsInALoopShareOneValue) {
    const Scene s = test::parse_ok(
        "#declare I = 0;\n#while (I < 5)\n  sphere { I*x, 0.4 pigment { rgb 1 } finish { phong 1 } }\n"
        "  #declare I = I + 1;\n#end\nsphere { 9*x, 1 pigment { rgb x } finish { phong 1 } }\n");
    ASSERT_EQ(s.objects.size(), 6u);
    for (std::size_t i = 1; i < 5; ++i) EXPECT_TRUE(s.objects[0].texture.shares(s.objects[i].texture)) << i;
    EXPECT_FALSE(s.objects[5].texture.shares(s.objects[0].texture));
    EXPECT_EQ(s.objects[0].texture->pigment.color.rgb(), (Vec3{1, 1, 1}));
    EXPECT_EQ(s.objects[0].texture->finish.phong, 1.0);
    EXPECT_EQ(s.objects[5].texture->pigment.color.rgb(), (Vec3{1, 0, 0}));
}

// Function patterns calling different declared pattern functions look equal (a program compares its calls of
// declared functions by count): objects with them keep textures of their own.
TEST(SharedObjects, TexturesWithFunctionPatternsAreNotShared) {
    const Scene s = test::parse_ok(
        "#declare F1 = function { pattern { bozo } }\n#declare F2 = function { pattern { granite } }\n"
        "sphere { 0, 1 pigment { function { F1(x, y, z) } } }\n"
        "sphere { x, 1 pigment { function { F2(x, y, z) } } }\n");
    ASSERT_EQ(s.objects.size(), 2u);
    EXPECT_FALSE(s.objects[0].texture.shares(s.objects[1].texture));
}

// Uses of a declared object share its parts until they change them (PartList): a later #declare of the name, and
// the transforms and textures of each use, must still leave every other use as POV-Ray's copies would be.
TEST(SharedObjects, ARedeclaredNameLeavesEarlierUsesAsTheyWere) {
    const Vec3 kOrigin{0, 0, 0};
    const Scene s = test::parse_ok(
        "#declare T = union { sphere { 0, 1 } box { -1, 1 } pigment { rgb x } }\n"
        "#declare A = object { T translate x }\n"
        "#declare B = object { T }\n"
        "#declare T = union { sphere { 0, 2 } }\n"
        "object { A }\n"
        "object { B translate y pigment { rgb z } }\n"
        "object { B }\n"
        "object { T }\n");
    ASSERT_EQ(s.objects.size(), 7u);
    auto radius = [&](std::size_t i) { return std::get<Sphere>(s.objects[i].shape).radius; };
    auto red = [&](std::size_t i) { return s.objects[i].texture->pigment.color.r; };
    auto blue = [&](std::size_t i) { return s.objects[i].texture->pigment.color.b; };
    // A: the first T, moved along x.
    EXPECT_EQ(radius(0), 1.0);
    EXPECT_TRUE(std::holds_alternative<Box>(s.objects[1].shape));
    EXPECT_EQ(s.objects[0].transform.point(kOrigin), (Vec3{1, 0, 0}));
    EXPECT_EQ(s.objects[1].transform.point(kOrigin), (Vec3{1, 0, 0}));
    EXPECT_EQ(red(0), 1.0);
    // B with its own transform and pigment, then B as declared: the first T, red, not moved.
    EXPECT_EQ(radius(2), 1.0);
    EXPECT_EQ(s.objects[2].transform.point(kOrigin), (Vec3{0, 1, 0}));
    EXPECT_EQ(blue(2), 1.0);
    EXPECT_EQ(red(2), 0.0);
    EXPECT_EQ(radius(4), 1.0);
    EXPECT_EQ(s.objects[4].transform.point(kOrigin), (Vec3{0, 0, 0}));
    EXPECT_EQ(red(4), 1.0);
    EXPECT_EQ(blue(4), 0.0);
    // The redeclared T.
    EXPECT_EQ(radius(6), 2.0);
}

TEST(SharedObjects, AUseOfALongDeclaredUnionCopiesNothingUntilPlaced) {
    // 20,000 levels of `union { object { U } sphere { } }`: each level shares U's parts, so the loop is linear
    // (the times are in docs/reports/deep_csg.md); the placed copies are whole and in order.
    const Scene s = test::parse_ok("#declare U = sphere { 0, 1 }\n#for (I, 1, 20000)\n"
                                   "  #declare U = union { object { U } sphere { <I, 0, 0>, 1 } }\n#end\n"
                                   "object { U }\nobject { U translate y }\n");
    ASSERT_EQ(s.objects.size(), 40002u);
    for (std::size_t i = 0; i < 20001; ++i) {
        const auto& a = std::get<Sphere>(s.objects[i].shape);
        ASSERT_EQ(a.center, (Vec3{static_cast<double>(i), 0, 0})) << i;
        ASSERT_EQ(std::get<Sphere>(s.objects[20001 + i].shape), a) << i;
        ASSERT_EQ(s.objects[20001 + i].transform.point(a.center), (a.center + Vec3{0, 1, 0})) << i;
    }
}

}  // namespace
}  // namespace wardray::parser
