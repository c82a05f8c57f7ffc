// Tests of the user-function stack machine and of `function { }` declarations and calls.
#include <cmath>
#include <thread>

#include "function/function_vm.h"
#include "tests/parser/test_util.h"

namespace wardray::parser {
namespace {

Instruction ins(Instruction::Op op, std::uint32_t a = 0, double value = 0.0) {
    Instruction i;
    i.op = op;
    i.a = a;
    i.value = value;
    return i;
}

TEST(FunctionVm, EvaluatesHandBuiltProgram) {
    // f(x, y) = x * x + 2 * y
    FunctionProgram p({"x", "y"});
    p.emit(ins(Instruction::Op::Arg, 0));
    p.emit(ins(Instruction::Op::Arg, 0));
    p.emit(ins(Instruction::Op::Mul));
    p.emit(ins(Instruction::Op::Const, 0, 2.0));
    p.emit(ins(Instruction::Op::Arg, 1));
    p.emit(ins(Instruction::Op::Mul));
    p.emit(ins(Instruction::Op::Add));
    const double args[] = {3.0, 4.0};
    EXPECT_EQ(p.evaluate(args), 17.0);
    EXPECT_EQ(p.arity(), 2u);
    EXPECT_TRUE(p.unsupported().empty());
}

TEST(FunctionVm, MissingArgumentsReadAsZero) {
    FunctionProgram p({"x", "y", "z"});
    p.emit(ins(Instruction::Op::Arg, 2));
    p.emit(ins(Instruction::Op::Const, 0, 1.0));
    p.emit(ins(Instruction::Op::Add));
    const double args[] = {5.0};
    EXPECT_EQ(p.evaluate(args), 1.0);
}

TEST(FunctionVm, UnsupportedCalleeIsReportedAndGivesZero) {
    auto internal = std::make_shared<FunctionProgram>(std::vector<std::string>{"x", "y", "z"});
    internal->emit_unsupported(3, "internal function 55 is not supported yet");
    FunctionProgram p({"x"});
    p.emit(ins(Instruction::Op::Const, 0, 1.0));
    p.emit(ins(Instruction::Op::Arg, 0));
    p.emit(ins(Instruction::Op::Arg, 0));
    p.emit(ins(Instruction::Op::Arg, 0));
    p.emit_call(internal, 3);
    p.emit(ins(Instruction::Op::Add));
    EXPECT_EQ(p.unsupported(), "internal function 55 is not supported yet");
    const double args[] = {2.0};
    EXPECT_EQ(p.evaluate(args), 1.0);
}

/// Appends `for local 0 = first while <= last: acc op= body()` as sum()/prod() compile it; `body` emits one value.
template <class Body>
void emit_loop(FunctionProgram& p, double first, double last, Instruction::Op combine, double neutral, Body body) {
    p.require_locals(2);
    p.emit(ins(Instruction::Op::Const, 0, first));
    p.emit(ins(Instruction::Op::StoreLocal, 0));
    p.emit(ins(Instruction::Op::Const, 0, last));
    p.emit(ins(Instruction::Op::StoreLocal, 1));
    p.emit(ins(Instruction::Op::Const, 0, neutral));
    Instruction test = ins(Instruction::Op::LoopTest);
    test.b = 0;
    const std::size_t skip = p.emit(test);
    Instruction next = ins(Instruction::Op::LoopNext, static_cast<std::uint32_t>(p.size()));
    next.b = 0;
    body();
    p.emit(ins(combine));
    p.emit(next);
    p.patch_jump(skip, p.size());
}

TEST(FunctionVm, LoopOverLocalSlot) {
    // sum(i, 1, 4, i * x) = 10 x
    FunctionProgram p({"x"});
    emit_loop(p, 1.0, 4.0, Instruction::Op::Add, 0.0, [&] {
        p.emit(ins(Instruction::Op::Local, 0));
        p.emit(ins(Instruction::Op::Arg, 0));
        p.emit(ins(Instruction::Op::Mul));
    });
    EXPECT_EQ(p.locals(), 2u);
    const double args[] = {2.0};
    EXPECT_EQ(p.evaluate(args), 20.0);
    // Evaluating again starts from fresh slots.
    EXPECT_EQ(p.evaluate(args), 20.0);
}

TEST(FunctionVm, LoopBoundsDecideTheCount) {
    const auto count = [](double first, double last) {
        FunctionProgram p({});
        emit_loop(p, first, last, Instruction::Op::Add, 0.0, [&] { p.emit(ins(Instruction::Op::Const, 0, 1.0)); });
        return p.evaluate({});
    };
    EXPECT_EQ(count(1.0, 4.0), 4.0);
    EXPECT_EQ(count(1.0, 4.999), 4.0);
    EXPECT_EQ(count(3.0, 3.0), 1.0);
    EXPECT_EQ(count(3.0, 2.999), 0.0);
    EXPECT_EQ(count(1.0, std::nan("")), 0.0);
    // A counter beyond 2^53 cannot step: POV-Ray loops forever there, the VM stops after one pass.
    EXPECT_EQ(count(1e17, 1e17 + 4096), 1.0);
}

TEST(FunctionVm, CalleeLocalsDoNotClobberTheCaller) {
    // G(a) = prod(j, 1, 3, a), F(x) = sum(i, 1, 2, G(x) + i): both use local slot 0.
    auto g = std::make_shared<FunctionProgram>(std::vector<std::string>{"a"});
    emit_loop(*g, 1.0, 3.0, Instruction::Op::Mul, 1.0, [&] { g->emit(ins(Instruction::Op::Arg, 0)); });
    FunctionProgram f({"x"});
    emit_loop(f, 1.0, 2.0, Instruction::Op::Add, 0.0, [&] {
        f.emit(ins(Instruction::Op::Arg, 0));
        f.emit_call(g, 1);
        f.emit(ins(Instruction::Op::Local, 0));
        f.emit(ins(Instruction::Op::Add));
    });
    const double args[] = {2.0};
    EXPECT_EQ(f.evaluate(args), 8.0 + 1.0 + 8.0 + 2.0);
}

/// Compiles `body` as `function(params) { body }` in a scene and evaluates it at `args`.
double eval(const std::string& declaration, const std::string& call) {
    const Scene s = test::parse_ok(declaration + "\n#declare R = " + call + ";\nsphere { 0, 1 translate <R, 0, 0> }\n");
    if (s.objects.empty()) return std::nan("");
    return s.objects[0].transform.point({0, 0, 0}).x;
}

TEST(UserFunctions, DeclaredAndCalled) {
    EXPECT_DOUBLE_EQ(eval("#declare F = function(a, b) { a * 2 + b }", "F(3, 4)"), 10.0);
    EXPECT_DOUBLE_EQ(eval("#declare F = function { x + 10 * y + 100 * z }", "F(1, 2, 3)"), 321.0);
    EXPECT_DOUBLE_EQ(eval("#declare F = function(x) { -x * -x - 1 }", "F(3)"), 8.0);
}

TEST(UserFunctions, PrecedenceComparisonsAndConditional) {
    EXPECT_DOUBLE_EQ(eval("#declare F = function(x) { 1 + 2 * x - 6 / 3 }", "F(4)"), 7.0);
    EXPECT_DOUBLE_EQ(eval("#declare F = function(x) { (x < 2) + (x >= 3) * 10 + (x = 5) * 100 }", "F(5)"), 110.0);
    EXPECT_DOUBLE_EQ(eval("#declare F = function(x) { x > 0 ? x : -x * 2 }", "F(-3)"), 6.0);
    EXPECT_DOUBLE_EQ(eval("#declare F = function(x) { x > 0 ? x : -x * 2 }", "F(3)"), 3.0);
    EXPECT_DOUBLE_EQ(eval("#declare F = function(x, y) { x & y | !x }", "F(0, 1)"), 1.0);
}

TEST(UserFunctions, MathBuiltins) {
    EXPECT_NEAR(eval("#declare F = function(x) { sin(x) * sin(x) + cos(x) * cos(x) }", "F(0.7)"), 1.0, 1e-12);
    EXPECT_DOUBLE_EQ(eval("#declare F = function(x) { sqrt(x) + pow(x, 2) + abs(-x) }", "F(4)"), 22.0);
    EXPECT_DOUBLE_EQ(eval("#declare F = function(x, y, z) { min(x, y, z) + max(x, y, z) * 10 }", "F(3, 1, 2)"),
                     31.0);
    EXPECT_DOUBLE_EQ(eval("#declare F = function(x) { select(x, -1, 0, 1) }", "F(-5)"), -1.0);
    EXPECT_DOUBLE_EQ(eval("#declare F = function(x) { select(x, -1, 1) }", "F(0)"), 1.0);
    EXPECT_DOUBLE_EQ(eval("#declare F = function(x) { mod(x, 3) + floor(2.5) + degrees(pi) }", "F(7)"), 183.0);
}

TEST(UserFunctions, CapturesDeclaredValuesAndCallsOtherFunctions) {
    EXPECT_DOUBLE_EQ(eval("#declare K = 3; #declare V = <1, 2, 3>;\n"
                          "#declare G = function(a) { a * K + V.z }\n#declare K = 100;\n"
                          "#declare F = function(a) { G(a) + G(1) }",
                          "F(2)"),
                     15.0);
}

TEST(UserFunctions, StandardIncludesDeclareFunctions) {
    EXPECT_DOUBLE_EQ(eval("#include \"math.inc\"", "f_sqr(3) + sgn(-2) + max3(1, 5, 2)"), 13.0);
    EXPECT_NEAR(eval("#include \"math.inc\"", "sind(30)"), 0.5, 1e-12);
    for (const char* inc : {"functions.inc", "math.inc", "shapes.inc", "transforms.inc"}) {
        const ParseResult r = parse_string(std::string("#include \"") + inc + "\"\n", "inc.pov",
                                           test::default_options());
        EXPECT_EQ(test::count_errors(r), 0u) << inc << "\n" << test::all_diagnostics(r);
    }
}

TEST(UserFunctions, TransformFunctionsFromTransformsInc) {
    const Scene s = test::parse_ok("#include \"transforms.inc\"\n"
                                   "#declare P = vtransform(<1, 0, 0>, transform { translate <0, 2, 0> });\n"
                                   "sphere { P, 1 }\n");
    ASSERT_EQ(s.objects.size(), 1u);
}

TEST(UserFunctions, UnevaluatedInternalFunctionIsAnErrorOnlyWhenCalled) {
    // internal(77) is POV-Ray's pattern function behind `function { pattern { ... } }`, not called by name.
    test::parse_ok("#declare G = function { internal(77) }\nsphere { 0, 1 }\n");
    ParseResult r = test::parse_fail("#declare G = function { internal(77) }\n#declare A = G(1, 2, 3);\n");
    EXPECT_NE(test::all_diagnostics(r).find(
                  "test.pov:2:14: error: internal function 77 is not supported yet (called through 'G')"),
              std::string::npos)
        << test::all_diagnostics(r);
    r = test::parse_fail("#declare F = function { internal(79) }\n");
    EXPECT_NE(test::all_diagnostics(r).find("test.pov:1:34: error: there is no internal function 79"),
              std::string::npos)
        << test::all_diagnostics(r);
}

TEST(UserFunctions, PatternFunctionWarnsWhenCalled) {
    const Scene s = test::parse_ok("#declare P = function { pattern { checker } }\n#declare A = P(1, 2, 3);\n"
                                   "sphere { 0, 1 }\n");
    bool warned = false;
    for (const auto& w : s.warnings) warned = warned || w.message.find("pattern function is not rendered") == 0;
    EXPECT_TRUE(warned);
}

TEST(UserFunctions, ParseTimePatternCallsUseTheScenesNoiseGenerator) {
    // POV-Ray evaluates a pattern function called at parse time with the scene's noise_generator as read so far,
    // as its render does (func_gradient.pov places its arrows where agate's noise 1 changes): here the pattern's
    // value is the generator it was handed, directly, through a float function, and before global_settings.
    ParseOptions options = test::default_options();
    options.pattern_value = [](const Pattern&, const Vec3&, int noise_generator) {
        return static_cast<double>(noise_generator);
    };
    const Scene s = test::parse_ok("#declare P = function { pattern { agate } }\n"
                                   "#declare G = function { P(x, y, z) + 10 }\n"
                                   "#declare Before = P(1, 2, 3);\n"
                                   "global_settings { noise_generator 1 }\n"
                                   "sphere { 0, 1 translate <Before, P(1, 2, 3), G(1, 2, 3)> }\n",
                                   options);
    ASSERT_EQ(s.objects.size(), 1u);
    const Vec3 c = s.objects[0].transform.point({0, 0, 0});
    EXPECT_EQ(c.x, 2.0);
    EXPECT_EQ(c.y, 1.0);
    EXPECT_EQ(c.z, 11.0);
}

TEST(UserFunctions, WrongArgumentCountAndUnknownName) {
    ParseResult r = test::parse_fail("#declare F = function(a, b) { a + b }\n#declare A = F(1);\n");
    EXPECT_NE(test::all_diagnostics(r).find("'F' takes 2 argument(s) but 1 were given"), std::string::npos)
        << test::all_diagnostics(r);
    r = test::parse_fail("#declare F = function(a) { a + bogus }\n");
    EXPECT_NE(test::all_diagnostics(r).find("undeclared identifier 'bogus'"), std::string::npos);
}

// The expected values of the sum()/prod() tests were printed by POV-Ray 3.7.0.10 with
//   #declare F = function(...) { BODY }  #debug concat(str(F(ARGS), 0, 6), "\n")
//   povray +W16 +H12 -D +Oout.png t.pov
// and checked by hand.

TEST(SumProd, SimpleSumsAndProducts) {
    // 1*2 + 2*2 + 3*2 + 4*2; POV-Ray: 20.000000
    EXPECT_DOUBLE_EQ(eval("#declare F = function { sum(i, 1, 4, i*x) }", "F(2, 0, 0)"), 20.0);
    // 4!; POV-Ray: 24.000000
    EXPECT_DOUBLE_EQ(eval("#declare F = function { prod(i, 1, 4, i) }", "F(0, 0, 0)"), 24.0);
    // 10 * (1+2+3) + 2*3; POV-Ray: 66.000000
    EXPECT_DOUBLE_EQ(eval("#declare F = function { sum(i, 1, 3, i) * 10 + prod(i, 2, 3, i) }", "F(0, 0, 0)"), 66.0);
    // 1 + 1/2 + 1/3 + 1/4 = 25/12; POV-Ray: 2.083333333333
    EXPECT_NEAR(eval("#declare F = function(a) { sum(i, 1, 4, 1/i) }", "F(5)"), 25.0 / 12.0, 1e-12);
    // The last value is included; POV-Ray: 3.000000
    EXPECT_DOUBLE_EQ(eval("#declare F = function { sum(i, 3, 3, i) }", "F(0, 0, 0)"), 3.0);
}

TEST(SumProd, EmptyRangesGiveTheNeutralValue) {
    // POV-Ray: 0.000000 and 1.000000
    EXPECT_DOUBLE_EQ(eval("#declare F = function { sum(i, 3, 1, i) }", "F(0, 0, 0)"), 0.0);
    EXPECT_DOUBLE_EQ(eval("#declare F = function { prod(i, 3, 1, i) }", "F(0, 0, 0)"), 1.0);
}

TEST(SumProd, NonIntegerBoundsStepByOneFromTheFirstValue) {
    // 0.5 + 1.5 + 2.5; POV-Ray: 4.500000
    EXPECT_DOUBLE_EQ(eval("#declare F = function { sum(i, 0.5, 3, i) }", "F(0, 0, 0)"), 4.5);
    // 1 + 2 + 3 (4 > 3.9); POV-Ray: 6.000000
    EXPECT_DOUBLE_EQ(eval("#declare F = function { sum(i, 1, 3.9, i) }", "F(0, 0, 0)"), 6.0);
    // -2.5 + -1.5 + -0.5; POV-Ray: -4.500000
    EXPECT_DOUBLE_EQ(eval("#declare F = function { sum(i, -2.5, -0.5, i) }", "F(0, 0, 0)"), -4.5);
    // 0.1 + 1.1 + 2.1 + 3.1 + 4.1; POV-Ray: 10.500000000000000
    EXPECT_NEAR(eval("#declare F = function { sum(i, 0.1, 5, i) }", "F(0, 0, 0)"), 10.5, 1e-12);
    // Bounds from arguments; the counter reaches 0.1 + 1 = 1.1 exactly: two passes; POV-Ray: 2.000000
    EXPECT_DOUBLE_EQ(eval("#declare F = function { sum(i, x, y, 1) }", "F(0.1, 1.1, 0)"), 2.0);
}

TEST(SumProd, Nesting) {
    // 1! + 2! + 3!; POV-Ray: 9.000000
    EXPECT_DOUBLE_EQ(eval("#declare F = function { sum(i, 1, 3, prod(j, 1, i, j)) }", "F(0, 0, 0)"), 9.0);
    // (1+2+3) + (2+3) + 3; POV-Ray: 14.000000
    EXPECT_DOUBLE_EQ(eval("#declare F = function(a) { sum(i, 1, 3, sum(j, i, 3, j)) }", "F(7)"), 14.0);
    // i=1: 6*(2*3) + i=2: 5*(3*4) + i=3: 3*(4*5); POV-Ray: 156.000000
    EXPECT_DOUBLE_EQ(
        eval("#declare F = function { sum(i, 1, 3, sum(j, i, 3, j) * prod(k, 1, 2, k + i)) }", "F(0, 0, 0)"), 156.0);
    // Sibling loops reuse the same name; POV-Ray: 11.000000
    EXPECT_DOUBLE_EQ(eval("#declare F = function(a) { sum(i, 1, 3, i) + sum(i, 2, 3, i) }", "F(7)"), 11.0);
    // A loop inside a function called from a loop.
    EXPECT_DOUBLE_EQ(eval("#declare G = function(n) { prod(j, 1, n, j) }\n"
                          "#declare F = function(a) { sum(i, 1, a, G(i)) }",
                          "F(4)"),
                     1.0 + 2.0 + 6.0 + 24.0);
}

TEST(SumProd, Shadowing) {
    // The inner i hides the outer one: 3 * (1+2); POV-Ray: 9.000000
    EXPECT_DOUBLE_EQ(eval("#declare F = function { sum(i, 1, 3, sum(i, 1, 2, i)) }", "F(0, 0, 0)"), 9.0);
    // A loop variable hides a parameter; POV-Ray: 6.000000
    EXPECT_DOUBLE_EQ(eval("#declare F = function(a) { sum(a, 1, 3, a) }", "F(10)"), 6.0);
    // but x, y, z still read the arguments (with a warning); POV-Ray: 30.000000 and 15.000000
    EXPECT_DOUBLE_EQ(eval("#declare F = function { sum(x, 1, 3, x) }", "F(10, 0, 0)"), 30.0);
    EXPECT_DOUBLE_EQ(eval("#declare F = function { sum(y, 1, 3, y) }", "F(0, 5, 0)"), 15.0);
    const Scene s = test::parse_ok("#declare F = function { sum(x, 1, 3, x) }\nsphere { 0, 1 }\n");
    bool warned = false;
    for (const auto& w : s.warnings)
        warned = warned || (w.message.find("'x' inside 'sum' still reads the function's x argument") == 0 &&
                            w.loc.line == 2 && w.loc.column == 29);  // parse_ok prepends a line
    EXPECT_TRUE(warned) << (s.warnings.empty() ? std::string("no warnings") : format_diagnostic(s.warnings[0]));
}

TEST(SumProd, ParametersAndTheLoopVariableInTheLastValue) {
    // 2^2 + 3^2 + 4^2 + 2; POV-Ray: 31.000000
    EXPECT_DOUBLE_EQ(eval("#declare F = function(a, b) { sum(k, a, b, k*k) + a }", "F(2, 4)"), 31.0);
    // 5!; POV-Ray: 120.000000
    EXPECT_DOUBLE_EQ(eval("#declare F = function(a) { prod(i, 1, a, i) }", "F(5)"), 120.0);
    // 3 * 7! + (1+2+3); POV-Ray: 15126.000000
    EXPECT_DOUBLE_EQ(eval("#declare F = function(a) { sum(i, 1, 3, prod(j, 1, a, j) + i) }", "F(7)"), 15126.0);
    // In the last value the variable holds the first value: 1 .. 1+2; POV-Ray: 6.000000
    EXPECT_DOUBLE_EQ(eval("#declare F = function(a) { sum(i, 1, i+2, i) }", "F(7)"), 6.0);
    // Inside select(); POV-Ray: 10.000000 and 8.000000
    const std::string f = "#declare F = function(a) { select(a, prod(i, 1, -a, 2), sum(i, 1, a, i)) }";
    EXPECT_DOUBLE_EQ(eval(f, "F(4)"), 10.0);
    EXPECT_DOUBLE_EQ(eval(f, "F(-3)"), 8.0);
}

TEST(SumProd, DeepNestingBeyondTheLocalStack) {
    // 40 nested sums need more slots than evaluate() keeps on its own stack: each level runs twice.
    std::string body = "1";
    for (int level = 0; level < 40; ++level)
        body = "sum(i" + std::to_string(level) + ", 1, " + (level < 10 ? "2" : "1") + ", " + body + ")";
    EXPECT_DOUBLE_EQ(eval("#declare F = function { " + body + " }", "F(0, 0, 0)"), 1024.0);
}

/// The first error of a scene that must fail to parse, as `file:line:col: error: message`.
std::string first_error(const std::string& text) {
    const ParseResult r = test::parse_fail(text);
    for (const auto& d : r.diagnostics)
        if (d.severity == Severity::Error)
            return d.loc.path + ":" + std::to_string(d.loc.line) + ":" + std::to_string(d.loc.column) +
                   ": error: " + d.message;
    return "";
}

TEST(SumProd, LocatedErrors) {
    // POV-Ray: "Invalid number of parameters: Only four parameters expected!" (and a crash for three).
    EXPECT_EQ(first_error("#declare F = function(a) { sum(i, 1, 3) }\n"),
              "test.pov:1:28: error: 'sum' takes 4 argument(s) but 3 were given");
    EXPECT_EQ(first_error("#declare F = function(a) { prod(i, 1, 3, i, 5, 6) }\n"),
              "test.pov:1:28: error: 'prod' takes 4 argument(s) but 6 were given");
    EXPECT_EQ(first_error("#declare F = function(a) { sum() }\n"),
              "test.pov:1:28: error: 'sum' takes 4 argument(s) but 0 were given");
    // POV-Ray: "Local variable name expected!"
    EXPECT_EQ(first_error("#declare F = function(a) { sum(2, 1, 3, 4) }\n"),
              "test.pov:1:32: error: the loop variable of 'sum' must be a name, but found '2'");
    EXPECT_EQ(first_error("#declare K = 1;\n#declare F = function(a) { prod(K, 1, 3, 4) }\n"),
              "test.pov:2:33: error: 'K' is already declared; the loop variable of 'prod' needs a new name");
    EXPECT_EQ(first_error("#declare F = function(a) { sum(sin, 1, 3, 4) }\n"),
              "test.pov:1:32: error: 'sin' is a reserved word; the loop variable of 'sum' needs a new name");
    // The variable is gone after the loop; POV-Ray: "Expected 'parameter identifier or floating-point constant
    // identifier'".
    EXPECT_EQ(first_error("#declare F = function(a) { sum(i, 1, 3, 4) + i }\n"),
              "test.pov:1:46: error: undeclared identifier 'i'");
    EXPECT_EQ(first_error("#declare A = sum(i, 1, 3, i);\n"),
              "test.pov:1:14: error: 'sum' can only be used inside a function body, e.g. function(n) { sum(i, 1, n, "
              "i) }");
}

TEST(UserFunctions, CompiledProgramIsThreadSafe) {
    // The program is shared by render threads: evaluate it concurrently and compare with a serial run.
    FunctionProgram p({"x", "y", "z"});
    p.emit(ins(Instruction::Op::Arg, 0));
    p.emit(ins(Instruction::Op::Arg, 1));
    p.emit(ins(Instruction::Op::Add));
    double sums[4] = {};
    std::vector<std::thread> threads;
    for (int t = 0; t < 4; ++t)
        threads.emplace_back([&, t] {
            for (int i = 0; i < 10000; ++i) {
                const double a[] = {double(i), double(t), 0.0};
                sums[t] += p.evaluate(a);
            }
        });
    for (auto& th : threads) th.join();
    for (int t = 0; t < 4; ++t) EXPECT_EQ(sums[t], 10000.0 * 9999.0 / 2.0 + 10000.0 * t);
}

}  // namespace
}  // namespace wardray::parser
