// Tests of deferred library declarations: a library file's pigments, finishes and textures are read at their
// first use, and must read exactly as they would have where they stand.
#include <cstdio>
#include <iterator>

#include "tests/parser/test_util.h"

namespace wardray::parser {
namespace {

using test::TempDir;

// Parses `scene` (written as dir/scene/s.pov) with dir/lib as the library path, deferring or not.
ParseResult parse_with_library(const TempDir& dir, const std::string& scene, bool defer) {
    const auto main = dir.write("scene/s.pov", "global_settings { assumed_gamma 1 }\n" + scene);
    ParseOptions o;
    o.library_paths = {dir.path() / "lib"};
    o.defer_library_declarations = defer;
    return parse_file(main, o);
}

const Color& color_of(const Scene& s, std::size_t object) { return s.objects.at(object).texture->pigment.color; }

TEST(DeferredDeclarations, ReadAsWhereTheyStand) {
    TempDir dir;
    dir.write("lib/l.inc", R"(
        #declare C1 = rgb <1, 0, 0>;
        #declare C2 = rgb <0, 0.5, 0>;
        #local L = rgb <0, 0, 1>;
        #declare ByParameter = pigment { C1 }
        #declare ByRebinding = pigment { C2 }
        #declare ByLocal = pigment { L }
        #version 3.5;
        #declare ByVersion = pigment { rgb version / 10 }
        #version 3.7;
        #declare Layered = texture { pigment { ByParameter } } texture { pigment { rgbt <0, 1, 0, 0.5> } }
        #declare Defaults = texture { pigment { rgb 1 } }
    )");
    const std::string scene = R"(
        #include "l.inc"
        #macro M(C1) sphere { 0, 1 pigment { ByParameter } } #end
        M(rgb 0)
        #declare C2 = rgb <0, 0, 0.25>;
        sphere { 0, 1 pigment { ByRebinding } }
        sphere { 0, 1 pigment { ByLocal } }
        sphere { 0, 1 pigment { ByVersion } }
        sphere { 0, 1 texture { Layered } }
        #default { finish { ambient 0.5 } }
        sphere { 0, 1 texture { Defaults } }
    )";
    for (const bool defer : {true, false}) {
        SCOPED_TRACE(defer ? "deferred" : "in place");
        const ParseResult r = parse_with_library(dir, scene, defer);
        ASSERT_TRUE(r.ok()) << test::all_diagnostics(r);
        const Scene& s = *r.scene;
        ASSERT_EQ(s.objects.size(), 6u);
        EXPECT_EQ(color_of(s, 0).r, 1.0);   // a macro parameter named C1 does not change what the pigment read
        EXPECT_EQ(color_of(s, 1).g, 0.5);   // nor does rebinding C2 after the declaration
        EXPECT_EQ(color_of(s, 2).b, 1.0);   // the include file's #local is gone by the time it is used
        EXPECT_NEAR(color_of(s, 3).r, 0.35, 1e-12);  // read under the #version it was declared under
        ASSERT_EQ(s.objects[4].texture->layers.size(), 1u);
        EXPECT_EQ(color_of(s, 4).r, 1.0);
        EXPECT_EQ(s.objects[4].texture->layers[0].pigment.color.transmit, 0.5);
        EXPECT_NEAR(s.objects[5].texture->finish.ambient.r, 0.1, 1e-12);  // the #default of its own place
    }
}

TEST(DeferredDeclarations, RandomNumbersAreDrawnInOrder) {
    TempDir dir;
    dir.write("lib/r.inc", "#declare S = seed(7);\n#declare R = pigment { rgb rand(S) }\n");
    const std::string scene = "#include \"r.inc\"\n#declare X = rand(S);\n"
                              "sphere { <X, 0, 0>, 1 pigment { R } }\n";
    const ParseResult deferred = parse_with_library(dir, scene, true);
    const ParseResult in_place = parse_with_library(dir, scene, false);
    ASSERT_TRUE(deferred.ok() && in_place.ok()) << test::all_diagnostics(deferred) << test::all_diagnostics(in_place);
    EXPECT_EQ(color_of(*deferred.scene, 0).r, color_of(*in_place.scene, 0).r);
    EXPECT_EQ(std::get<Sphere>(deferred.scene->objects[0].shape).center.x,
              std::get<Sphere>(in_place.scene->objects[0].shape).center.x);
}

TEST(DeferredDeclarations, MistakesShowWhereWrittenWhenUsedOrChecked) {
    TempDir dir;
    dir.write("lib/b.inc", "#declare Fine = pigment { rgb 1 }\n#declare Broken = pigment { rgb 1 phong 1 }\n");
    // Unused, it costs nothing and says nothing; evaluated in place (as --check does) it is an error.
    EXPECT_TRUE(parse_with_library(dir, "#include \"b.inc\"\nsphere { 0, 1 pigment { Fine } }\n", true).ok());
    const ParseResult checked = parse_with_library(dir, "#include \"b.inc\"\n", false);
    ASSERT_FALSE(checked.ok());
    EXPECT_EQ(checked.diagnostics[0].loc.line, 2u);
    // Used, the error points into the library file and names the declaration.
    const ParseResult used = parse_with_library(dir, "#include \"b.inc\"\nsphere { 0, 1 pigment { Broken } }\n", true);
    ASSERT_FALSE(used.ok());
    const Diagnostic& d = used.diagnostics[0];
    EXPECT_EQ(d.loc.path, (dir.path() / "lib/b.inc").string());
    EXPECT_EQ(d.loc.line, 2u);
    EXPECT_EQ(d.loc.column, 35u);
    EXPECT_EQ(d.message, checked.diagnostics[0].message);
    ASSERT_FALSE(d.notes.empty());
    EXPECT_EQ(d.notes[0], "in the declaration of 'Broken', read at its first use");
}

TEST(DeferredDeclarations, LibraryFileIncludedTwice) {
    // The tokens of a finished library file are released; a second #include lexes it again.
    TempDir dir;
    dir.write("lib/twice.inc", "#declare Count = Count + 1;\n#declare Z = pigment { rgb <Count / 4, 0, 0> }\n");
    const ParseResult r = parse_with_library(
        dir, "#declare Count = 0;\n#include \"twice.inc\"\n#include \"twice.inc\"\nsphere { 0, 1 pigment { Z } }\n",
        true);
    ASSERT_TRUE(r.ok()) << test::all_diagnostics(r);
    EXPECT_EQ(color_of(*r.scene, 0).r, 0.5);
}

TEST(DeferredDeclarations, MacrosOfAFinishedLibraryFile) {
    // A finished library file keeps only its macros' bodies; calls still read them, and report into the file.
    TempDir dir;
    dir.write("lib/m.inc", "#declare Before = 1;\n#macro Twice(X) (2 * X) #end\n#declare Between = 2;\n"
                           "#macro Broken() (1 + ) #end\n");
    ParseResult r = parse_with_library(dir, "#include \"m.inc\"\nsphere { 0, Twice(Twice(Between)) }\n", true);
    ASSERT_TRUE(r.ok()) << test::all_diagnostics(r);
    EXPECT_EQ(std::get<Sphere>(r.scene->objects[0].shape).radius, 8.0);
    r = parse_with_library(dir, "#include \"m.inc\"\nsphere { 0, Broken() }\n", true);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.diagnostics[0].loc.path, (dir.path() / "lib/m.inc").string());
    EXPECT_EQ(r.diagnostics[0].loc.line, 4u);
    EXPECT_EQ(r.diagnostics[0].loc.column, 22u);
}

// The example scenes that include files describe the same scene whether the library files' declarations are
// deferred or read in place.
TEST(DeferredDeclarations, ExampleScenesDescribeTheSameScene) {
    const std::filesystem::path root = "/usr/share/doc/povray/examples";
    if (!std::filesystem::exists(root)) GTEST_SKIP() << "povray-examples is not installed";
    std::size_t compared = 0;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(root)) {
        if (entry.path().extension() != ".pov") continue;
        std::ifstream in(entry.path());
        const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        if (text.find("#include") == std::string::npos) continue;
        ParseOptions o = test::default_options();
        o.defer_library_declarations = false;
        const ParseResult in_place = parse_file(entry.path(), o);
        if (!in_place.ok()) continue;  // scenes needing trace() or files this test does not provide
        o.defer_library_declarations = true;
        const ParseResult deferred = parse_file(entry.path(), o);
        ASSERT_TRUE(deferred.ok()) << entry.path() << "\n" << test::all_diagnostics(deferred);
        const Scene& a = *in_place.scene;
        const Scene& b = *deferred.scene;
        EXPECT_TRUE(a.objects == b.objects) << entry.path();
        EXPECT_TRUE(a.lights == b.lights && a.camera == b.camera) << entry.path();
        EXPECT_TRUE(a.global == b.global && a.background == b.background) << entry.path();
        EXPECT_TRUE(a.sky_sphere == b.sky_sphere && a.fogs == b.fogs && a.rainbows == b.rainbows) << entry.path();
        ++compared;
    }
    EXPECT_GE(compared, 200u);
    std::printf("compared %zu example scenes\n", compared);
}

TEST(DeferredDeclarations, SceneFilesAreReadInPlace) {
    // Only library files defer: a mistake in the scene's own declaration is reported even when unused.
    TempDir dir;
    dir.write("scene/own.inc", "#declare Broken = pigment { rgb 1 phong 1 }\n");
    EXPECT_FALSE(parse_with_library(dir, "#include \"own.inc\"\n", true).ok());
}

}  // namespace
}  // namespace wardray::parser
