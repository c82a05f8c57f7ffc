// Golden tests of diagnostics as users see them, error recovery and the error limit.
#include <filesystem>
#include <fstream>

#include "tests/parser/test_util.h"

namespace wardray::parser {
namespace {

TEST(Diagnostics, UndeclaredIdentifierWithCaretAndSuggestion) {
    const ParseResult r = test::parse_fail(
        "#declare Green = rgb <0, 1, 0>;\nsphere { 0, 1\n  pigment { color Gren }\n}\n");
    ASSERT_FALSE(r.diagnostics.empty());
    EXPECT_EQ(format_diagnostic(r.diagnostics[0]),
              "test.pov:3:19: error: undeclared identifier 'Gren'\n"
              "    3 |   pigment { color Gren }\n"
              "      |                   ^~~~\n"
              "note: did you mean 'Green'?\n");
}

TEST(Diagnostics, KeywordSuggestion) {
    const ParseResult r = test::parse_fail("spher { 0, 1 }\n");
    ASSERT_FALSE(r.diagnostics.empty());
    ASSERT_EQ(r.diagnostics[0].notes.size(), 1u);
    EXPECT_EQ(r.diagnostics[0].notes[0], "did you mean 'sphere'?");
}

TEST(Diagnostics, UnterminatedComment) {
    const ParseResult r = test::parse_fail("sphere { 0, 1 }\n  /* never closed\n");
    ASSERT_FALSE(r.diagnostics.empty());
    EXPECT_EQ(format_diagnostic(r.diagnostics[0]),
              "test.pov:2:3: error: unterminated comment\n"
              "    2 |   /* never closed\n"
              "      |   ^~\n");
}

TEST(Diagnostics, MissingSceneFile) {
    const ParseResult r = parse_file("nope/missing.pov", test::default_options());
    ASSERT_FALSE(r.ok());
    ASSERT_EQ(r.diagnostics.size(), 1u);
    EXPECT_EQ(format_diagnostic(r.diagnostics[0]),
              "error: cannot open scene file 'nope/missing.pov': No such file or directory\n");
}

TEST(Diagnostics, SeveralErrorsAreCollected) {
    const ParseResult r = test::parse_fail(
        "sphere { 0, Foo }\nbox { 0, 1 pigment { color Bar } }\nsphere { 0, 1 }\nplane { y, Baz }\n");
    EXPECT_EQ(test::count_errors(r), 3u) << test::all_diagnostics(r);
    EXPECT_EQ(r.diagnostics[1].loc.line, 2u);
    EXPECT_EQ(r.diagnostics[2].loc.line, 4u);
}

TEST(Diagnostics, StopsAtErrorLimit) {
    std::string text;
    for (int i = 0; i < 50; ++i) text += "sphere { 0, Missing" + std::to_string(i) + " }\n";
    ParseOptions o = test::default_options();
    o.max_errors = 5;
    const ParseResult r = test::parse_fail(text, o);
    EXPECT_EQ(test::count_errors(r), 5u);
}

TEST(Diagnostics, ErrorInDirectiveOperandsIsTheOnlyOne) {
    // Each snippet has one mistake; the rest of the directive (and of an #if/#while/... its block, with its
    // #else and #end) must not report again, nor the statements after it, nor uses of what it failed to declare.
    const char* const snippets[] = {
        "#if (Undeclared) sphere { 0, 1 } #else sphere { 0, 2 } #end\nsphere { 0, 3 }\n",
        "#if (1 +) sphere { 0, 1 } #end\n",
        "#while (Foo < 3) #end\n",
        "#for (I, 0, Q) sphere { 0, I } #end\n",
        "#switch (Q) #case (1) sphere { 0, 1 } #break #end\n",
        "#switch (1) #case (Q) #break #end\nsphere { 0, 1 }\n",
        "#if (0) #elseif (Q) #end\n",
        "#ifdef (1) #end\n",
        "#declare X = 1 + Q * 2;\nsphere { 0, X }\nsphere { 0, 1 }\n",
        "#declare X = sphere { 0, Q };\nobject { X }\n",
        "#version Q;\nsphere { 0, 1 }\n",
        "#debug concat(\"a\", Q)\nsphere { 0, 1 }\n",
        "#macro M(A) #local B = Q; 1 #end\n#if (M(1)) #end\nsphere { 0, 1 }\n",
        "sphere { 0, 1 #if (Q) #end pigment { rgb 1 } }\nsphere { 0, 1 }\n",
        "#else sphere { 0, 1 } #end\n",
    };
    for (const char* text : snippets) {
        const ParseResult r = test::parse_fail(text);
        EXPECT_EQ(test::count_errors(r), 1u) << text << "\n" << test::all_diagnostics(r);
    }
}

TEST(Diagnostics, MissingEndAndStrayEnd) {
    ParseResult r = test::parse_fail("#if (1)\nsphere { 0, 1 }\n");
    EXPECT_NE(test::all_diagnostics(r).find("test.pov:1:1: error: '#if' has no matching #end"), std::string::npos)
        << test::all_diagnostics(r);
    r = test::parse_fail("#end\n");
    EXPECT_NE(test::all_diagnostics(r).find("#end without matching"), std::string::npos);
}

TEST(Diagnostics, GarbageNeverCrashes) {
    const char* inputs[] = {"{", "}", "sphere {", "sphere { <1,2", "#declare", "#declare X =", "#if (", "#macro M(",
                            "#include", "union { union { union {", "camera { look_at", "<<<<<<<<", "#while (1)",
                            "#for (I, 0, 10", "#switch (1) #case (1)", "object { }", "#macro M() M #end M()",
                            "light_source { }", "\"unterminated", "/* /* */", "#version", "global_settings { radiosity {"};
    for (const char* text : inputs) {
        const ParseResult r = parse_string(text, "g.pov", test::default_options());
        EXPECT_FALSE(r.ok()) << text;
        for (const auto& d : r.diagnostics) EXPECT_FALSE(format_diagnostic(d).empty());
    }
}


// --- Golden texts: one test per kind of mistake, the whole first diagnostic as the user sees it. ---

/// The first diagnostic of parsing `text` as test.pov, formatted.
std::string first_diagnostic(const std::string& text, ParseOptions o = test::default_options()) {
    const ParseResult r = parse_string(text, "test.pov", o);
    EXPECT_FALSE(r.ok());
    return r.diagnostics.empty() ? std::string() : format_diagnostic(r.diagnostics[0]);
}

TEST(Golden, MisspeltKeyword) {
    const ParseResult r = test::parse_fail("spher { 0, 1 }\nsphere { 0, 1 }\n");
    EXPECT_EQ(test::all_diagnostics(r),
              "test.pov:1:1: error: undeclared identifier 'spher'\n"
              "    1 | spher { 0, 1 }\n"
              "      | ^~~~~\n"
              "note: did you mean 'sphere'?\n"
              "test.pov: warning: assumed_gamma not given in a scene for POV-Ray before 3.7 (by its #version, or having "
              "none): gamma handling is off, as in POV-Ray 3.6\n");
}

TEST(Golden, UnclosedBraceAtEndOfFile) {
    EXPECT_EQ(first_diagnostic("sphere { 0, 1\n  pigment { rgb 1 }\n"),
              "test.pov:1:8: error: this '{' is never closed: the file ends before its '}'\n"
              "    1 | sphere { 0, 1\n"
              "      |        ^\n"
              "note: the file ends at line 3 inside this block\n");
}

TEST(Golden, VectorWhereFloatExpected) {
    EXPECT_EQ(first_diagnostic("#declare V = <1, 2, 3>;\nsphere { 0, V }\n"),
              "test.pov:2:13: error: expected a float but found a vector\n"
              "    2 | sphere { 0, V }\n"
              "      |             ^\n");
}

TEST(Golden, OperatorOnAPigment) {
    EXPECT_EQ(first_diagnostic("#declare P = pigment { rgb 1 }\n#declare A = P + 1;\n"),
              "test.pov:2:16: error: '+' cannot be applied to a pigment\n"
              "    2 | #declare A = P + 1;\n"
              "      |                ^\n");
}

TEST(Golden, DivisionByZero) {
    // POV-Ray compat: a warning, not an error (the #error ends the parse so that the diagnostics are kept).
    EXPECT_EQ(first_diagnostic("#declare A = 1 / (2 - 2);\n#error \"stop\"\n"),
              "test.pov:1:16: warning: Divide by zero.\n"
              "    1 | #declare A = 1 / (2 - 2);\n"
              "      |                ^\n");
}

TEST(Golden, EndWithoutIf) {
    EXPECT_EQ(first_diagnostic("sphere { 0, 1 }\n#end\n"),
              "test.pov:2:1: error: #end without matching #if, #while, #for, #switch or #macro\n"
              "    2 | #end\n"
              "      | ^~~~\n");
}

TEST(Golden, IfWithoutEnd) {
    EXPECT_EQ(first_diagnostic("#if (1)\nsphere { 0, 1 }\n"),
              "test.pov:1:1: error: '#if' has no matching #end\n"
              "    1 | #if (1)\n"
              "      | ^~~\n");
}

TEST(Golden, MissingIncludeNamesTheSearchedFolders) {
    EXPECT_EQ(first_diagnostic("#include \"nosuch.inc\"\n"),
              "test.pov:1:10: error: cannot open include file 'nosuch.inc': No such file or directory\n"
              "    1 | #include \"nosuch.inc\"\n"
              "      |          ^~~~~~~~~~~~\n"
              "note: searched ., /usr/share/povray-3.7/include\n");
}

TEST(Golden, ErrorInsideAnIncludeShowsTheChain) {
    const auto dir = std::filesystem::temp_directory_path() / "wardray_golden_include";
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "outer.inc") << "// outer\n#include \"inner.inc\"\n";
    std::ofstream(dir / "inner.inc") << "#declare A = 1;\n#declare B = A + Missing;\n";
    const std::string scene = (dir / "s.pov").string();
    const ParseResult r = parse_string("\n#include \"outer.inc\"\n", scene, test::default_options());
    ASSERT_FALSE(r.diagnostics.empty());
    EXPECT_EQ(format_diagnostic(r.diagnostics[0]),
              (dir / "inner.inc").string() + ":2:18: error: undeclared identifier 'Missing'\n"
              "    2 | #declare B = A + Missing;\n"
              "      |                  ^~~~~~~\n"
              "note: included from " + (dir / "outer.inc").string() + ":2\n"
              "note: included from " + scene + ":2\n");
    std::filesystem::remove_all(dir);
}

TEST(Golden, ErrorInsideAMacroShowsTheCall) {
    EXPECT_EQ(first_diagnostic("#macro M(A)\n  sphere { 0, A + Q }\n#end\nM(1)\n"),
              "test.pov:2:19: error: undeclared identifier 'Q'\n"
              "    2 |   sphere { 0, A + Q }\n"
              "      |                   ^\n"
              "note: in macro 'M' invoked from test.pov:4\n");
}

TEST(Golden, WrongMacroArgumentCount) {
    EXPECT_EQ(first_diagnostic("#macro M(A, B) #end\nM(1, 2, 3)\n"),
              "test.pov:2:1: error: macro 'M' takes 2 parameter(s) but 3 were given\n"
              "    2 | M(1, 2, 3)\n"
              "      | ^\n");
    EXPECT_EQ(first_diagnostic("#macro M(A, B) #end\nM(1)\n"),
              "test.pov:2:1: error: macro 'M' is missing parameter 'B'\n"
              "    2 | M(1)\n"
              "      | ^\n");
}

TEST(Golden, ArrayIndexOutOfRange) {
    EXPECT_EQ(first_diagnostic("#declare A = array[3];\n#declare B = A[3];\n"),
              "test.pov:2:16: error: index 3 of 'A' is out of range (size 3)\n"
              "    2 | #declare B = A[3];\n"
              "      |                ^\n");
}

TEST(Golden, RunawayLoop) {
    ParseOptions o = test::default_options();
    o.max_loop_iterations = 1000;
    EXPECT_EQ(first_diagnostic("#while (1)\n#end\n", o),
              "test.pov:1:1: error: loops ran more than the limit of 1000 iterations in total (endless #while?); "
              "raise it with --max-loop-iterations\n"
              "    1 | #while (1)\n"
              "      | ^~~~~~\n");
}

TEST(Golden, RecursionDepth) {
    ParseOptions o = test::default_options();
    o.max_macro_depth = 20;
    EXPECT_EQ(first_diagnostic("#macro R(N) R(N+1) #end\nR(0)\n", o),
              "test.pov:1:13: error: macro calls nest deeper than the limit of 20 (runaway recursion?); raise it "
              "with --max-macro-depth\n"
              "    1 | #macro R(N) R(N+1) #end\n"
              "      |             ^\n"
              "note: in macro 'R' invoked from test.pov:1\n"
              "note: in macro 'R' invoked from test.pov:1\n"
              "note: in macro 'R' invoked from test.pov:1\n"
              "note: ... 14 more macro calls and includes ...\n"
              "note: in macro 'R' invoked from test.pov:1\n"
              "note: in macro 'R' invoked from test.pov:1\n"
              "note: in macro 'R' invoked from test.pov:2\n");
}

TEST(Golden, UnterminatedString) {
    const ParseResult r = test::parse_fail("#declare S = \"abc;\nsphere { 0, 1 }\n");
    EXPECT_EQ(test::all_diagnostics(r),
              "test.pov:1:14: error: unterminated string\n"
              "    1 | #declare S = \"abc;\n"
              "      |              ^\n");
}

TEST(Golden, RedeclaringAKeyword) {
    const ParseResult r = test::parse_fail("#declare sphere = 1;\nsphere { 0, 1 }\n");
    EXPECT_EQ(test::all_diagnostics(r),
              "test.pov:1:10: error: 'sphere' is a reserved word and cannot be declared\n"
              "    1 | #declare sphere = 1;\n"
              "      |          ^~~~~~\n"
              "test.pov: warning: assumed_gamma not given in a scene for POV-Ray before 3.7 (by its #version, or having "
              "none): gamma handling is off, as in POV-Ray 3.6\n");
}

TEST(Golden, UnknownDotItem) {
    EXPECT_EQ(first_diagnostic("#declare A = <1, 2, 3>;\n#declare B = A.q;\n"),
              "test.pov:2:16: error: unknown dot item '.q'\n"
              "    2 | #declare B = A.q;\n"
              "      |                ^\n");
}

TEST(Golden, FunctionBuiltinArgumentCount) {
    EXPECT_EQ(first_diagnostic("#declare F = function(a) { a + sin(a, 2) }\n"),
              "test.pov:1:32: error: 'sin' takes 1 argument(s) but 2 were given\n"
              "    1 | #declare F = function(a) { a + sin(a, 2) }\n"
              "      |                                ^~~\n");
}

TEST(Golden, FileReadOutsideAllowedFolders) {
    EXPECT_EQ(first_diagnostic("#fopen F \"/etc/hostname\" read\n"),
              "test.pov:1:10: error: reading '/etc/hostname' (#fopen read) is not allowed: files are read only "
              "from the scene's folder, the include path (+L, Library_Path) and the folders given with --read-path "
              "DIR\n"
              "    1 | #fopen F \"/etc/hostname\" read\n"
              "      |          ^~~~~~~~~~~~~~~\n");
}

TEST(Golden, GeometryQueryWithoutGeometryLayer) {
    EXPECT_EQ(first_diagnostic("#declare B = max_extent(sphere { 0, 1 });\n"),
              "test.pov:1:14: error: max_extent() needs the geometry layer, which this program did not provide\n"
              "    1 | #declare B = max_extent(sphere { 0, 1 });\n"
              "      |              ^~~~~~~~~~\n");
}

}  // namespace
}  // namespace wardray::parser
