// Tests of the parametric against brute force: hits near the surface POV-Ray draws (moved by -accuracy on each
// axis), the nearest of them, normals against the analytic ones, precompute, no inside in CSG, extreme scales.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "geometry/instance.h"
#include "geometry/parametric.h"
#include "parser/parse.h"
#include "test_util.h"

namespace wardray::geometry {
namespace {

using test::Random;

// The one object of a scene made of `statement`.
scene::Object parse_object(const std::string& statement) {
    const parser::ParseResult r = parser::parse_string("global_settings { assumed_gamma 1 }\n" + statement,
                                                       "parametric.pov", parser::ParseOptions{});
    EXPECT_TRUE(r.ok());
    if (!r.ok() || !r.scene || r.scene->objects.size() != 1) return {};
    return r.scene->objects.front();
}

// A sphere of radius 0.8 by longitude u and latitude v; max_gradient 0.8 bounds every coordinate's slope.
std::string sphere_parametric(const std::string& extra) {
    return "parametric { function { 0.8*cos(u)*cos(v) } function { 0.8*sin(v) } function { 0.8*sin(u)*cos(v) } "
           "<0, -pi/2>, <2*pi, pi/2> contained_by { box { -1, 1 } } max_gradient 0.8 accuracy 0.002 " +
           extra + " }";
}

// The first crossing of the line o + t d (|d| = 1) with the sphere (c, r), or -1.
double sphere_first(const Vec3& o, const Vec3& d, const Vec3& c, double r) {
    const Vec3 w = o - c;
    const double b = dot(w, d), q = dot(w, w) - r * r, disc = b * b - q;
    if (disc < 0.0) return -1.0;
    return -b - std::sqrt(disc);
}

TEST(Parametric, SphereHitsNormalsAndNearestAgreeWithTheAnalyticSphere) {
    for (const char* extra : {"", "precompute 10, x, y, z", "precompute 6 y"}) {
        SCOPED_TRACE(extra);
        const scene::Object obj = parse_object(sphere_parametric(extra));
        const auto inst = ShapeInstance::create(obj, 0);
        ASSERT_TRUE(inst.has_value());
        // POV-Ray compat: the drawn sphere is centred at -accuracy on each axis.
        const double acc = 0.002;
        const Vec3 centre{-acc, -acc, -acc};
        Random rng(21);
        int hit = 0, near_miss = 0, early = 0;
        for (int trial = 0; trial < 400; ++trial) {
            const Vec3 origin = 4.0 * rng.direction();
            const Vec3 target = rng.vec(-0.85, 0.85);
            const Vec3 dir = normalize(target - origin);
            const SurfaceHits hits = inst->intersect_all(origin, dir, 1e-6, INFINITY);
            const double exact = sphere_first(origin, dir, centre, 0.8);
            ASSERT_LE(hits.size(), 1u);
            if (hits.empty()) {
                // A miss only where the ray grazes the sphere.
                if (exact > 0.0) {
                    const Vec3 w = origin - centre;
                    const double b = dot(w, dir);
                    EXPECT_LT(0.8 - std::sqrt(dot(w, w) - b * b), 0.01);
                    ++near_miss;
                }
                continue;
            }
            ASSERT_GT(exact, 0.0);
            ++hit;
            // The hit is never beyond the near side, and mostly within a few accuracy steps of it. POV-Ray compat:
            // it is the near side of the last axis's slab, which runs far ahead for rays nearly along its plane.
            EXPECT_LT(hits[0].t, exact + 0.02) << "trial " << trial;
            if (std::fabs(hits[0].t - exact) > 0.02) {
                ++early;
                continue;
            }
            const Vec3 p = origin + hits[0].t * dir;
            const Vec3 n_exact = normalize(p - centre);
            EXPECT_GT(std::fabs(dot(hits[0].normal, n_exact)), 0.98) << "trial " << trial;
            EXPECT_NEAR(length(hits[0].normal), 1.0, 1e-9);
        }
        EXPECT_GT(hit, 280);
        EXPECT_LT(early, hit / 10);
        EXPECT_LT(near_miss, 8);
    }
}

TEST(Parametric, PlanePatchIsHitWithinAccuracy) {
    // x = u, y = v, z = 0.3 over [-0.5, 0.5]²: POV-Ray draws z = 0.3 - accuracy, to within a slab of accuracy.
    const scene::Object obj = parse_object(
        "parametric { function { u }, function { v }, function { 0.3 } <-0.5, -0.5>, <0.5, 0.5> "
        "contained_by { box { -1, 1 } } accuracy 0.001 }");
    const auto inst = ShapeInstance::create(obj, 0);
    ASSERT_TRUE(inst.has_value());
    const ParametricShape& par = std::get<ParametricShape>(inst->shape());
    EXPECT_EQ(par.point(0.25, -0.1).x, 0.25);
    EXPECT_GT(std::fabs(normalize(par.normal_at(0.1, 0.2)).z), 0.999999);
    Random rng(5);
    int hits = 0;
    for (int trial = 0; trial < 300; ++trial) {
        const Vec3 target{rng.uniform(-0.7, 0.7), rng.uniform(-0.7, 0.7), 0.3};
        const Vec3 origin = target + Vec3{rng.uniform(-1, 1), rng.uniform(-1, 1), -3.0};
        const Vec3 dir = normalize(target - origin);
        const SurfaceHits h = inst->intersect_all(origin, dir, 1e-6, INFINITY);
        const Vec3 on_plane = origin + ((0.3 - 0.001 - origin.z) / dir.z) * dir;
        const bool over = std::fabs(on_plane.x) < 0.5 - 0.002 && std::fabs(on_plane.y) < 0.5 - 0.002;
        const bool off = std::fabs(on_plane.x) > 0.5 + 0.002 || std::fabs(on_plane.y) > 0.5 + 0.002;
        if (over) {
            EXPECT_EQ(h.size(), 1u);
        }
        if (off) {
            EXPECT_TRUE(h.empty());
        }
        if (h.empty()) continue;
        ++hits;
        const Vec3 p = origin + h[0].t * dir;
        EXPECT_NEAR(p.z, 0.3 - 0.001, 0.0011);
    }
    EXPECT_GT(hits, 100);
}

TEST(Parametric, HasNoInsideSoAnIntersectionShowsNothing) {
    const std::string par = sphere_parametric("");
    const scene::Object u = parse_object("merge { " + par + " box { <-2, -2, 0.5>, <2, 2, 2> } }");
    const scene::Object i = parse_object("intersection { " + par + " box { <-2, -2, -2>, <2, 2, 2> } }");
    const auto iu = ShapeInstance::create(u, 0);
    const auto ii = ShapeInstance::create(i, 0);
    ASSERT_TRUE(iu && ii);
    const Vec3 origin{0.1, 0.05, -5.0}, dir{0.0, 0.0, 1.0};
    EXPECT_FALSE(iu->inside(Vec3{0, 0, 0}));
    EXPECT_FALSE(ii->inside(Vec3{0, 0, 0}));
    EXPECT_FALSE(iu->intersect_all(origin, dir, 0.0, INFINITY).empty());
    // The box's crossings are never inside the parametric, the parametric's only one is inside the box.
    const SurfaceHits hi = ii->intersect_all(origin, dir, 0.0, INFINITY);
    ASSERT_EQ(hi.size(), 1u);
    EXPECT_NEAR(hi[0].t, 5.0 - 0.8, 0.02);
}

TEST(Parametric, ExtremeScalesGiveFiniteHits) {
    for (const char* scale : {"1e-4", "1e4"}) {
        SCOPED_TRACE(scale);
        const scene::Object obj = parse_object(sphere_parametric(std::string("scale ") + scale));
        const auto inst = ShapeInstance::create(obj, 0);
        ASSERT_TRUE(inst.has_value());
        const double s = std::stod(scale);
        Random rng(8);
        int found = 0;
        for (int i = 0; i < 100; ++i) {
            // POV-Ray compat: no crossing within 4 accuracy of the ray's origin, so the small one is seen from afar.
            const double far = std::fmax(s, 1.0);
            const Vec3 origin = 4.0 * far * rng.direction();
            const Vec3 dir = normalize(s * rng.vec(-0.5, 0.5) - origin);
            for (const SurfaceHit& h : inst->intersect_all(origin, dir, 0.0, INFINITY)) {
                EXPECT_TRUE(std::isfinite(h.t) && is_finite(h.normal));
                EXPECT_GT(h.t, 0.0);
                EXPECT_LT(h.t, 8.0 * far);
                ++found;
            }
        }
        // POV-Ray compat: at 1e-4 the uv rectangle's bounds dwarf the surface, the first piece below accuracy along
        // the ray lies before the container, and POV-Ray draws nothing either.
        if (s > 1.0) {
            EXPECT_GT(found, 50);
        }
    }
}

TEST(Parametric, ParserReadsPovRaysSyntax) {
    const scene::Object obj = parse_object(
        "parametric { function { cos(u) } function { sin(u) } function { v } <2*pi, 0.3>, <0, -0.3> "
        "contained_by { sphere { <0, 0, 1>, 2 } } max_gradient 2 accuracy 0.01 precompute 12 x, z }");
    const auto& p = std::get<scene::Parametric>(obj.shape);
    EXPECT_EQ(p.u_min, 0.0);
    EXPECT_NEAR(p.u_max, 2 * 3.14159265358979, 1e-12);
    EXPECT_EQ(p.v_min, -0.3);
    EXPECT_TRUE(p.sphere_container);
    EXPECT_EQ(p.radius, 2.0);
    EXPECT_EQ(p.max_gradient, 2.0);
    EXPECT_EQ(p.accuracy, 0.01);
    EXPECT_EQ(p.precompute_depth, 12);
    EXPECT_EQ(p.precompute_axes, 5);
    EXPECT_FALSE(parser::parse_string("parametric { function { u } function { v } function { 0 } <0,0>, <1,1> "
                                      "precompute 21, x }",
                                      "deep.pov", parser::ParseOptions{})
                     .ok());
}

}  // namespace
}  // namespace wardray::geometry
