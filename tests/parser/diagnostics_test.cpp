// Golden tests of diagnostics as users see them, error recovery and the error limit.
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

}  // namespace
}  // namespace wardray::parser
