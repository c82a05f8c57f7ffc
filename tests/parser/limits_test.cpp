// Tests of the guard rails: each limit stops the parse with an error that names the limit and its switch.
#include <filesystem>
#include <fstream>

#include "tests/parser/test_util.h"

namespace wardray::parser {
namespace {

std::string first_error(const ParseResult& r) {
    for (const auto& d : r.diagnostics)
        if (d.severity == Severity::Error) return d.message;
    return {};
}

TEST(Limits, LoopIterations) {
    ParseOptions o = test::default_options();
    o.max_loop_iterations = 1000;
    const ParseResult r = test::parse_fail("#declare I = 0;\n#while (1)\n  #declare I = I + 1;\n#end\n", o);
    EXPECT_EQ(first_error(r),
              "loops ran more than the limit of 1000 iterations in total (endless #while?); raise it with "
              "--max-loop-iterations");
    EXPECT_EQ(r.diagnostics[0].loc.line, 2u);
    o.max_loop_iterations = 2000;
    test::parse_ok("#for (I, 1, 1500) #end\n", o);
}

TEST(Limits, MacroRecursionDepth) {
    ParseOptions o = test::default_options();
    o.max_macro_depth = 50;
    const ParseResult r = test::parse_fail("#macro Down(N) Down(N + 1) #end\nDown(0)\n", o);
    EXPECT_EQ(first_error(r),
              "macro calls nest deeper than the limit of 50 (runaway recursion?); raise it with --max-macro-depth");
    test::parse_ok("#macro Count(N) #if (N > 0) Count(N - 1) #end #end\nCount(40)\n", o);
}

TEST(Limits, IncludeDepth) {
    const auto dir = std::filesystem::temp_directory_path() / "wardray_limits_include";
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "self.inc") << "#include \"self.inc\"\n";
    ParseOptions o = test::default_options();
    o.max_include_depth = 8;
    const ParseResult r = parse_string("#include \"self.inc\"\n", (dir / "s.pov").string(), o);
    EXPECT_EQ(first_error(r),
              "#include files nest deeper than the limit of 8 (recursive #include?); raise it with "
              "--max-include-depth");
    std::filesystem::remove_all(dir);
}

TEST(Limits, ArraySize) {
    ParseOptions o = test::default_options();
    o.max_array_elements = 1000;
    const ParseResult r = test::parse_fail("#declare A = array[100][11];\n", o);
    EXPECT_EQ(first_error(r), "array has more elements than the limit of 1000; raise it with --max-array-size");
    EXPECT_EQ(r.diagnostics[0].loc.column, 25u);
    test::parse_ok("#declare A = array[100][10];\n", o);
}

TEST(Limits, StringLength) {
    ParseOptions o = test::default_options();
    o.max_string_length = 100;
    const ParseResult r = test::parse_fail(
        "#declare S = \"0123456789\";\n#while (1) #declare S = concat(S, S); #end\n", o);
    EXPECT_EQ(first_error(r), "string longer than the limit of 100 characters; raise it with --max-string-length");
}

}  // namespace
}  // namespace wardray::parser
