// Tests of `spline { ... }` values and calls: each spline type, its ends, point order, copies and bad input.
//
// Expected values are worked out by hand from POV-Ray 3.7's definitions and were compared with POV-Ray 3.7.0.10:
// each spline below was declared in a scene and printed with
//   #debug concat(vstr(5, S(t), ",", 0, 6), "\n")
// run as `povray +W16 +H12 -D +Oout.png splines.pov`; values with six decimals are POV-Ray's output.
#include <array>

#include "tests/parser/test_util.h"

namespace wardray::parser {
namespace {

using test::all_diagnostics;
using test::parse_fail;
using test::parse_ok;

const char* const k_splines = R"(
#declare L = spline { linear_spline 0,<0,0,0> 1,<1,2,3> 3,<3,0,-1> }
#declare Q = spline { quadratic_spline 0,<0,0> 1,<1,1> 2,<4,0> 4,<2,8> }
#declare C = spline { cubic_spline 0,<0,0,0> 1,<1,2,0> 2,<3,3,1> 4,<4,0,2> 5,<0,0,0> }
#declare N = spline { natural_spline 0,<0,0,0> 1,<1,2,0> 2,<3,3,1> 4,<4,0,2> 5,<0,0,0> }
)";

// The five components of a spline call (padded with zeros), read back through two spheres' centres.
std::array<double, 5> eval5(const std::string& expr, const std::string& prelude = k_splines) {
    const Scene s = parse_ok(prelude + "\n#declare V__ = " + expr + " + <0,0,0,0,0>;\n" +
                             "sphere { <V__.x, V__.y, V__.z>, 1 }\nsphere { <V__.t, V__.transmit, 0>, 1 }");
    if (s.objects.size() != 2) return {};
    const Vec3 a = std::get<Sphere>(s.objects[0].shape).center;
    const Vec3 b = std::get<Sphere>(s.objects[1].shape).center;
    return {a.x, a.y, a.z, b.x, b.y};
}

void expect5(const std::array<double, 5>& got, std::array<double, 5> want, double tol = 1e-6) {
    for (int k = 0; k < 5; ++k) EXPECT_NEAR(got[k], want[k], tol) << "component " << k;
}

TEST(Spline, LinearInterpolatesAndHoldsItsEnds) {
    expect5(eval5("L(0.5)"), {0.5, 1, 1.5, 0, 0});
    expect5(eval5("L(2)"), {2, 1, 1, 0, 0});      // halfway from <1,2,3> to <3,0,-1>
    expect5(eval5("L(1)"), {1, 2, 3, 0, 0});
    expect5(eval5("L(-1)"), {0, 0, 0, 0, 0});     // before the first point: the first point
    expect5(eval5("L(4)"), {3, 0, -1, 0, 0});     // after the last: the last
}

TEST(Spline, QuadraticUsesTheParabolaThroughThreePoints) {
    // Before the second point: the parabola through points 0, 1, 2 (x = t^2, y = 2t - t^2).
    expect5(eval5("Q(0.5)"), {0.25, 0.75, 0, 0, 0});
    expect5(eval5("Q(1.5)"), {2.25, 0.75, 0, 0, 0});
    // Between T = 2 and 4: the parabola through the points at T = 1, 2, 4 (x: 1, 4, 2 -> 13/3 at T = 3).
    expect5(eval5("Q(3)"), {13.0 / 3.0, 7.0 / 3.0, 0, 0, 0});
    expect5(eval5("Q(-1)"), {0, 0, 0, 0, 0});
    expect5(eval5("Q(5)"), {2, 8, 0, 0, 0});
}

TEST(Spline, CubicIsCatmullRomWithTheEndPointsAsControlPoints) {
    // T = 1.5, segment 1..2, u = 1/2: tangents (1 + 2)/2 and (2 + 0.5)/2 in x give 2 + (1.5 - 1.25)/8.
    expect5(eval5("C(1.5)"), {2.03125, 2.71875, 0.46875, 0, 0});
    expect5(eval5("C(3)"), {4.25, 1.625, 1.875, 0, 0});
    expect5(eval5("C(1.99)"), {2.987301, 3.002301, 0.992401, 0, 0});
    // Up to the second point the value is the second point; from the next-to-last on, the next-to-last.
    expect5(eval5("C(-1)"), {1, 2, 0, 0, 0});
    expect5(eval5("C(0.5)"), {1, 2, 0, 0, 0});
    expect5(eval5("C(4.5)"), {4, 0, 2, 0, 0});
    expect5(eval5("C(6)"), {4, 0, 2, 0, 0});
}

TEST(Spline, NaturalHasZeroCurvatureAtItsEnds) {
    // Three points <0,0>, <1,2>, <0,0> at T = 0, 1, 2: the middle second derivative is 6(-1-1)/4 = -3 (x), so
    // x(0.5) = 0.5 (1 + 3/6 - 0.5 * 3/12) = 0.6875.
    const std::string h = "#declare H = spline { natural_spline 0, <0,0> 1, <1,2> 2, <0,0> }";
    expect5(eval5("H(0.5)", h), {0.6875, 1.375, 0, 0, 0});
    expect5(eval5("H(1.5)", h), {0.6875, 1.375, 0, 0, 0});
    expect5(eval5("N(0.5)"), {0.401639, 1.043033, -0.092213, 0, 0});
    expect5(eval5("N(1.5)"), {1.920082, 2.745902, 0.401639, 0, 0});
    expect5(eval5("N(3)"), {4.674180, 1.665984, 2.108607, 0, 0});
    expect5(eval5("N(4.5)"), {2.275102, -0.161373, 1.158299, 0, 0});
    expect5(eval5("N(-1)"), {0, 0, 0, 0, 0});
    expect5(eval5("N(6)"), {0, 0, 0, 0, 0});
}

TEST(Spline, PointsAreSortedByT) {
    const std::string u = "#declare U = spline { linear_spline 2,<2,0> 0,<0,0> 3,<9,1> 1,<1,5> }";
    expect5(eval5("U(0.5)", u), {0.5, 2.5, 0, 0, 0});
    expect5(eval5("U(1.5)", u), {1.5, 2.5, 0, 0, 0});
    expect5(eval5("U(2.5)", u), {5.5, 0.5, 0, 0, 0});
}

TEST(Spline, RepeatedTReplacesExceptAtTheLargestT) {
    // POV-Ray 3.7 replaces the value of a T it has, but loses a repeat of the largest T read so far.
    expect5(eval5("D(1)", "#declare D = spline { 0,<0,0> 2,<2,2> 1,<1,1> 1,<5,5> }"), {5, 5, 0, 0, 0});
    expect5(eval5("D(0)", "#declare D = spline { 0,<0,0> 0,<7,7> 2,<2,2> }"), {7, 7, 0, 0, 0});
    expect5(eval5("D(1)", "#declare D = spline { 0,<0,0> 1,<1,1> 1,<5,5> 2,<2,2> }"), {1, 1, 0, 0, 0});
}

TEST(Spline, FloatValuesGiveTwoComponentsAndMixedSizesKeepEarlierComponents) {
    const std::string f = "#declare F = spline { 0, 1 1, 3 2, 4 }";
    expect5(eval5("F(0.5)", f), {2, 2, 0, 0, 0});
    const ParseResult r = parse_fail(f + "\n#declare V = F(0.5);\nsphere { 0, V.z }");
    EXPECT_NE(all_diagnostics(r).find("test.pov:3:15: error: '.z' needs a vector with 3 components but this one has 2"),
              std::string::npos)
        << all_diagnostics(r);
    // A float fills two components; the <5,6,7> point keeps the fourth component of the point before it.
    const std::string m = "#declare M = spline { linear_spline 0, 2, 1, <1,2,3,4>, 2, <5,6,7> }";
    expect5(eval5("M(0)", m), {2, 2, 0, 0, 0});
    expect5(eval5("M(0.5)", m), {1.5, 2, 1.5, 2, 0});
    expect5(eval5("M(2)", m), {5, 6, 7, 4, 0});
}

TEST(Spline, CallCanOverrideTheType) {
    expect5(eval5("C(1.5, natural_spline)"), {1.920082, 2.745902, 0.401639, 0, 0});
    expect5(eval5("C(1.5, linear_spline)"), {2, 2.5, 0.5, 0, 0});
    expect5(eval5("C(1.5, quadratic_spline)"), {1.875, 2.625, 0.375, 0, 0});
    expect5(eval5("N(1.5, cubic_spline)"), {2.03125, 2.71875, 0.46875, 0, 0});
}

TEST(Spline, CopiesKeepOrChangeTheTypeAndTakeMorePoints) {
    expect5(eval5("C2(1.5)",
                  std::string(k_splines) + "#declare C2 = spline { C natural_spline }"),
            {1.920082, 2.745902, 0.401639, 0, 0});
    const std::string c3 = std::string(k_splines) + "#declare C3 = spline { C 3, <10,10,10> }";
    expect5(eval5("C3(2.5)", c3), {7, 7.1875, 6.0625, 0, 0});
    expect5(eval5("C3(3)", c3), {10, 10, 10, 0, 0});
    expect5(eval5("L2(2)", std::string(k_splines) + "#declare L2 = L;"), {2, 1, 1, 0, 0});
}

TEST(Spline, TooFewPointsFallBackAsPovRayDoes) {
    // Cubic: two points give their mean, three the second point; quadratic and natural with two are linear.
    expect5(eval5("K(0.3)", "#declare K = spline { cubic_spline 0, <0,0> 1, <2,4> }"), {1, 2, 0, 0, 0});
    expect5(eval5("K(2.5)", "#declare K = spline { cubic_spline 0, <0,0> 1, <2,4> 3, <5,5> }"), {2, 4, 0, 0, 0});
    expect5(eval5("K(0.5)", "#declare K = spline { natural_spline 0, <0,0> 2, <2,4> }"), {0.5, 1, 0, 0, 0});
    expect5(eval5("K(0.5)", "#declare K = spline { quadratic_spline 0, <0,0> 2, <2,4> }"), {0.5, 1, 0, 0, 0});
    expect5(eval5("K(7)", "#declare K = spline { 3, <1,2,3> }"), {1, 2, 3, 0, 0});
    // ... with a warning at the spline.
    const ParseResult r = parse_string("#declare K = spline { cubic_spline 0, <0,0> 1, <2,4> 3, <5,5> }\n",
                                       "test.pov", test::default_options());
    EXPECT_NE(all_diagnostics(r).find("test.pov:1:14: warning: a cubic_spline needs at least 4 points; with 3, it is "
                                      "the second point everywhere"),
              std::string::npos)
        << all_diagnostics(r);
}

TEST(Spline, PointsFromLoopsAndSplinesPassedToMacros) {
    const std::string w = "#declare W = spline { linear_spline\n#for (I, 0, 4) I, <I*I, 1> #end\n}\n"
                          "#macro At(Sp, T) Sp(T) #end";
    expect5(eval5("W(2.5)", w), {6.5, 1, 0, 0, 0});
    expect5(eval5("At(W, 1.5)", w), {2.5, 1, 0, 0, 0});
}

TEST(Spline, SplineFunctionsEvaluateTheirSpline) {
    // povray: F(0.5) printed 2.468750,3.562500,4.562500 and G(0.5) 2,2 with two components (G(0.5).z is an error).
    const std::string f = "#declare F = function { spline { natural_spline 0, <1,2,3> 1, <3,4,5> 2, <0,0,1> } }\n"
                          "#declare G = function { spline { 0, 1 1, 3 } }";
    expect5(eval5("F(0.5)", f), {2.46875, 3.5625, 4.5625, 0, 0});
    expect5(eval5("G(0.5)", f), {2, 2, 0, 0, 0});
    const ParseResult r = parse_fail(f + "\n#declare W = G(0.5);\nsphere { 0, W.z }");
    EXPECT_NE(all_diagnostics(r).find("'.z' needs a vector with 3 components but this one has 2"), std::string::npos)
        << all_diagnostics(r);
}

// Each bad input stops at its own token with a message that says what was expected.
void expect_error(const std::string& scene, const std::string& message) {
    const ParseResult r = parse_fail(scene);
    EXPECT_NE(all_diagnostics(r).find(message), std::string::npos) << all_diagnostics(r);
}

TEST(Spline, BadInputIsALocatedError) {
    expect_error("#declare S = spline { }", "test.pov:1:14: error: a spline needs at least one point");
    expect_error("#declare S = spline { linear_spline \"a\", <1,1> }",
                 "test.pov:1:37: error: expected a spline point (a float T, then its value) or '}' but found string");
    expect_error("#declare S = spline { <1,2>, <1,1> }",
                 "test.pov:1:23: error: a spline point's T must be a float but this is a vector");
    expect_error("#declare S = spline { 0, <1,1> 1 }", "test.pov:1:34: error: the spline point at T = 1");
    expect_error("#declare S = spline { linear_spline 0, <0,0> cubic_spline 1, <1,1> }",
                 "test.pov:1:46: error: the spline type must come before the first point");
    expect_error("#declare S = spline { 0, <0,0> 1, <1,1> }\n#declare V = S(0.5, bezier_spline);",
                 "test.pov:2:21: error: expected linear_spline, quadratic_spline, cubic_spline or natural_spline");
    expect_error("#declare S = spline { 0, <0,0> 1, <1,1> }\nsphere { S, 1 }",
                 "test.pov:2:10: error: 'S' is a spline: call it with a parameter, as S(t)");
    expect_error("#declare S = spline { 0, <0,0> 1, <1,1> }\n#declare V = S(<1,1>);",
                 "test.pov:2:16: error: the parameter of a spline call must be a float");
    expect_error("#declare P = pigment { rgb 1 }\n#declare S = spline { P 0, <0,0> }",
                 "test.pov:2:23: error: 'P' is a pigment, not a spline or a float");
    expect_error("#declare S = spline { 0, <1,1>", "test.pov:1:21: error: this '{' is never closed");
}

}  // namespace
}  // namespace wardray::parser
