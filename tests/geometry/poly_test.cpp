// Tests of PolyShape for cubic, poly and polynomial: random products of spheres and planes (whose surfaces are
// known) against their factors, finite-difference normals, the inside tolerance, scales and the three readers.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "geometry/instance.h"
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
        const auto shape = PolyShape::create(product(f));
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
    const auto shape = PolyShape::create(a);
    ASSERT_TRUE(shape);
    EXPECT_NEAR(shape->implicit({2, 3, 0.5}), 8 + 4.5 - 1, 1e-12);
    EXPECT_FALSE(parser::parse_string("poly { 36, <1> }", "bad.pov", options).ok());
    EXPECT_FALSE(parser::parse_string("polynomial { 2, xyz(2, 1, 0): 1 }", "bad.pov", options).ok());
}

}  // namespace
}  // namespace wardray::geometry
