// Tests of expressions: precedence, vectors, functions, constants, dot items and colour promotion.
#include <cmath>
#include <numbers>

#include "tests/parser/test_util.h"

namespace wardray::parser {
namespace {

using test::parse_ok;

// Evaluates a float expression through a sphere's radius.
double eval_float(const std::string& expr, const std::string& prelude = "") {
    const Scene s = parse_ok(prelude + "\nsphere { 0, " + expr + " }");
    if (s.objects.size() != 1) return std::nan("");
    return std::get<Sphere>(s.objects[0].shape).radius;
}

// Evaluates a vector expression through a sphere's centre.
Vec3 eval_vector(const std::string& expr, const std::string& prelude = "") {
    const Scene s = parse_ok(prelude + "\n#declare V__ = " + expr + ";\nsphere { V__, 1 }");
    if (s.objects.size() != 1) return {};
    return std::get<Sphere>(s.objects[0].shape).center;
}

// Evaluates a colour through the background statement.
Color eval_background(const std::string& color_text, const std::string& prelude = "") {
    return parse_ok(prelude + "\nbackground { " + color_text + " }").background;
}

void expect_color(const Color& c, double r, double g, double b, double f, double t) {
    EXPECT_NEAR(c.r, r, 1e-12);
    EXPECT_NEAR(c.g, g, 1e-12);
    EXPECT_NEAR(c.b, b, 1e-12);
    EXPECT_NEAR(c.filter, f, 1e-12);
    EXPECT_NEAR(c.transmit, t, 1e-12);
}

TEST(Expression, ArithmeticPrecedence) {
    EXPECT_DOUBLE_EQ(eval_float("1 + 2 * 3"), 7.0);
    EXPECT_DOUBLE_EQ(eval_float("(1 + 2) * 3"), 9.0);
    EXPECT_DOUBLE_EQ(eval_float("10 - 4 - 3"), 3.0);
    EXPECT_DOUBLE_EQ(eval_float("12 / 2 / 3"), 2.0);
    EXPECT_DOUBLE_EQ(eval_float("-2 * -3"), 6.0);
    EXPECT_DOUBLE_EQ(eval_float("+4 - -1"), 5.0);
}

TEST(Expression, RelationalLogicalConditional) {
    EXPECT_DOUBLE_EQ(eval_float("(1 < 2) + 1"), 2.0);
    EXPECT_DOUBLE_EQ(eval_float("(2 <= 2) + (3 >= 4) + (1 = 1) + (1 != 1) + (5 > 4)"), 3.0);
    // Relations bind tighter than & and |, which share one level; ?: is lowest.
    EXPECT_DOUBLE_EQ(eval_float("(1 < 2 & 3 < 4) + 1"), 2.0);
    EXPECT_DOUBLE_EQ(eval_float("(0 | 0 & 1) + 1"), 1.0);
    EXPECT_DOUBLE_EQ(eval_float("(1 + 1 = 2 ? 5 : 6)"), 5.0);
    EXPECT_DOUBLE_EQ(eval_float("(0 ? 1 : 0 ? 2 : 3)"), 3.0);
    EXPECT_DOUBLE_EQ(eval_float("(!0) + (!3) + 1"), 2.0);
    EXPECT_DOUBLE_EQ(eval_float("(1 + 2 * 3 > 6)"), 1.0);
}

TEST(Expression, TauIsTwoPiUnlessTheSceneDeclaresIt) {
    EXPECT_DOUBLE_EQ(eval_float("tau"), 2.0 * std::numbers::pi);
    // POV-Ray 3.7 does not reserve tau: a scene of its own may declare it.
    EXPECT_DOUBLE_EQ(eval_float("tau", "#declare tau = 0.25;"), 0.25);
}

TEST(Expression, AscGivesTheFirstCharacterCode) {
    EXPECT_DOUBLE_EQ(eval_float("asc(\"A\")"), 65.0);
    EXPECT_DOUBLE_EQ(eval_float("asc(strupr(\"cubic\")) - 60"), 7.0);  // meshmaker.inc's BuildSpline
    EXPECT_DOUBLE_EQ(eval_float("asc(\"\") + 1"), 1.0);
}

TEST(Expression, EqualityUsesPovRayEpsilon) {
    EXPECT_DOUBLE_EQ(eval_float("(0.1 + 0.2 = 0.3) + 1"), 2.0);
    // '<=' and '>=' also hold within the tolerance (twenty steps of 1/20 sum to 1 + 2e-16: meshmaker.inc's
    // `#while (J <= 1)` loops rely on it); '<' and '>' are exact.
    EXPECT_DOUBLE_EQ(eval_float("(0.1 + 0.2 <= 0.3) + (0.3 >= 0.1 + 0.2) + 1"), 3.0);
    EXPECT_DOUBLE_EQ(eval_float("(0.1 + 0.2 > 0.3) + (0.3 < 0.1 + 0.2) + 1"), 3.0);
}

TEST(Expression, VectorsAndPromotion) {
    const Vec3 v = eval_vector("<1, 2, 3> * 2 + 1");
    EXPECT_EQ(v, (Vec3{3, 5, 7}));
    EXPECT_EQ(eval_vector("2 * x + y * 3 - z"), (Vec3{2, 3, -1}));
    EXPECT_EQ(eval_vector("<1, 2, 3> * <2, 3, 4>"), (Vec3{2, 6, 12}));
    EXPECT_EQ(eval_vector("<1, 2, 3> / 2"), (Vec3{0.5, 1, 1.5}));
    EXPECT_EQ(eval_vector("-<1, 2, 3>"), (Vec3{-1, -2, -3}));
    EXPECT_EQ(eval_vector("5"), (Vec3{5, 5, 5}));
    // A vector component may hold any additive expression.
    EXPECT_EQ(eval_vector("<1 + 1, 2 * 3, (4 > 3)>"), (Vec3{2, 6, 1}));
}

TEST(Expression, DotItems) {
    EXPECT_DOUBLE_EQ(eval_float("<1, 2, 3>.y"), 2.0);
    EXPECT_DOUBLE_EQ(eval_float("V.z + V.x", "#declare V = <1, 2, 3>;"), 4.0);
    EXPECT_DOUBLE_EQ(eval_float("C.red + C.green * 10 + C.transmit * 100 + C.filter * 1000",
                                "#declare C = rgbft <0.5, 0.25, 0, 0.125, 0.0625>;"),
                     0.5 + 2.5 + 6.25 + 125);
    EXPECT_DOUBLE_EQ(eval_float("<1, 2, 3, 4>.t"), 4.0);
}

TEST(Expression, Functions) {
    EXPECT_DOUBLE_EQ(eval_float("abs(-2) + ceil(1.2) + floor(1.8) + int(-1.7)"), 2 + 2 + 1 - 1);
    EXPECT_DOUBLE_EQ(eval_float("mod(7, 3) + pow(2, 3) + sqrt(16)"), 1 + 8 + 4);
    EXPECT_DOUBLE_EQ(eval_float("mod(-7, 3)"), -1.0);
    EXPECT_DOUBLE_EQ(eval_float("div(7, 2) + div(-7, 2)"), 3 - 3);
    EXPECT_NEAR(eval_float("sin(pi / 2) + cos(0) + tan(0)"), 2.0, 1e-12);
    EXPECT_NEAR(eval_float("asin(1) + acos(1) + atan(1) + atan2(1, 1)"), std::numbers::pi, 1e-12);
    EXPECT_NEAR(eval_float("exp(1)"), std::exp(1.0), 1e-12);
    EXPECT_NEAR(eval_float("ln(exp(2)) + log(1000)"), 5.0, 1e-12);
    EXPECT_DOUBLE_EQ(eval_float("min(3, 1, 2) + max(3, 7)"), 8.0);
    EXPECT_NEAR(eval_float("degrees(radians(30))"), 30.0, 1e-12);
    EXPECT_DOUBLE_EQ(eval_float("vlength(<3, 4, 0>)"), 5.0);
    EXPECT_DOUBLE_EQ(eval_float("vdot(<1, 2, 3>, <4, 5, 6>)"), 32.0);
    EXPECT_EQ(eval_vector("vcross(x, y)"), (Vec3{0, 0, 1}));
    EXPECT_EQ(eval_vector("vnormalize(<0, 0, 5>)"), (Vec3{0, 0, 1}));
    EXPECT_DOUBLE_EQ(eval_float("select(-1, 2, 3) + select(1, 20, 30) + select(0, 1, 100, 1000)"), 2 + 30 + 100);
}

TEST(Expression, VectorRotationMatchesRotate) {
    const Vec3 a = eval_vector("vrotate(<0, 0, 1>, <0, 90, 0>)");
    const Vec3 b = eval_vector("vaxis_rotate(<0, 0, 1>, y, 90)");
    EXPECT_NEAR(a.x, 1.0, 1e-12);  // POV-Ray: rotate y*90 turns +z into +x
    EXPECT_NEAR(a.z, 0.0, 1e-12);
    EXPECT_NEAR(b.x, a.x, 1e-12);
    EXPECT_NEAR(b.z, a.z, 1e-12);
}

TEST(Expression, Constants) {
    EXPECT_NEAR(eval_float("pi"), std::numbers::pi, 1e-15);
    EXPECT_DOUBLE_EQ(eval_float("true + yes + on + false + no + off"), 3.0);
    ParseOptions o = test::default_options();
    o.image_width = 640;
    o.image_height = 480;
    o.animation.clock = 0.25;
    const Scene s = parse_ok("sphere { <image_width, image_height, clock>, version }", o);
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_EQ(std::get<Sphere>(s.objects[0].shape).center, (Vec3{640, 480, 0.25}));
    EXPECT_DOUBLE_EQ(std::get<Sphere>(s.objects[0].shape).radius, 3.7);
    EXPECT_DOUBLE_EQ(eval_float("clock_delta"), 0.0);
    EXPECT_DOUBLE_EQ(eval_float("initial_clock + final_clock + frame_number + clock_on"), 0.0);
}

// The animation values come from the front end, frame by frame (here frame 3 of 2..4, clock 0..1).
TEST(Expression, AnimationValues) {
    ParseOptions o = test::default_options();
    o.animation = {.clock = 0.5, .clock_delta = 0.5, .clock_on = true, .frame_number = 3, .initial_frame = 2,
                   .final_frame = 4, .initial_clock = 0, .final_clock = 1};
    const Scene s = parse_ok(
        "sphere { <clock + clock_delta, clock_on * frame_number, initial_frame * final_frame>, final_clock + 1 }", o);
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_EQ(std::get<Sphere>(s.objects[0].shape).center, (Vec3{1.0, 3.0, 8.0}));
    EXPECT_DOUBLE_EQ(std::get<Sphere>(s.objects[0].shape).radius, 2.0);
}

TEST(Expression, Strings) {
    EXPECT_DOUBLE_EQ(eval_float("strlen(concat(\"ab\", S, str(1.5, 0, 1)))", "#declare S = \"cd\";"), 7.0);
    EXPECT_DOUBLE_EQ(eval_float("val(\"2.5\") + strcmp(\"a\", \"b\")"), 1.5);
    EXPECT_DOUBLE_EQ(eval_float("strlen(substr(\"hello\", 2, 3)) + strlen(chr(65))"), 4.0);
}

TEST(Color, FloatAfterColorSetsAllFiveComponents) {
    // POV-Ray compat: `color 0.5` promotes to filter and transmit too; `rgb 0.5` only to r, g, b.
    expect_color(eval_background("color 0.5"), 0.5, 0.5, 0.5, 0.5, 0.5);
    expect_color(eval_background("color rgb 0.5"), 0.5, 0.5, 0.5, 0, 0);
    expect_color(eval_background("rgb 0.5"), 0.5, 0.5, 0.5, 0, 0);
}

TEST(Color, ColorForms) {
    expect_color(eval_background("color rgb <1, 0.5, 0.25>"), 1, 0.5, 0.25, 0, 0);
    expect_color(eval_background("rgbf <1, 0.5, 0.25, 0.1>"), 1, 0.5, 0.25, 0.1, 0);
    expect_color(eval_background("rgbt <1, 0.5, 0.25, 0.2>"), 1, 0.5, 0.25, 0, 0.2);
    expect_color(eval_background("rgbft <1, 0.5, 0.25, 0.1, 0.2>"), 1, 0.5, 0.25, 0.1, 0.2);
    expect_color(eval_background("rgbf 0.3"), 0.3, 0.3, 0.3, 0.3, 0);
    expect_color(eval_background("color red 0.2 green 0.4 blue 0.6 filter 0.1 transmit 0.3"), 0.2, 0.4, 0.6, 0.1, 0.3);
    expect_color(eval_background("color <0.1, 0.2, 0.3>"), 0.1, 0.2, 0.3, 0, 0);
    expect_color(eval_background("color rgb 1 transmit 0.5"), 1, 1, 1, 0, 0.5);
    const double half = std::pow((0.5 + 0.055) / 1.055, 2.4);
    expect_color(eval_background("srgb <0.5, 0, 1>"), half, 0, 1, 0, 0);
}

TEST(Color, ASecondRgbKeywordStartsTheNextColourOfAList) {
    // POV-Ray compat: `checker rgbt A rgbt B` (no comma) lists two colours, as with the comma.
    for (const char* list : {"rgbt <0, 1, 0, 0.5> rgb <1, 0, 0>", "rgbt <0, 1, 0, 0.5>, rgb <1, 0, 0>"}) {
        const Scene s = parse_ok(std::string("sphere { 0, 1 pigment { checker ") + list + " } }");
        ASSERT_EQ(s.objects.size(), 1u);
        const auto& map = s.objects[0].texture->pigment.color_map;
        ASSERT_EQ(map.size(), 2u) << list;
        expect_color(map[0].color, 0, 1, 0, 0, 0.5);
        expect_color(map[1].color, 1, 0, 0, 0, 0);
    }
}

TEST(Color, AMandelWithAnExponentAboveTwoTakesTheGreyRamp) {
    // POV-Ray compat: mandel's own default map (black, then cyan, yellow, magenta near 0) is for exponent 2 only;
    // with exponent 3 to 33 it is another pattern type in POV-Ray 3.7, which takes the grey ramp.
    const Scene s = parse_ok("sphere { 0, 1 pigment { mandel 20 } }\nsphere { 0, 1 pigment { mandel 20 exponent 2 } }\n"
                             "sphere { 0, 1 pigment { mandel 20 exponent 6 } }\n"
                             "sphere { 0, 1 pigment { julia <0.3, 0.5>, 20 exponent 3 } }");
    ASSERT_EQ(s.objects.size(), 4u);
    EXPECT_EQ(s.objects[0].texture->pigment.color_map.size(), 5u);
    EXPECT_EQ(s.objects[1].texture->pigment.color_map.size(), 5u);
    for (int i : {2, 3}) {
        const auto& map = s.objects[i].texture->pigment.color_map;
        ASSERT_EQ(map.size(), 2u) << i;
        expect_color(map[0].color, 0, 0, 0, 0, 0);
        expect_color(map[1].color, 1, 1, 1, 0, 0);
    }
}

TEST(Color, DeclaredColorMapsAndLayeredTexturesAreKept) {
    const Scene s = parse_ok(
        "#declare CM = color_map { [0 rgb <1, 0, 0>] [1 rgb <0, 0, 1>] }\n"
        "#declare T = texture { pigment { gradient x color_map { CM } } } texture { pigment { rgbt 1 } }\n"
        "sphere { 0, 1 texture { T } }");
    ASSERT_EQ(s.objects.size(), 1u);
    const Texture& t = s.objects[0].texture;
    ASSERT_EQ(t.pigment.color_map.size(), 2u);
    expect_color(t.pigment.color_map[1].color, 0, 0, 1, 0, 0);
    ASSERT_EQ(t.layers.size(), 1u);
    expect_color(t.layers[0].pigment.color, 1, 1, 1, 0, 1);
}

TEST(Color, IdentifiersCarryFiveComponents) {
    const std::string prelude = "#declare C = color rgbt <1, 0, 0, 0.5>;\n#declare D = C * 0.5;\n";
    expect_color(eval_background("color C", prelude), 1, 0, 0, 0, 0.5);
    expect_color(eval_background("D", prelude), 0.5, 0, 0, 0, 0.25);
    expect_color(eval_background("C filter 0.25", prelude), 1, 0, 0, 0.25, 0.5);
    // A colour plus a 3-vector: the vector is padded with zeros, not promoted.
    expect_color(eval_background("C + <0, 1, 0>", prelude), 1, 1, 0, 0, 0.5);
    // A float declared as a colour keeps all five components.
    expect_color(eval_background("G", "#declare G = color 0.25;"), 0.25, 0.25, 0.25, 0.25, 0.25);
}

TEST(Expression, VturbulenceHandsItsArgumentsToTheLightingLayer) {
    // vturbulence(Lambda, Omega, Octaves, V); POV-Ray truncates the octaves and keeps them within 1..10. (The values
    // themselves are checked against POV-Ray in tests/lighting, where the turbulence lives.)
    ParseOptions o = test::default_options();
    std::vector<std::string> calls;
    o.vector_turbulence = [&](const Vec3& p, int octaves, double omega, double lambda) {
        calls.push_back(std::to_string(octaves) + " " + std::to_string(omega) + " " + std::to_string(lambda));
        return Vec3{p.x + 1, p.y, p.z};
    };
    const Scene s = parse_ok("sphere { vturbulence(3, 0.25, 2.7, <1, 2, 3>), 1 }\n"
                             "#declare V = vturbulence(2, 0.5, 0, x) + vturbulence(2, 0.5, 20, y);\n",
                             o);
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_EQ(std::get<Sphere>(s.objects[0].shape).center.x, 2);
    ASSERT_EQ(calls.size(), 3u);
    EXPECT_EQ(calls[0], "2 0.250000 3.000000");
    EXPECT_EQ(calls[1], "1 0.500000 2.000000");
    EXPECT_EQ(calls[2], "10 0.500000 2.000000");
    const ParseResult r = test::parse_fail("#declare V = vturbulence(2, 0.5, 6, x);\n");
    EXPECT_NE(test::all_diagnostics(r).find("needs the lighting layer"), std::string::npos) << test::all_diagnostics(r);
}

TEST(Expression, ErrorsAreReportedNotThrown) {
    test::parse_fail("sphere { 0, pow(10, 400) }");
    test::parse_fail("sphere { 0, sqrt(-1) }");
    test::parse_fail("sphere { <1, 2, 3> < 2, 1 }");
    test::parse_fail("sphere { 0, <1, 2>.z }");
    test::parse_fail("sphere { 0, min() }");
    test::parse_fail("sphere { 0, (((1 }");
}

}  // namespace
}  // namespace wardray::parser
