// Tests of the user-function stack machine and of `function { }` declarations and calls.
#include <cmath>
#include <thread>

#include "parser/function_vm.h"
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

TEST(UserFunctions, InternalFunctionIsAnErrorOnlyWhenCalled) {
    test::parse_ok("#include \"functions.inc\"\n#declare G = function { f_sphere(x, y, z, 1) }\nsphere { 0, 1 }\n");
    const ParseResult r = test::parse_fail("#include \"functions.inc\"\n#declare A = f_sphere(1, 2, 3, 1);\n");
    EXPECT_NE(test::all_diagnostics(r).find("test.pov:2:14: error: internal function 61 is not supported yet (called through 'f_sphere')"),
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

TEST(UserFunctions, WrongArgumentCountAndUnknownName) {
    ParseResult r = test::parse_fail("#declare F = function(a, b) { a + b }\n#declare A = F(1);\n");
    EXPECT_NE(test::all_diagnostics(r).find("'F' takes 2 argument(s) but 1 were given"), std::string::npos)
        << test::all_diagnostics(r);
    r = test::parse_fail("#declare F = function(a) { a + bogus }\n");
    EXPECT_NE(test::all_diagnostics(r).find("undeclared identifier 'bogus'"), std::string::npos);
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
