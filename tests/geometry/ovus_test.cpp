// Tests of the ovus against brute force: hits on the egg's surface, normals by finite differences, the inside test
// against sampling along rays, POV-Ray's geometry (tangent joins, box, sphere substitute), extreme scales.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "geometry/instance.h"
#include "geometry/ovus.h"
#include "parser/parse.h"
#include "test_util.h"

namespace wardray::geometry {
namespace {

using test::Random;

// The one object of a scene made of `statement`.
scene::Object parse_object(const std::string& statement) {
    const parser::ParseResult r =
        parser::parse_string("global_settings { assumed_gamma 1 }\n" + statement, "ovus.pov", parser::ParseOptions{});
    EXPECT_TRUE(r.ok());
    if (!r.ok() || !r.scene || r.scene->objects.size() != 1) return {};
    return r.scene->objects.front();
}

// A bigger bottom, equal radii, a bigger top, a small top, the top sphere alone, transformed.
const char* const k_eggs[] = {
    "ovus { 1, 0.5 }",
    "ovus { 0.8, 0.8 }",
    "ovus { 0.7, 1.2 }",
    "ovus { 1, 0.15 }",
    "ovus { 0.5, 1.2 }",
    "ovus { 1, 0.6 scale <1, 2, 0.5> rotate <30, 40, 50> translate <0.5, -1, 2> }",
};

// The egg's object-space gradient by central differences of its distance function.
Vec3 gradient(const OvusShape& s, const Vec3& p) {
    const double h = 1e-6;
    return {s.implicit(p + Vec3{h, 0, 0}) - s.implicit(p - Vec3{h, 0, 0}),
            s.implicit(p + Vec3{0, h, 0}) - s.implicit(p - Vec3{0, h, 0}),
            s.implicit(p + Vec3{0, 0, h}) - s.implicit(p - Vec3{0, 0, h})};
}

TEST(Ovus, HitsNormalsAndInsideAgreeWithBruteForce) {
    Random rng(16);
    int crossings = 0;
    for (const char* text : k_eggs) {
        SCOPED_TRACE(text);
        const scene::Object obj = parse_object(text);
        const auto inst = ShapeInstance::create(obj, 0);
        ASSERT_TRUE(inst.has_value());
        const OvusShape& egg = std::get<OvusShape>(inst->shape());
        for (int trial = 0; trial < 300; ++trial) {
            const Vec3 target = obj.transform.point(rng.vec(-1.0, 1.8));
            const Vec3 origin = target - 8.0 * rng.direction();
            const Vec3 dir = normalize(target - origin);
            const SurfaceHits hits = inst->intersect_all(origin, dir, 1e-9, INFINITY);
            // A convex solid: a ray from outside crosses it twice or not at all, entering first.
            ASSERT_TRUE(hits.size() == 0 || hits.size() == 2) << hits.size();
            if (hits.size() == 2) {
                EXPECT_TRUE(hits[0].entering);
                EXPECT_FALSE(hits[1].entering);
            }
            for (const SurfaceHit& h : hits) {
                const Vec3 p = obj.transform.inverse_point(origin + h.t * dir);
                EXPECT_NEAR(egg.implicit(p), 0.0, 1e-9) << "t " << h.t;
                EXPECT_NEAR(length(h.normal), 1.0, 1e-9);
                const Vec3 n_world = normalize(obj.transform.normal(gradient(egg, p)));
                EXPECT_GT(dot(n_world, h.normal), 0.9999) << "normal at t " << h.t;
                ++crossings;
            }
            // Sampled along the ray, inside() holds exactly between the two crossings.
            for (int k = 0; k < 64; ++k) {
                const double t = 16.0 * (k + 0.5) / 64.0;
                bool between = hits.size() == 2 && t > hits[0].t && t < hits[1].t;
                const double margin = 1e-7;
                bool near = false;
                for (const SurfaceHit& h : hits) near = near || std::fabs(t - h.t) < margin;
                if (!near) {
                    EXPECT_EQ(inst->inside(origin + t * dir), between) << "t " << t;
                }
            }
            // Brute force: a march of inside() finds no crossing the solver missed.
            if (hits.empty()) {
                bool any = false;
                for (int k = 0; k < 4000 && !any; ++k) any = inst->inside(origin + (16.0 * k / 4000.0) * dir);
                EXPECT_FALSE(any) << "a missed crossing";
            }
        }
    }
    EXPECT_GT(crossings, 1000);
}

TEST(Ovus, JoinsAreTangentAndTheBoxIsPovRays) {
    const std::vector<std::pair<double, double>> radii = {{1.0, 0.5}, {0.8, 0.8}, {0.7, 1.2}, {1.0, 0.15}};
    for (const auto& [b, t] : radii) {
        SCOPED_TRACE(std::to_string(b) + " " + std::to_string(t));
        const auto egg = OvusShape::create(scene::Ovus{b, t});
        ASSERT_TRUE(egg.has_value());
        // Poles: the bottom sphere's at -b, the top sphere's at b + t.
        const LocalRay down{{0.0, 10.0, 0.0}, {0.0, -1.0, 0.0}};
        const SurfaceHits hits = egg->intersect_all(down, 0.0, INFINITY);
        ASSERT_EQ(hits.size(), 2u);
        EXPECT_NEAR(10.0 - hits[0].t, b + t, 1e-12);
        EXPECT_NEAR(10.0 - hits[1].t, -b, 1e-12);
        EXPECT_EQ(egg->bounds()->lower.y, -b);
        EXPECT_EQ(egg->bounds()->upper.y, b + t);
        // Horizontal rays at every height meet the surface with normals that turn smoothly (C1 joins).
        Vec3 last{};
        for (int k = 1; k < 400; ++k) {
            const double y = -b + (b + b + t) * (k + 0.37) / 400.0;  // off the joins, where POV-Ray has a gap
            const SurfaceHits h = egg->intersect_all(LocalRay{{-10.0, y, 0.0}, {1.0, 0.0, 0.0}}, 0.0, INFINITY);
            ASSERT_EQ(h.size(), 2u) << "y " << y;
            const Vec3 n = normalize(h[0].normal);
            if (k > 1) {
                EXPECT_GT(dot(n, last), 0.99) << "y " << y;
            }
            last = n;
        }
    }
}

TEST(Ovus, TopRadiusOfTwiceTheBottomOrMoreIsTheTopSphere) {
    const auto egg = OvusShape::create(scene::Ovus{0.5, 1.2});
    ASSERT_TRUE(egg.has_value());
    Random rng(3);
    for (int i = 0; i < 200; ++i) {
        const Vec3 p = rng.vec(-2.0, 2.0);
        EXPECT_EQ(egg->inside(p), length(p - Vec3{0, 0.5, 0}) < 1.2);
    }
    EXPECT_FALSE(OvusShape::create(scene::Ovus{0.0, 0.0}).has_value());
    EXPECT_FALSE(OvusShape::create(scene::Ovus{-1.0, 0.5}).has_value());
}

TEST(Ovus, ExtremeScalesGiveFiniteHits) {
    for (const char* scale : {"1e-4", "1e4"}) {
        SCOPED_TRACE(scale);
        const scene::Object obj = parse_object(std::string("ovus { 1, 0.6 scale ") + scale + " }");
        const auto inst = ShapeInstance::create(obj, 0);
        ASSERT_TRUE(inst.has_value());
        const double s = std::stod(scale);
        Random rng(9);
        int found = 0;
        for (int i = 0; i < 200; ++i) {
            const Vec3 target = s * rng.vec(-0.9, 1.3);
            const Vec3 origin = target - 5.0 * s * rng.direction();
            const Vec3 dir = normalize(target - origin);
            for (const SurfaceHit& h : inst->intersect_all(origin, dir, 0.0, INFINITY)) {
                EXPECT_TRUE(std::isfinite(h.t) && is_finite(h.normal));
                const Vec3 p = obj.transform.inverse_point(origin + h.t * dir);
                EXPECT_NEAR(std::get<OvusShape>(inst->shape()).implicit(p), 0.0, 1e-8);
                ++found;
            }
        }
        EXPECT_GT(found, 100);
    }
}

TEST(Ovus, ParserChecksRadiiAsPovRay) {
    const parser::ParseResult neg = parser::parse_string("ovus { -1, 0.5 }", "neg.pov", parser::ParseOptions{});
    EXPECT_FALSE(neg.ok());
    const parser::ParseResult big = parser::parse_string("ovus { 0.5, 1 }", "big.pov", parser::ParseOptions{});
    ASSERT_TRUE(big.ok());
    int substitutes = 0;
    for (const auto& w : big.scene->warnings) substitutes += w.message.find("a sphere is drawn") != std::string::npos;
    EXPECT_EQ(substitutes, 1);
    // POV-Ray 3.7.0 has neither of 3.7.1's ovus keywords.
    EXPECT_FALSE(parser::parse_string("ovus { 1, 0.5 radius 3 }", "r.pov", parser::ParseOptions{}).ok());
}

}  // namespace
}  // namespace wardray::geometry
