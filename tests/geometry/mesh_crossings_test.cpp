// Tests of a mesh's crossings for CSG: the face tree finds what testing every face finds, a mesh without an
// inside_vector stops at its nearest crossing as POV-Ray's does, and shapes of one scene mesh share their data.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "geometry/mesh.h"
#include "test_util.h"

namespace wardray::geometry {
namespace {

using test::Random;

constexpr double k_far = std::numeric_limits<double>::infinity();

// The regular octahedron |x| + |y| + |z| = 1 as eight faces.
scene::Mesh octahedron() {
    scene::Mesh m;
    m.vertices = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (const int a : {0, 1})
        for (const int b : {2, 3})
            for (const int c : {4, 5}) {
                scene::Mesh::Face f;
                f.v = {a, b, c};
                m.faces.push_back(f);
            }
    return m;
}

// Every face's crossing in (t_min, inf), sorted by t: what the tree must reproduce.
std::vector<double> every_face(const MeshShape& mesh, const LocalRay& ray, double t_min) {
    std::vector<double> ts;
    for (std::size_t i = 0; i < mesh.faces().size(); ++i)
        if (const auto h = mesh.intersect_face(ray, i, t_min, k_far)) ts.push_back(h->t);
    std::sort(ts.begin(), ts.end());
    return ts;
}

TEST(MeshCrossings, TheFaceTreeFindsEveryCrossingThatTestingEachFaceFinds) {
    Random rng(2311);
    scene::Mesh m = test::random_soup(rng, 600, 0.5);
    m.inside_vector = {0.3, 1.0, 0.2};  // all crossings, as POV-Ray gives a mesh with an inside_vector
    const auto mesh = MeshShape::create(m);
    ASSERT_TRUE(mesh);
    int crossings = 0;
    for (int i = 0; i < 4000; ++i) {
        const LocalRay ray{rng.vec(-4, 4), rng.direction() * rng.uniform(0.2, 3.0)};
        const std::vector<double> want = every_face(*mesh, ray, 1e-6);
        const SurfaceHits got = mesh->intersect_all(ray, 1e-6, k_far);
        ASSERT_EQ(got.size(), want.size()) << "ray " << i;
        for (std::size_t k = 0; k < want.size(); ++k) EXPECT_EQ(got[k].t, want[k]) << "ray " << i;
        crossings += static_cast<int>(want.size());
        // The inside test walks the same tree: an odd count of crossings along the inside_vector.
        const LocalRay up{ray.origin, m.inside_vector};
        EXPECT_EQ(mesh->inside(ray.origin), every_face(*mesh, up, 0.0).size() % 2 == 1) << "ray " << i;
    }
    EXPECT_GT(crossings, 1000);  // the rays do cross the soup (1650 crossings with this seed)
}

TEST(MeshCrossings, WithoutAnInsideVectorOnlyTheNearestCrossingOfAConvexMeshIsGiven) {
    scene::Mesh m = octahedron();
    const auto open = MeshShape::create(m);
    m.inside_vector = {0.1, 1.0, 0.2};
    const auto closed = MeshShape::create(m);
    ASSERT_TRUE(open && closed);
    // Along +z at (0.1, 0.1): in through the face at z < 0 (t = 4.2), out through the face at z > 0 (t = 5.8),
    // whose box starts at z = 0 (t = 5), beyond the first crossing.
    const LocalRay ray{{0.1, 0.1, -5.0}, {0.0, 0.0, 1.0}};
    const SurfaceHits both = closed->intersect_all(ray, 1e-6, k_far);
    ASSERT_EQ(both.size(), 2u);
    EXPECT_NEAR(both[0].t, 4.2, 1e-12);
    EXPECT_NEAR(both[1].t, 5.8, 1e-12);
    const SurfaceHits near = open->intersect_all(ray, 1e-6, k_far);
    ASSERT_EQ(near.size(), 1u);
    EXPECT_EQ(near[0].t, both[0].t);
    // From inside, the only crossing is the way out.
    const SurfaceHits out = open->intersect_all({{0.1, 0.1, 0.0}, {0.0, 0.0, 1.0}}, 1e-6, k_far);
    ASSERT_EQ(out.size(), 1u);
    EXPECT_NEAR(out[0].t, 0.8, 1e-12);
}

TEST(MeshCrossings, WithoutAnInsideVectorTheNearestCrossingIsAlwaysAmongThoseGiven) {
    Random rng(907);
    scene::Mesh m = test::random_soup(rng, 300, 0.5);
    const auto open = MeshShape::create(m);
    m.inside_vector = {0.3, 1.0, 0.2};
    const auto closed = MeshShape::create(m);
    ASSERT_TRUE(open && closed);
    int fewer = 0;
    for (int i = 0; i < 3000; ++i) {
        const LocalRay ray{rng.vec(-4, 4), rng.direction()};
        const SurfaceHits all = closed->intersect_all(ray, 1e-6, k_far);
        const SurfaceHits some = open->intersect_all(ray, 1e-6, k_far);
        ASSERT_EQ(all.empty(), some.empty()) << "ray " << i;
        if (all.empty()) continue;
        EXPECT_EQ(some[0].t, all[0].t) << "ray " << i;
        // Each crossing given is one of the crossings: the walk leaves some out, never makes one up.
        for (const SurfaceHit& h : some)
            EXPECT_TRUE(std::any_of(all.begin(), all.end(), [&](const SurfaceHit& a) { return a.t == h.t; }));
        if (some.size() < all.size()) ++fewer;
    }
    EXPECT_GT(fewer, 100);  // the far crossings are left out for many rays
}

TEST(MeshCrossings, ShapesMadeFromOneSceneMeshShareTheirData) {
    Random rng(41);
    const scene::Mesh m = test::random_soup(rng, 200, 0.5);
    const scene::Mesh same = m;  // a copy that shares the vectors, as `object { M }` does
    const auto a = MeshShape::create(m);
    const auto b = MeshShape::create(same);
    ASSERT_TRUE(a && b);
    EXPECT_EQ(a->faces().data(), b->faces().data());
    EXPECT_EQ(a->vertices().data(), m.vertices.data());  // the scene's own vertices, not a copy
    // A mesh changed since (its own vectors) or with another inside_vector is a shape of its own.
    scene::Mesh moved = m;
    moved.vertices.mut()[0] += Vec3{0.25, 0.0, 0.0};
    scene::Mesh closed = m;
    closed.inside_vector = {0.0, 1.0, 0.0};
    const auto c = MeshShape::create(moved);
    const auto d = MeshShape::create(closed);
    ASSERT_TRUE(c && d);
    EXPECT_NE(c->faces().data(), a->faces().data());
    EXPECT_NE(c->vertices()[0].x, a->vertices()[0].x);
    EXPECT_NE(d->faces().data(), a->faces().data());
    // Shared or not, they cross a ray alike where they are alike.
    for (int i = 0; i < 500; ++i) {
        const LocalRay ray{rng.vec(-4, 4), rng.direction()};
        const SurfaceHits ha = a->intersect_all(ray, 1e-6, k_far), hb = b->intersect_all(ray, 1e-6, k_far);
        ASSERT_EQ(ha.size(), hb.size());
        for (std::size_t k = 0; k < ha.size(); ++k) EXPECT_EQ(ha[k].t, hb[k].t);
    }
}

}  // namespace
}  // namespace wardray::geometry
