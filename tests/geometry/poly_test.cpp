// Tests of PolyShape for cubic, poly and polynomial: random products of spheres and planes (whose surfaces are
// known) against their factors, finite-difference normals, the inside tolerance, scales and the three readers;
// POV-Ray's Solve_Polynomial (solve_polynomial_pov) and the closed-form quartic's stray roots.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "geometry/instance.h"
#include "geometry/polynomial.h"
#include "parser/parse.h"
#include "test_util.h"

namespace wardray::geometry {
namespace {

using test::make_object;
using test::Random;

// A dense polynomial of three variables: coefficient of x^i y^j z^k at [i][j][k].
struct Dense {
    int order = 0;
    std::vector<double> c;  // (order + 1)³
    double& at(int i, int j, int k) { return c[(i * (order + 1) + j) * (order + 1) + k]; }
    double at(int i, int j, int k) const { return c[(i * (order + 1) + j) * (order + 1) + k]; }
};

Dense times(const Dense& a, const Dense& b) {
    Dense r;
    r.order = a.order + b.order;
    r.c.assign(static_cast<std::size_t>((r.order + 1) * (r.order + 1) * (r.order + 1)), 0.0);
    for (int i = 0; i <= a.order; ++i)
        for (int j = 0; j <= a.order; ++j)
            for (int k = 0; k <= a.order; ++k)
                if (a.at(i, j, k) != 0.0)
                    for (int p = 0; p <= b.order; ++p)
                        for (int q = 0; q <= b.order; ++q)
                            for (int s = 0; s <= b.order; ++s) r.at(i + p, j + q, k + s) += a.at(i, j, k) * b.at(p, q, s);
    return r;
}

// |p - c|² - r², and the plane n·p - d.
Dense sphere(const Vec3& c, double r) {
    Dense s;
    s.order = 2;
    s.c.assign(27, 0.0);
    s.at(2, 0, 0) = s.at(0, 2, 0) = s.at(0, 0, 2) = 1.0;
    s.at(1, 0, 0) = -2 * c.x;
    s.at(0, 1, 0) = -2 * c.y;
    s.at(0, 0, 1) = -2 * c.z;
    s.at(0, 0, 0) = dot(c, c) - r * r;
    return s;
}
Dense plane(const Vec3& n, double d) {
    Dense s;
    s.order = 1;
    s.c.assign(8, 0.0);
    s.at(1, 0, 0) = n.x;
    s.at(0, 1, 0) = n.y;
    s.at(0, 0, 1) = n.z;
    s.at(0, 0, 0) = -d;
    return s;
}

// The dense polynomial as POV-Ray's coefficient list of a poly of its order.
scene::Poly as_poly(const Dense& d) {
    scene::Poly p;
    p.order = d.order;
    for (int i = d.order; i >= 0; --i)
        for (int j = d.order - i; j >= 0; --j)
            for (int k = d.order - i - j; k >= 0; --k) p.coefficients.push_back(d.at(i, j, k));
    return p;
}

// The factors of a random product: 1 to 3 spheres and up to one plane (orders 2 to 7).
struct Factors {
    std::vector<std::pair<Vec3, double>> spheres;
    std::vector<std::pair<Vec3, double>> planes;
};
Factors random_factors(Random& r) {
    Factors f;
    const int n = r.integer(1, 3);
    for (int i = 0; i < n; ++i) f.spheres.push_back({r.vec(-1.0, 1.0), r.uniform(0.3, 1.2)});
    if (r.chance(0.5)) f.planes.push_back({r.direction(), r.uniform(-0.5, 0.5)});
    return f;
}
scene::Poly product(const Factors& f) {
    Dense d;
    d.order = 0;
    d.c = {1.0};
    for (const auto& [c, r] : f.spheres) d = times(d, sphere(c, r));
    for (const auto& [n, o] : f.planes) d = times(d, plane(n, o));
    return as_poly(d);
}

// The crossings of the factors' surfaces with the ray, found analytically.
std::vector<double> factor_roots(const Factors& f, const Vec3& o, const Vec3& d) {
    std::vector<double> t;
    for (const auto& [c, r] : f.spheres) {
        const Vec3 oc = o - c;
        const double a = dot(d, d), b = dot(oc, d), q = dot(oc, oc) - r * r, disc = b * b - a * q;
        if (disc <= 0) continue;
        t.push_back((-b - std::sqrt(disc)) / a);
        t.push_back((-b + std::sqrt(disc)) / a);
    }
    for (const auto& [n, off] : f.planes)
        if (dot(n, d) != 0.0) t.push_back((off - dot(n, o)) / dot(n, d));
    std::erase_if(t, [](double v) { return !(v > 0.0); });
    std::sort(t.begin(), t.end());
    return t;
}

TEST(Poly, ProductsOfSpheresAndPlanesCrossWhereTheirFactorsDo) {
    Random rng(21);
    int checked = 0;
    for (int trial = 0; trial < 300; ++trial) {
        const Factors f = random_factors(rng);
        // Sturm sequences: POV-Ray's closed-form cubic and quartic lose digits (up to 1e-5 here).
        scene::Poly p = product(f);
        p.sturm = true;
        const auto shape = PolyShape::create(p);
        ASSERT_TRUE(shape);
        const Vec3 o = rng.direction() * rng.uniform(3.0, 10.0);
        const Vec3 d = (rng.vec(-0.8, 0.8) - o) * rng.uniform(0.2, 5.0);
        const std::vector<double> want = factor_roots(f, o, d);
        const SurfaceHits got = shape->intersect_all({o, d}, 0.0, 1e30);
        // Rays grazing a sphere or crossing where two factors meet leave a double root: skip those.
        bool close = false;
        for (std::size_t i = 1; i < want.size(); ++i) close = close || want[i] - want[i - 1] < 1e-3 * want[i];
        if (close) continue;
        ASSERT_EQ(got.size(), want.size()) << "trial " << trial;
        for (std::size_t i = 0; i < want.size(); ++i) {
            EXPECT_NEAR(got[i].t, want[i], 1e-7 * want[i]) << "trial " << trial;
            const Vec3 p = o + got[i].t * d;
            // The normal is the gradient: compare with central differences.
            const double e = 1e-6;
            Vec3 g;
            for (int k = 0; k < 3; ++k) {
                Vec3 dp;
                dp[k] = e;
                g[k] = (shape->implicit(p + dp) - shape->implicit(p - dp)) / (2 * e);
            }
            EXPECT_GT(dot(normalize(g), normalize(got[i].normal)), 1.0 - 1e-6) << "trial " << trial;
            EXPECT_EQ(got[i].entering, dot(got[i].normal, d) < 0.0);
            ++checked;
        }
    }
    EXPECT_GT(checked, 500);
}

TEST(Poly, InsideIsBelowPovRaysTolerance) {
    // One sphere of radius 1: inside where |p|² - 1 < 1e-4, so just beyond the surface still counts.
    const auto shape = PolyShape::create(as_poly(sphere({0, 0, 0}, 1.0)));
    ASSERT_TRUE(shape);
    EXPECT_TRUE(shape->inside({0.5, 0.0, 0.0}));
    EXPECT_TRUE(shape->inside({1.00004, 0.0, 0.0}));
    EXPECT_FALSE(shape->inside({1.0001, 0.0, 0.0}));
    Random rng(2);
    for (int k = 0; k < 1000; ++k) {
        const Vec3 p = rng.vec(-2.0, 2.0);
        EXPECT_EQ(shape->inside(p), dot(p, p) - 1.0 < 1e-4);
    }
}

TEST(Poly, HighOrdersAndExtremeScalesStayFinite) {
    // Order 7 (three spheres and a plane) scaled by 1e-4 and 1e4 finds the same crossings.
    Factors f;
    f.spheres = {{{0, 0, 0}, 1.0}, {{0.5, 0, 0}, 0.7}, {{-0.3, 0.2, 0}, 0.4}};
    f.planes = {{{0, 1, 0}, 0.1}};
    const scene::Poly p = product(f);
    ASSERT_EQ(p.order, 7);
    EXPECT_GT(test::check_scale_invariance(p, 8, 100, 5.0, 1e-7, 1e-7), 100);
}

TEST(Poly, CubicPolyAndPolynomialReadTheSameSurface) {
    // x³ + y² z - 1 three ways: cubic's 20 coefficients, poly 3 and polynomial's xyz terms.
    parser::ParseOptions options;
    const parser::ParseResult r = parser::parse_string(
        "cubic { <1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, -1> sturm }\n"
        "poly { 3, <1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, -1> }\n"
        "polynomial { 3, xyz(3, 0, 0): 1, xyz(0, 2, 1): 1, xyz(0, 0, 0): -1 }\n",
        "poly.pov", options);
    ASSERT_TRUE(r.ok());
    ASSERT_EQ(r.scene->objects.size(), 3u);
    const auto& a = std::get<scene::Poly>(r.scene->objects[0].shape);
    const auto& b = std::get<scene::Poly>(r.scene->objects[1].shape);
    const auto& c = std::get<scene::Poly>(r.scene->objects[2].shape);
    EXPECT_EQ(a.coefficients, b.coefficients);
    EXPECT_EQ(a.coefficients, c.coefficients);
    EXPECT_STREQ(a.keyword(), "cubic");
    EXPECT_STREQ(c.keyword(), "polynomial");
    // Only the cubic says sturm.
    EXPECT_TRUE(a.sturm);
    EXPECT_FALSE(b.sturm);
    const auto shape = PolyShape::create(a);
    ASSERT_TRUE(shape);
    EXPECT_NEAR(shape->implicit({2, 3, 0.5}), 8 + 4.5 - 1, 1e-12);
    EXPECT_FALSE(parser::parse_string("poly { 36, <1> }", "bad.pov", options).ok());
    EXPECT_FALSE(parser::parse_string("polynomial { 2, xyz(2, 1, 0): 1 }", "bad.pov", options).ok());
}

// The roots solve_polynomial_pov finds, sorted.
std::vector<double> pov_roots(std::vector<double> c, bool sturm, double epsilon) {
    std::vector<double> r(c.size());
    r.resize(static_cast<std::size_t>(solve_polynomial_pov(c.data(), static_cast<int>(c.size()) - 1, r.data(),
                                                           sturm, epsilon)));
    std::sort(r.begin(), r.end());
    return r;
}

TEST(PovSolver, ClosedFormAndSturmFindWellSeparatedRoots) {
    // (x - 1)(x - 2)(x - 3)(x - 4) and (x² - 1)(x² - 4), highest power first.
    for (const bool sturm : {false, true}) {
        const std::vector<double> r = pov_roots({1, -10, 35, -50, 24}, sturm, 0.0);
        ASSERT_EQ(r.size(), 4u) << sturm;
        for (int i = 0; i < 4; ++i) EXPECT_NEAR(r[i], i + 1.0, 1e-9) << sturm;
    }
    // The closed form returns every real root; Sturm sequences only those in [0, 1e7], as POV-Ray's do.
    EXPECT_EQ(pov_roots({1, 0, -5, 0, 4}, false, 0.0).size(), 4u);
    const std::vector<double> positive = pov_roots({1, 0, -5, 0, 4}, true, 0.0);
    ASSERT_EQ(positive.size(), 2u);
    EXPECT_NEAR(positive[0], 1.0, 1e-9);
    EXPECT_NEAR(positive[1], 2.0, 1e-9);
}

TEST(PovSolver, PovRaysShortcutsChangeTheRootsFound) {
    // 1e-6 x⁴ = 1e7: coefficients 13 orders of magnitude apart send the quartic to Sturm sequences, which see
    // only the positive root.
    const std::vector<double> difficult = pov_roots({1e-6, 0, 0, 0, -1e7}, false, 0.0);
    ASSERT_EQ(difficult.size(), 1u);
    EXPECT_NEAR(difficult[0], std::pow(1e13, 0.25), 1e-9 * std::pow(1e13, 0.25));
    // x (x - 1)(x - 2)(x - 3) + 1e-9: a constant below epsilon times the linear term drops the root near 0.
    EXPECT_EQ(pov_roots({1, -6, 11, -6, 1e-9}, false, 1e-4).size(), 3u);
    EXPECT_EQ(pov_roots({1, -6, 11, -6, 1e-9}, false, 0.0).size(), 4u);
    // A leading coefficient below 1e-10 lowers the order: (x - 1)(x - 2).
    const std::vector<double> quadratic = pov_roots({1e-11, 1, -3, 2}, false, 0.0);
    ASSERT_EQ(quadratic.size(), 2u);
    EXPECT_NEAR(quadratic[0], 1.0, 1e-12);
    EXPECT_NEAR(quadratic[1], 2.0, 1e-12);
}

TEST(Poly, ClosedFormQuarticFindsStrayRoots) {
    // lemnisc2.pov's lemniscate of Gerono x⁴ - x² + y² + z² = 0 (POV-Ray's 35 quartic coefficients). Rays aimed
    // at its x axis beyond the surface (|x| > 1) meet nothing, but where the direction is nearly perpendicular to
    // the axis the quartic's leading coefficient nearly vanishes and POV-Ray's closed form returns roots anyway:
    // the thin stray lines of its picture. Sturm sequences (POV-Ray's, as ill-conditioned there) find far fewer.
    scene::Quartic q;
    q.coefficients[0] = 1.0;    // x⁴
    q.coefficients[9] = -1.0;   // x²
    q.coefficients[25] = 1.0;   // y²
    q.coefficients[32] = 1.0;   // z²
    const auto closed = PolyShape::create(q);
    q.sturm = true;
    const auto sturm = PolyShape::create(q);
    ASSERT_TRUE(closed && sturm);
    Random rng(5);
    int stray_closed = 0, stray_sturm = 0;
    const auto stray = [](const PolyShape& shape, const LocalRay& ray) {
        const SurfaceHits h = shape.intersect_all(ray, 0.0, 1e30);
        for (std::size_t k = 0; k < h.size(); ++k)
            if (std::fabs(shape.implicit(ray.origin + h[k].t * ray.direction)) > 1e-3) return 1;
        return 0;
    };
    for (int n = 0; n < 8000; ++n) {
        const Vec3 o = rng.direction() * rng.uniform(2.5, 5.0);
        const double x = rng.uniform(1.05, 3.0) * (rng.uniform(0, 1) < 0.5 ? -1 : 1);
        const Vec3 target{x, 1e-4 * rng.uniform(-1, 1), 1e-4 * rng.uniform(-1, 1)};
        const LocalRay ray{o, target - o};
        stray_closed += stray(*closed, ray);
        stray_sturm += stray(*sturm, ray);
    }
    EXPECT_GT(stray_closed, 3 * stray_sturm) << stray_closed << " against " << stray_sturm;
}

}  // namespace
}  // namespace wardray::geometry
