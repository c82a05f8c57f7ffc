// Tests of meshes traced by Embree as native triangles: nearest hits and shadows against a brute-force loop.
#include <gtest/gtest.h>

#include <cmath>

#include "geometry/instance.h"
#include "geometry/scene_geometry.h"
#include "test_util.h"

namespace wardray::geometry {
namespace {

using test::make_object;
using test::Random;

std::optional<Hit> brute_force(const scene::Scene& scene, const Ray& ray) {
    std::optional<Hit> best;
    for (std::uint32_t i = 0; i < scene.objects.size(); ++i) {
        const auto inst = ShapeInstance::create(scene.objects[i], i);
        if (!inst || !inst->visible_to(ray.kind)) continue;
        if (auto hit = inst->nearest(ray.origin, ray.direction, ray.t_min, best ? best->t : ray.t_max)) best = hit;
    }
    return best;
}

TEST(MeshScene, EmbreeTrianglesMatchBruteForce) {
    Random rng(77);
    scene::Scene scene;
    for (int i = 0; i < 8; ++i) {
        scene::Object o = make_object(test::random_soup(rng, 40, 0.6, 0.3), rng.transform(10.0));
        o.no_shadow = rng.chance(0.2);
        o.no_image = rng.chance(0.2);
        scene.objects.push_back(o);
    }
    for (int i = 0; i < 20; ++i) scene.objects.push_back(make_object(test::random_shape(rng, false), rng.transform(10.0)));
    const SceneGeometry geometry(scene);
    int mismatches = 0;
    int hits = 0;
    constexpr int rays = 20000;
    for (int i = 0; i < rays; ++i) {
        Ray ray;
        ray.origin = rng.vec(-25, 25);
        ray.direction = normalize(rng.vec(-8, 8) - ray.origin) * rng.uniform(0.5, 2.0);
        ray.kind = static_cast<RayKind>(rng.integer(0, 3));
        const auto got = geometry.intersect(ray);
        const auto want = brute_force(scene, ray);
        hits += got.has_value();
        // Float traversal and double refinement may disagree only for rays through a triangle's edge.
        if (got.has_value() != want.has_value() || (got && (got->object != want->object ||
                                                            std::fabs(got->t - want->t) > 1e-9 * want->t))) {
            ++mismatches;
            continue;
        }
        if (got) {
            EXPECT_NEAR(length(got->normal), 1.0, 1e-12);
            EXPECT_EQ(got->leaf, &scene.objects[got->object]);
        }
        ray.kind = RayKind::Shadow;
        EXPECT_EQ(geometry.occluded(ray), brute_force(scene, ray).has_value());
    }
    EXPECT_GT(hits, rays / 10);
    EXPECT_LE(mismatches, rays / 1000);
}

// Beside a sky sphere of radius 1e6, rays from far away meet the meshes in one traversal and the other objects in
// the scene-wide BVH (see SceneGeometry's far_scene); rays from near meet both in the tight one.
TEST(MeshScene, MeshesBesideAHugeObjectMatchBruteForce) {
    Random rng(78);
    scene::Scene scene;
    for (int i = 0; i < 6; ++i) {
        scene::Object o = make_object(test::random_soup(rng, 40, 0.6, 0.3), rng.transform(4.0));
        o.no_shadow = rng.chance(0.2);
        scene.objects.push_back(o);
    }
    for (int i = 0; i < 20; ++i) scene.objects.push_back(make_object(test::random_shape(rng, false), rng.transform(4.0)));
    scene::Object sky = make_object(scene::Sphere{{0, 0, 0}, 1.0});
    sky.transform = Transform::scaling({1e6, 1e6, 1e6});
    scene.objects.push_back(sky);
    const SceneGeometry geometry(scene);
    int mismatches = 0, hits = 0;
    constexpr int rays = 20000;
    for (int i = 0; i < rays; ++i) {
        Ray ray;
        ray.origin = rng.chance(0.5) ? rng.direction() * std::pow(10.0, rng.uniform(1.5, 5.0)) : rng.vec(-6, 6);
        ray.direction = normalize(rng.vec(-4, 4) - ray.origin) * rng.uniform(0.5, 2.0);
        ray.kind = static_cast<RayKind>(rng.integer(0, 3));
        const auto got = geometry.intersect(ray);
        const auto want = brute_force(scene, ray);
        hits += got.has_value() && got->object + 1 < scene.objects.size();
        // Float traversal and double refinement may disagree only for rays through a triangle's edge.
        if (got.has_value() != want.has_value() ||
            (got && (got->object != want->object || std::fabs(got->t - want->t) > 1e-9 * want->t))) {
            ++mismatches;
            continue;
        }
        ray.kind = RayKind::Shadow;
        mismatches += geometry.occluded(ray) != brute_force(scene, ray).has_value();
    }
    EXPECT_GT(hits, rays / 4);
    EXPECT_LE(mismatches, rays / 1000);
}

// The trace writes an accepted face's hit itself (flat meshes copy a normal made when the scene is built): every
// field must be what ShapeInstance::face_hit gives for that face, bit for bit, on flat, smooth and inverse meshes.
TEST(MeshScene, AcceptedFaceIsFaceHitBitForBit) {
    Random rng(79);
    scene::Scene scene;
    for (int i = 0; i < 9; ++i) {
        scene::Object o = make_object(test::random_soup(rng, 40, 0.6, i % 3 == 0 ? 0.5 : 0.0), rng.transform(10.0));
        o.inverse = i % 4 == 1;
        scene.objects.push_back(o);
    }
    const SceneGeometry geometry(scene);
    int face_hits = 0;
    for (int i = 0; i < 5000; ++i) {
        Ray ray;
        ray.origin = rng.vec(-25, 25);
        ray.direction = normalize(rng.vec(-8, 8) - ray.origin) * rng.uniform(0.5, 2.0);
        const auto got = geometry.intersect(ray);
        if (!got || got->face < 0) continue;
        const auto inst = ShapeInstance::create(scene.objects[got->object], got->object);
        ASSERT_TRUE(inst.has_value());
        const auto& faces = std::get<MeshShape>(inst->shape()).faces();
        std::size_t f = 0;
        while (f < faces.size() && faces[f].source != got->face) ++f;
        ASSERT_LT(f, faces.size());
        const auto want = inst->face_hit(ray.origin, ray.direction, f, -INFINITY, INFINITY);
        ASSERT_TRUE(want.has_value());
        ++face_hits;
        EXPECT_EQ(got->t, want->t);
        EXPECT_EQ(got->position, want->position);
        EXPECT_EQ(got->normal, want->normal);
        EXPECT_EQ(got->bary_u, want->bary_u);
        EXPECT_EQ(got->bary_v, want->bary_v);
        EXPECT_EQ(got->leaf, want->leaf);
    }
    EXPECT_GT(face_hits, 500);
}

}  // namespace
}  // namespace wardray::geometry
