// Tests of the guard rails: each limit stops the parse with an error that names the limit and its switch.
#include <cmath>
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

TEST(Limits, MemoryFileWrittenWhileWritesAreOff) {
    ParseOptions o = test::default_options();
    o.max_memory_file_bytes = 1000;
    const ParseResult r = test::parse_fail(
        "#fopen F \"log.txt\" write\n#while (1)\n  #write (F, \"0123456789\")\n#end\n", o);
    EXPECT_NE(first_error(r).find("grew past 1000 bytes"), std::string::npos) << first_error(r);
    EXPECT_NE(first_error(r).find("raise it with --max-memory-file"), std::string::npos) << first_error(r);
    EXPECT_EQ(test::count_errors(r), 1u);
}

TEST(Limits, RecoveryInALoopOfUnclosedBlocks) {
    const ParseResult r =
        test::parse_fail("#declare I = 0;\n#while (1)\n  #declare I = I + 1;\n  union { union { x ^\n#end\n");
    EXPECT_NE(test::all_diagnostics(r).find("while skipping a failed statement"), std::string::npos)
        << test::all_diagnostics(r);
}

// Values that are not finite stop at the expression or literal that made them.
TEST(Limits, NonFiniteValuesAreErrorsAtTheirSource) {
    for (const char* text : {"#declare X = pow(10, 400);\n", "#declare X = 0 * 1e999;\n",
                             "sphere { 0, 1e308 * 10 }\n", "#declare V = <1e308, 0, 0> * 10;\n"}) {
        const ParseResult r = test::parse_fail(text);
        ASSERT_FALSE(r.diagnostics.empty()) << text;
        EXPECT_EQ(r.diagnostics[0].loc.line, 1u) << text;
        EXPECT_GT(r.diagnostics[0].loc.column, 1u) << text;
    }
    test::parse_ok("#declare Tiny = 1e-999;\n#declare Big = 1e308;\n");
}

// POV-Ray compat: an all-zero matrix column is a scale by 0 changed to 1 (a warning); a singular matrix is an
// error.
TEST(Limits, SingularMatricesAsPovRayTreatsThem) {
    const Scene s = test::parse_ok("sphere { 0, 1 matrix <1, 0, 0,  0, 0, 0,  0, 0, 1,  0, 0, 0> }\n");
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_TRUE(s.objects[0].transform.is_invertible());
    ASSERT_EQ(s.warnings.size(), 1u);
    EXPECT_NE(s.warnings[0].message.find("matrix column 2 is zero"), std::string::npos);
    const ParseResult r = test::parse_fail("sphere { 0, 1 matrix <1, 1, 0,  1, 1, 0,  0, 0, 1,  0, 0, 0> }\n");
    EXPECT_EQ(first_error(r), "matrix is singular: it flattens space, so the object has no inverse");
    EXPECT_EQ(r.diagnostics[0].loc.column, 15u);
}

// A composed transform's inverse is the composition of the inverses, as POV-Ray composes them: re-inverting the
// product judged woods.inc's `scale <0.01, 0.01, 100000>` followed by `rotate x*90` singular and dropped it.
TEST(Limits, StretchedThenRotatedTransformKeepsItsInverse) {
    const Scene s = test::parse_ok("sphere { 0, 1 scale <0.01, 0.01, 100000> rotate x*90 translate <1, 2, 3> }\n");
    ASSERT_EQ(s.objects.size(), 1u);
    const Transform& xf = s.objects[0].transform;
    ASSERT_TRUE(xf.is_invertible());
    for (const Vec3 p : {Vec3{0.3, -0.7, 2.0}, Vec3{-50, 4e4, 1e-3}}) {
        const Vec3 back = xf.inverse_point(xf.point(p));
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(back[k], p[k], 1e-9 * (1 + std::fabs(p[k]))) << k;
    }
    // Object space z (stretched 1e5) lies along world -y after the rotation.
    const Vec3 q = xf.inverse_point(Vec3{1, 2 - 1e5, 3});
    EXPECT_NEAR(q[2], 1.0, 1e-9);
}

// An object redeclared from its own value inherits the warnings of what it holds once per declaration; collecting
// them once per lookup multiplied them with every redeclaration, so this parse never finished (arosFractal.pov).
TEST(Limits, RedeclaredObjectKeepsOneCopyOfItsWarnings) {
    const Scene s = test::parse_ok(R"(
        #declare Ring = torus { 1, 0.1 radiosity { importance 0.5 } }
        #declare U = object { Ring }
        #for (I, 1, 40)
          #declare U = union { object { U } object { Ring translate I * x } }
        #end
        object { U }
    )");
    ASSERT_EQ(s.objects.size(), 41u);
    std::size_t importance_warnings = 0;
    for (const Diagnostic& d : s.warnings) importance_warnings += d.message == "object radiosity importance is not rendered yet";
    EXPECT_EQ(importance_warnings, 1u);
}

}  // namespace
}  // namespace wardray::parser
