// Tests of the parse-time geometry queries (trace, inside, extents) against hand-computed answers.
#include "geometry/object_query.h"

#include <gtest/gtest.h>

namespace wardray::geometry {
namespace {

scene::Object stretched_sphere() {
    // sphere { <1,2,3>, 2 scale <1,1,2> }: centre <1,2,6>, semi-axes 2, 2, 4.
    scene::Object o;
    o.shape = scene::Sphere{{1, 2, 3}, 2};
    o.transform = Transform::scaling({1, 1, 2});
    return o;
}

TEST(ObjectQuery, TraceFindsTheNearestSurfaceAndItsNormal) {
    const ObjectQuery q;
    const auto hit = q.trace(stretched_sphere(), {1, 10, 6}, {0, -1, 0});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->point.x, 1.0, 1e-12);
    EXPECT_NEAR(hit->point.y, 4.0, 1e-12);
    EXPECT_NEAR(hit->point.z, 6.0, 1e-12);
    EXPECT_NEAR(hit->normal.y, 1.0, 1e-12);
    EXPECT_FALSE(q.trace(stretched_sphere(), {1, 10, 6}, {0, 1, 0}));  // pointing away
    EXPECT_FALSE(q.trace(stretched_sphere(), {1, 10, 6}, {0, 0, 0}));  // no direction
}

TEST(ObjectQuery, TraceKeepsNoStalePlacementWhenTheObjectChanges) {
    // trace() keeps the last object it placed; a different object (or the same one moved) is placed afresh,
    // and a temporary object gone after the call leaves the kept copy valid.
    const ObjectQuery q;
    for (int turn = 0; turn < 3; ++turn) {
        scene::Object moved = stretched_sphere();
        moved.transform = moved.transform.then(Transform::translation({0, -1.0 * turn, 0}));
        const auto a = q.trace(moved, {1, 10, 6}, {0, -1, 0});
        ASSERT_TRUE(a);
        EXPECT_NEAR(a->point.y, 4.0 - turn, 1e-12) << turn;
        const auto b = q.trace(stretched_sphere(), {1, 10, 6}, {0, -1, 0});
        ASSERT_TRUE(b);
        EXPECT_NEAR(b->point.y, 4.0, 1e-12) << turn;
    }
}

TEST(ObjectQuery, InsideFollowsTransformAndInverse) {
    const ObjectQuery q;
    scene::Object o = stretched_sphere();
    EXPECT_TRUE(q.inside(o, {1, 2, 9.5}));   // inside only because of the z stretch
    EXPECT_FALSE(q.inside(o, {1, 4.5, 6}));
    o.inverse = true;
    EXPECT_FALSE(q.inside(o, {1, 2, 9.5}));
    EXPECT_TRUE(q.inside(o, {1, 4.5, 6}));
}

TEST(ObjectQuery, ExtentsOfBoundedAndUnboundedObjects) {
    const ObjectQuery q;
    const auto box = q.extent(stretched_sphere());
    ASSERT_TRUE(box);
    EXPECT_NEAR(box->first.x, -1.0, 1e-9);
    EXPECT_NEAR(box->first.z, 2.0, 1e-9);
    EXPECT_NEAR(box->second.y, 4.0, 1e-9);
    EXPECT_NEAR(box->second.z, 10.0, 1e-9);
    scene::Object plane;
    plane.shape = scene::Plane{{0, 1, 0}, 0};
    EXPECT_FALSE(q.extent(plane));  // the parser reports POV-Ray's huge box for it
    scene::Object degenerate = stretched_sphere();
    degenerate.transform = Transform::scaling({1, 0, 1});
    EXPECT_FALSE(q.extent(degenerate));
    EXPECT_FALSE(q.trace(degenerate, {1, 10, 6}, {0, -1, 0}));
}

}  // namespace
}  // namespace wardray::geometry
