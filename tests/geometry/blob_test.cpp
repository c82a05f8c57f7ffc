// Tests of BlobShape: random blobs against brute force (surface, finite-difference normals, sampled inside) and
// single components whose surfaces are known exactly.
#include <gtest/gtest.h>

#include <cmath>

#include "geometry/instance.h"
#include "parser/parse.h"
#include "test_util.h"

namespace wardray::geometry {
namespace {

using test::make_object;
using test::Random;
using Component = scene::Blob::Component;

// A blob of 1 to 5 components: spheres and cylinders, some of negative strength, some with their own transforms.
scene::Blob random_blob(Random& r) {
    scene::Blob b;
    b.threshold = r.uniform(0.2, 0.8);
    const int n = r.integer(1, 5);
    for (int i = 0; i < n; ++i) {
        Component c;
        c.cylinder = r.chance(0.4);
        c.a = r.vec(-0.8, 0.8);
        c.b = c.a + r.direction() * r.uniform(0.3, 1.5);
        c.radius = r.uniform(0.5, 1.3);
        c.strength = i > 0 && r.chance(0.25) ? -r.uniform(0.5, 2.0) : r.uniform(0.8, 2.5);
        if (r.chance(0.3)) c.transform = Transform::scaling(r.vec(0.5, 1.5)).then(Transform::rotation(r.vec(-90, 90)));
        b.components.push_back(c);
    }
    return b;
}

Component sphere_component(const Vec3& centre, double radius, double strength) {
    Component c;
    c.a = centre;
    c.radius = radius;
    c.strength = strength;
    return c;
}

TEST(Blob, RandomRaysHitTheThresholdWithOutwardNormals) {
    test::check_shape(random_blob, true, 77, 1e-9, 150, 400);
}

TEST(Blob, NormalsAgreeWithFiniteDifferences) {
    Random rng(5);
    int checked = 0;
    for (int trial = 0; trial < 300; ++trial) {
        const scene::Object obj = make_object(random_blob(rng), rng.transform());
        const auto inst = ShapeInstance::create(obj, 0);
        ASSERT_TRUE(inst);
        const test::AimedRay ray = test::aim_random_ray(rng, obj, 0.8);
        for (const SurfaceHit& h : inst->intersect_all(ray.origin, ray.direction, 0.0, 1e30)) {
            const Vec3 p = ray.origin + h.t * ray.direction;
            // The implicit function rises outwards, so its world gradient points along the normal.
            const double e = 1e-6 * test::object_scale(*inst);
            Vec3 g;
            for (int k = 0; k < 3; ++k) {
                Vec3 d;
                d[k] = e;
                g[k] = (inst->object_implicit(p + d) - inst->object_implicit(p - d)) / (2 * e);
            }
            // Where components start or stop the density is smooth only to first order: skip weak gradients.
            if (length(g) * test::object_scale(*inst) < 1e-2) continue;
            EXPECT_GT(dot(normalize(g), h.normal), 1.0 - 1e-6) << "trial " << trial;
            ++checked;
        }
    }
    EXPECT_GT(checked, 200);
}

TEST(Blob, CrossingsAgreeWithTheSampledInsideTest) {
    // Along each ray the inside test, sampled densely, changes where the blob reports a crossing and nowhere else.
    Random rng(11);
    int rays = 0, mismatches = 0;
    for (int trial = 0; trial < 300; ++trial) {
        const scene::Object obj = make_object(random_blob(rng), rng.transform());
        const auto inst = ShapeInstance::create(obj, 0);
        ASSERT_TRUE(inst);
        const test::AimedRay ray = test::aim_random_ray(rng, obj, 0.8);
        const double t_end = 40.0 / length(ray.direction);
        const SurfaceHits hits = inst->intersect_all(ray.origin, ray.direction, 0.0, t_end);
        const int samples = 20000;
        int changes = 0;
        bool was = inst->inside(ray.origin);
        for (int i = 1; i <= samples; ++i) {
            const bool now = inst->inside(ray.origin + (t_end * i / samples) * ray.direction);
            changes += now != was;
            was = now;
        }
        ++rays;
        mismatches += changes != static_cast<int>(hits.size());
    }
    // Grazing rays whose two crossings fall between two samples may differ.
    EXPECT_LE(mismatches, rays / 50);
}

TEST(Blob, SphereComponentSurfaceIsAtTheThresholdRadius) {
    scene::Blob b;
    b.threshold = 0.5;
    b.components = {sphere_component({0, 0, 0}, 1.0, 1.0)};
    const auto inst = ShapeInstance::create(make_object(b), 0);
    ASSERT_TRUE(inst);
    // (1 - d²)² = 1/2 at d² = 1 - √½.
    const double d = std::sqrt(1.0 - std::sqrt(0.5));
    const SurfaceHits hits = inst->intersect_all({-5, 0, 0}, {1, 0, 0}, 0.0, 1e30);
    ASSERT_EQ(hits.size(), 2u);
    EXPECT_NEAR(hits[0].t, 5.0 - d, 1e-12);
    EXPECT_NEAR(hits[1].t, 5.0 + d, 1e-12);
    EXPECT_NEAR(hits[0].normal.x, -1.0, 1e-12);
    EXPECT_TRUE(hits[0].entering);
    EXPECT_FALSE(hits[1].entering);
    EXPECT_TRUE(inst->inside({0.5, 0, 0}));
    EXPECT_FALSE(inst->inside({0.6, 0, 0}));
    // A weaker component's surface is nearer its centre; strength below the threshold has none.
    b.components[0].strength = 0.4;
    const auto weak = ShapeInstance::create(make_object(b), 0);
    ASSERT_TRUE(weak);
    EXPECT_TRUE(weak->intersect_all({-5, 0, 0}, {1, 0, 0}, 0.0, 1e30).empty());
}

TEST(Blob, CylinderComponentIsRoundedAtItsEnds) {
    scene::Blob b;
    b.threshold = 0.5;
    Component c;
    c.cylinder = true;
    c.a = {-1, 0, 0};
    c.b = {1, 0, 0};
    c.radius = 1.0;
    c.strength = 1.0;
    b.components = {c};
    const auto inst = ShapeInstance::create(make_object(b), 0);
    ASSERT_TRUE(inst);
    const double d = std::sqrt(1.0 - std::sqrt(0.5));
    // From the side at any point of the axis, and along the axis beyond each end.
    for (double x : {-0.9, 0.0, 0.7}) {
        const auto side = inst->nearest({x, 5, 0}, {0, -1, 0}, 0.0, 1e30);
        ASSERT_TRUE(side);
        EXPECT_NEAR(side->t, 5.0 - d, 1e-12);
        EXPECT_NEAR(side->normal.y, 1.0, 1e-12);
    }
    const SurfaceHits along = inst->intersect_all({-5, 0, 0}, {1, 0, 0}, 0.0, 1e30);
    ASSERT_EQ(along.size(), 2u);
    EXPECT_NEAR(along[0].t, 4.0 - d, 1e-12);
    EXPECT_NEAR(along[1].t, 6.0 + d, 1e-12);
    // On the end cap, off the axis by 45 degrees, the surface is a sphere about the end point.
    const Vec3 dir = normalize(Vec3{1, 1, 0});
    const auto cap = inst->nearest(Vec3{1, 0, 0} + 5.0 * dir, -dir, 0.0, 1e30);
    ASSERT_TRUE(cap);
    EXPECT_NEAR(cap->t, 5.0 - d, 1e-12);
    EXPECT_NEAR(dot(cap->normal, dir), 1.0, 1e-12);
}

TEST(Blob, NegativeStrengthCutsAHole) {
    scene::Blob b;
    b.threshold = 0.5;
    b.components = {sphere_component({0, 0, 0}, 2.0, 2.0), sphere_component({0, 0, 0}, 0.8, -3.0)};
    const auto inst = ShapeInstance::create(make_object(b), 0);
    ASSERT_TRUE(inst);
    EXPECT_FALSE(inst->inside({0, 0, 0}));
    EXPECT_TRUE(inst->inside({0, 1.0, 0}));
    // Outer wall, inner wall, inner wall, outer wall.
    EXPECT_EQ(inst->intersect_all({-5, 0, 0}, {1, 0, 0}, 0.0, 1e30).size(), 4u);
}

TEST(Blob, TinyAndHugeScalesGiveTheSameHits) {
    Random rng(3);
    const scene::Blob b = random_blob(rng);
    const auto unit = ShapeInstance::create(make_object(b), 0);
    ASSERT_TRUE(unit);
    for (double s : {1e-4, 1e4}) {
        const auto scaled = ShapeInstance::create(make_object(b, Transform::scaling({s, s, s})), 0);
        ASSERT_TRUE(scaled);
        for (int i = 0; i < 50; ++i) {
            const Vec3 o = rng.direction() * 6.0, d = rng.vec(-0.5, 0.5) - o;
            const SurfaceHits a = unit->intersect_all(o, d, 0.0, 1e30);
            const SurfaceHits c = scaled->intersect_all(s * o, s * d, 0.0, 1e30);
            ASSERT_EQ(a.size(), c.size());
            for (std::size_t k = 0; k < a.size(); ++k) {
                EXPECT_NEAR(a[k].t, c[k].t, 1e-9 * (1.0 + a[k].t));
                EXPECT_TRUE(is_finite(c[k].normal));
                EXPECT_NEAR(dot(a[k].normal, c[k].normal), 1.0, 1e-9);
            }
        }
    }
}

TEST(Blob, ParsesBothSyntaxesLastComponentFirst) {
    parser::ParseOptions options;
    const parser::ParseResult r = parser::parse_string(
        "blob { threshold 0.6 component 1, 2, <1, 0, 0>\n"
        "  sphere { <0, 1, 0>, 0.5, strength -1 scale 2 }\n"
        "  cylinder { 0, x, 0.3, 2 translate y } sturm hierarchy off pigment { rgb 1 } }",
        "blob.pov", options);
    ASSERT_TRUE(r.ok());
    ASSERT_EQ(r.scene->objects.size(), 1u);
    const auto& b = std::get<scene::Blob>(r.scene->objects[0].shape);
    EXPECT_EQ(b.threshold, 0.6);
    ASSERT_EQ(b.components.size(), 3u);
    EXPECT_TRUE(b.components[0].cylinder);
    EXPECT_EQ(b.components[0].strength, 2.0);
    EXPECT_EQ(b.components[0].transform.point({0, 0, 0}), (Vec3{0, 1, 0}));
    EXPECT_EQ(b.components[1].strength, -1.0);
    EXPECT_EQ(b.components[1].transform.point({1, 0, 0}), (Vec3{2, 0, 0}));
    EXPECT_EQ(b.components[2].radius, 2.0);
    EXPECT_EQ(b.components[2].a, (Vec3{1, 0, 0}));
    const parser::ParseResult bad = parser::parse_string("blob { cylinder { x, x, 1, 1 } }", "bad.pov", options);
    EXPECT_FALSE(bad.ok());
}

}  // namespace
}  // namespace wardray::geometry
