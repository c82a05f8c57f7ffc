// Tests of JuliaFractalShape: crossings against an independent orbit iteration, normals against finite differences
// of the orbit's escape value, first-crossing semantics, scale invariance, the complex functions and the reader.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "geometry/instance.h"
#include "geometry/julia_complex.h"
#include "parser/parse.h"
#include "test_util.h"

namespace wardray::geometry {
namespace {

using test::make_object;
using test::Random;
using Function = scene::JuliaFractal::Function;
using Algebra = scene::JuliaFractal::Algebra;

struct Q {
    double x, y, z, w;
};

// |z_n|² after n steps of z -> z² + c or z³ + c in the quaternions from (x, y, z, 0); the escape step in `escaped`
// (-1 when the orbit stays within exit² for the n tests POV-Ray makes, before each step).
double quaternion_orbit(const scene::JuliaFractal& f, const Vec3& p, double exit2, int& escaped) {
    Q q{p.x, p.y, p.z, 0.0};
    escaped = -1;
    for (int i = 0; i < f.max_iteration; ++i) {
        const double n2 = q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w;
        if (n2 > exit2 && escaped < 0) escaped = i;
        const double v = q.y * q.y + q.z * q.z + q.w * q.w;
        if (f.function == Function::Cube) {
            // (x + v)³ = x³ - 3 x |v|² + (3 x² - |v|²) v for the vector part v.
            const double k = 3 * q.x * q.x - v;
            q = {q.x * q.x * q.x - 3 * q.x * v + f.c[0], k * q.y + f.c[1], k * q.z + f.c[2], k * q.w + f.c[3]};
        } else {
            q = {q.x * q.x - v + f.c[0], 2 * q.x * q.y + f.c[1], 2 * q.x * q.z + f.c[2], 2 * q.x * q.w + f.c[3]};
        }
    }
    return q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w;
}

scene::JuliaFractal random_quaternion(Random& r) {
    scene::JuliaFractal f;
    f.c = {r.uniform(-0.6, 0.3), r.uniform(-0.5, 0.5), r.uniform(-0.8, 0.8), r.uniform(-0.3, 0.3)};
    f.function = r.chance(0.5) ? Function::Cube : Function::Sqr;
    f.max_iteration = r.integer(5, 9);
    f.step = 1.0 / r.uniform(20.0, 200.0);
    return f;
}

double exit2_of(const scene::JuliaFractal& f) {
    const double c = std::sqrt(f.c[0] * f.c[0] + f.c[1] * f.c[1] + f.c[2] * f.c[2] + f.c[3] * f.c[3]);
    const double r = std::fmin(2.0, 1.0 + c + 1e-7);
    return r * r + 1e-7;
}

// A shape reporting all crossings, as a CSG child does.
JuliaFractalShape all_crossings(const scene::JuliaFractal& f) {
    auto shape = JuliaFractalShape::create(f);
    EXPECT_TRUE(shape);
    shape->keep_all_crossings();
    return *shape;
}

TEST(JuliaFractal, InsideAgreesWithAnIndependentOrbit) {
    Random rng(3);
    int inside = 0, total = 0;
    for (int trial = 0; trial < 40; ++trial) {
        const scene::JuliaFractal f = random_quaternion(rng);
        const auto shape = JuliaFractalShape::create(f);
        ASSERT_TRUE(shape);
        for (int k = 0; k < 500; ++k) {
            const Vec3 p = rng.vec(-1.5, 1.5);
            int escaped = 0;
            quaternion_orbit(f, p, exit2_of(f), escaped);
            EXPECT_EQ(shape->inside(p), escaped < 0) << "trial " << trial;
            inside += escaped < 0;
            ++total;
        }
    }
    // Both outcomes occur, so the test says something.
    EXPECT_GT(inside, total / 50);
    EXPECT_LT(inside, total - total / 50);
}

TEST(JuliaFractal, CrossingsChangeTheInsideStateWithOutwardNormals) {
    Random rng(7);
    int checked = 0;
    for (int trial = 0; trial < 200; ++trial) {
        const scene::JuliaFractal f = random_quaternion(rng);
        const JuliaFractalShape shape = all_crossings(f);
        const LocalRay ray{rng.direction() * 3.0, (rng.vec(-0.5, 0.5) - rng.direction() * 3.0) * rng.uniform(0.2, 5)};
        const LocalRay aimed{ray.origin, rng.vec(-0.6, 0.6) - ray.origin};
        const SurfaceHits hits = shape.intersect_all(aimed, 0.0, 1e30);
        for (std::size_t i = 0; i < hits.size(); ++i) {
            const SurfaceHit& h = hits[i];
            ASSERT_TRUE(std::isfinite(h.t));
            if (i > 0) {
                EXPECT_GE(h.t, hits[i - 1].t);
            }
            // The bisection ends within 1e-7 of the change along the unit direction (the reported depth lags by up
            // to one step after the first crossing, as POV-Ray's does, so only the first is placed exactly).
            if (i > 0) continue;
            const double unit = 1.0 / length(aimed.direction);
            const Vec3 p = aimed.origin + h.t * aimed.direction;
            const Vec3 d = aimed.direction * unit;
            EXPECT_EQ(shape.inside(p - 1e-6 * d), !h.entering) << "trial " << trial;
            EXPECT_EQ(shape.inside(p + 1e-6 * d), h.entering) << "trial " << trial;
            EXPECT_EQ(h.entering, dot(h.normal, aimed.direction) < 0.0) << "trial " << trial;
            ++checked;
        }
    }
    EXPECT_GT(checked, 60);
}

TEST(JuliaFractal, NormalsAreTheGradientOfTheOrbitsEscapeValue) {
    Random rng(11);
    int checked = 0;
    for (int trial = 0; trial < 200 && checked < 100; ++trial) {
        const scene::JuliaFractal f = random_quaternion(rng);
        const auto shape = JuliaFractalShape::create(f);
        ASSERT_TRUE(shape);
        const LocalRay ray{rng.direction() * 3.0, rng.vec(-0.5, 0.5)};
        const LocalRay aimed{ray.origin, ray.direction - ray.origin};
        const SurfaceHits hits = shape->intersect_all(aimed, 0.0, 1e30);
        if (hits.empty()) continue;
        Vec3 p = aimed.origin + hits[0].t * aimed.direction;
        // The point just inside, where POV-Ray takes the normal.
        if (!shape->inside(p)) p = p + 2e-7 * normalize(aimed.direction);
        if (!shape->inside(p)) continue;
        const double e = 1e-7;
        Vec3 g;
        int escaped = 0;
        for (int k = 0; k < 3; ++k) {
            Vec3 dp;
            dp[k] = e;
            g[k] = (quaternion_orbit(f, p + dp, 1e300, escaped) - quaternion_orbit(f, p - dp, 1e300, escaped)) / (2 * e);
        }
        const Vec3 n = shape->normal_at(p);
        if (!(length(g) > 0.0)) continue;
        EXPECT_GT(dot(normalize(g), normalize(n)), 1.0 - 1e-5) << "trial " << trial;
        EXPECT_NEAR(dot(normalize(hits[0].normal), normalize(n)), 1.0, 1e-12);
        ++checked;
    }
    EXPECT_GE(checked, 50);
}

TEST(JuliaFractal, AloneItStopsAtTheFirstCrossingLosesItBeforeMinIsectDepthAndRestartsBeyond) {
    scene::JuliaFractal f;
    f.c = {-0.083, 0.0, -0.83, -0.025};
    f.max_iteration = 8;
    f.step = 1.0 / 15.0;
    const scene::Object obj = make_object(f);
    const auto inst = ShapeInstance::create(obj, 0);
    ASSERT_TRUE(inst);
    const JuliaFractalShape all = all_crossings(f);
    const Vec3 o{0.1, 0.2, -5.0}, d{0.0, 0.0, 1.0};
    const SurfaceHits every = all.intersect_all({o, d}, 0.0, 1e30);
    ASSERT_GE(every.size(), 2u);
    const SurfaceHits first = inst->intersect_all(o, d, 0.0, 1e30);
    ASSERT_EQ(first.size(), 1u);
    EXPECT_EQ(first[0].t, every[0].t);
    // From just before the surface the first crossing lies within 1e-4: POV-Ray discards it and sees nothing more.
    const Vec3 p = o + (every[0].t - 1e-6) * d;
    EXPECT_TRUE(inst->intersect_all(p, d, 1e-9, 1e30).empty());
    EXPECT_GE(all.intersect_all({p, d}, 1e-9, 1e30).size(), 1u);
    // Asked about from beyond the first crossing, the ray starts again there (as POV-Ray's shadow rays do at each
    // transparent surface) and finds the next crossing, as a ray from that point would.
    const double t_past = every[0].t + 1e-3;
    const SurfaceHits next = inst->intersect_all(o, d, t_past, 1e30);
    const SurfaceHits from_there = inst->intersect_all(o + t_past * d, d, 0.0, 1e30);
    ASSERT_EQ(next.size(), 1u);
    ASSERT_EQ(from_there.size(), 1u);
    EXPECT_NEAR(next[0].t, t_past + from_there[0].t, 1e-12);
    EXPECT_GT(next[0].t, every[0].t);
}

TEST(JuliaFractal, TinyAndHugeScalesGiveTheSameCrossings) {
    scene::JuliaFractal f;
    f.c = {-0.03, 0.5, -0.2, -0.5};
    f.function = Function::Cube;
    f.max_iteration = 8;
    f.step = 1.0 / 30.0;
    EXPECT_GT(test::check_scale_invariance(f, 5, 200, 3.0, 1e-9, 1e-9), 50);
}

TEST(JuliaFractal, HypercomplexFunctionsGiveFiniteCrossings) {
    // Every function of the hypercomplex algebra draws something with finite unit normals.
    const Function functions[] = {Function::Sqr,   Function::Cube,  Function::Reciprocal, Function::Exp,
                                  Function::Ln,    Function::Sin,   Function::Asin,       Function::Cos,
                                  Function::Acos,  Function::Tan,   Function::Atan,       Function::Sinh,
                                  Function::Asinh, Function::Cosh,  Function::Acosh,      Function::Tanh,
                                  Function::Atanh, Function::Pwr};
    Random rng(9);
    for (Function fn : functions) {
        scene::JuliaFractal f;
        f.algebra = Algebra::Hypercomplex;
        f.function = fn;
        f.c = {0.2, 0.1, 0.59, -0.2};
        f.max_iteration = 6;
        f.exponent_re = 2.5;
        f.exponent_im = 0.3;
        const auto inst = ShapeInstance::create(make_object(f), 0);
        ASSERT_TRUE(inst);
        int hits = 0;
        for (int k = 0; k < 300; ++k) {
            const Vec3 o = rng.direction() * 5.0;
            for (const SurfaceHit& h : inst->intersect_all(o, rng.vec(-1.5, 1.5) - o, 0.0, 1e30)) {
                ASSERT_TRUE(std::isfinite(h.t));
                ASSERT_NEAR(length(h.normal), 1.0, 1e-12);
                ++hits;
            }
        }
        EXPECT_GT(hits, 3) << "function " << static_cast<int>(fn);
    }
}

TEST(JuliaFractal, ComplexFunctionsAreThePrincipalBranches) {
    Random rng(13);
    using C = std::complex<double>;
    const std::pair<Function, C (*)(const C&)> cases[] = {
        {Function::Exp, [](const C& z) { return std::exp(z); }},    {Function::Ln, [](const C& z) { return std::log(z); }},
        {Function::Sin, [](const C& z) { return std::sin(z); }},    {Function::Cos, [](const C& z) { return std::cos(z); }},
        {Function::Tan, [](const C& z) { return std::tan(z); }},    {Function::Sinh, [](const C& z) { return std::sinh(z); }},
        {Function::Cosh, [](const C& z) { return std::cosh(z); }},  {Function::Tanh, [](const C& z) { return std::tanh(z); }},
        {Function::Asin, [](const C& z) { return std::asin(z); }},
        {Function::Atan, [](const C& z) { return std::atan(z); }},  {Function::Asinh, [](const C& z) { return std::asinh(z); }},
        {Function::Atanh, [](const C& z) { return std::atanh(z); }}};
    for (const auto& [fn, reference] : cases)
        for (int k = 0; k < 200; ++k) {
            // Off the branch cuts on the axes.
            const C z(rng.uniform(0.1, 2.0) * (rng.chance(0.5) ? 1 : -1), rng.uniform(0.1, 2.0) * (rng.chance(0.5) ? 1 : -1));
            const Complex got = julia_complex_function(fn, {z.real(), z.imag()}, {});
            const C want = reference(z);
            EXPECT_NEAR(got.re, want.real(), 1e-9 * (1 + std::abs(want))) << "function " << static_cast<int>(fn);
            EXPECT_NEAR(got.im, want.imag(), 1e-9 * (1 + std::abs(want))) << "function " << static_cast<int>(fn);
        }
    // POV-Ray's acos and acosh take sqrt(z² - 1), another branch than the principal one in half the plane: they
    // are still inverses of cos and cosh.
    for (int k = 0; k < 200; ++k) {
        const C z(rng.uniform(-2.0, 2.0), rng.uniform(-2.0, 2.0));
        const Complex a = julia_complex_function(Function::Acos, {z.real(), z.imag()}, {});
        const Complex h = julia_complex_function(Function::Acosh, {z.real(), z.imag()}, {});
        EXPECT_NEAR(std::abs(std::cos(C(a.re, a.im)) - z), 0.0, 1e-9);
        EXPECT_NEAR(std::abs(std::cosh(C(h.re, h.im)) - z), 0.0, 1e-9);
    }
    const Complex p = julia_complex_function(Function::Pwr, {1.2, 0.7}, {2.0, 0.5});
    const C want = std::pow(C(1.2, 0.7), C(2.0, 0.5));
    EXPECT_NEAR(p.re, want.real(), 1e-12);
    EXPECT_NEAR(p.im, want.imag(), 1e-12);
}

TEST(JuliaFractal, ReadsEveryKeywordAndRejectsQuaternionFunctions) {
    parser::ParseOptions options;
    const parser::ParseResult r = parser::parse_string(
        "#version 3.7; global_settings { assumed_gamma 1 }\n"
        "julia_fractal { <0.1, 0.2, 0.3, 0.4> hypercomplex pwr(2, 0.5) max_iteration 6.7 precision 0.5\n"
        "  slice <0, 0, 1, 1>, 0.25 pigment { rgb 1 } }",
        "julia.pov", options);
    ASSERT_TRUE(r.ok());
    ASSERT_EQ(r.scene->objects.size(), 1u);
    const auto& f = std::get<scene::JuliaFractal>(r.scene->objects[0].shape);
    EXPECT_EQ(f.c[3], 0.4);
    EXPECT_EQ(f.algebra, Algebra::Hypercomplex);
    EXPECT_EQ(f.function, Function::Pwr);
    EXPECT_EQ(f.exponent_re, 2.0);
    EXPECT_EQ(f.exponent_im, 0.5);
    EXPECT_EQ(f.max_iteration, 6);
    EXPECT_EQ(f.step, 1.0);  // precisions below 1 count as 1
    EXPECT_NEAR(f.slice[2], std::sqrt(0.5), 1e-15);
    EXPECT_NEAR(f.slice[3], std::sqrt(0.5), 1e-15);
    EXPECT_EQ(f.slice_distance, 0.25);
    for (const Diagnostic& d : r.diagnostics) EXPECT_NE(d.severity, Severity::Warning) << d.message;
    EXPECT_FALSE(parser::parse_string("julia_fractal { <0, 0, 0, 0> quaternion exp }", "bad.pov", options).ok());
    EXPECT_FALSE(parser::parse_string("julia_fractal { <0, 0, 0, 0> slice <1, 0, 0, 0>, 0 }", "bad.pov", options).ok());
}

}  // namespace
}  // namespace wardray::geometry
