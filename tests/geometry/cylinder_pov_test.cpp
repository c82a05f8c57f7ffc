// Tests that cylinders meet grazing rays as POV-Ray 3.7 does (its single matrix to the unit cylinder).
#include <gtest/gtest.h>

#include <cmath>

#include "geometry/instance.h"
#include "test_util.h"

namespace wardray::geometry {
namespace {

using test::make_object;

// qtvrpanorama.pov's CylinderCluster placed by `extra`: five cylinders {-z, +z, 1} (one moved by each of -x-y,
// +x-y, -x+y, +x+y), scaled by <0.4, 0.4, 1.1>, inverse.
scene::Object cylinder_cluster(const Transform& extra) {
    scene::Csg cluster;
    const Vec3 moves[5] = {{0, 0, 0}, {-1, -1, 0}, {1, -1, 0}, {-1, 1, 0}, {1, 1, 0}};
    for (const Vec3& move : moves) {
        scene::Cylinder c;
        c.base = {0, 0, -1};
        c.cap = {0, 0, 1};
        c.radius = 1.0;
        Transform xf = Transform::translation(move).then(Transform::scaling({0.4, 0.4, 1.1})).then(extra);
        cluster.children.push_back(make_object(c, xf));
    }
    scene::Object o = make_object(cluster);
    o.inverse = true;
    return o;
}

// Its HollowBox: box {-1, 1} with the cluster bored through it along z, x and y.
scene::Object hollow_box() {
    scene::Csg box;
    box.op = scene::Csg::Op::Intersection;
    box.children.push_back(make_object(scene::Box{{-1, -1, -1}, {1, 1, 1}}));
    box.children.push_back(cylinder_cluster(Transform()));
    box.children.push_back(cylinder_cluster(Transform::rotation({0, 90, 0})));
    box.children.push_back(cylinder_cluster(Transform::rotation({90, 0, 0})));
    return make_object(box);
}

// The sideways cylinder camera's rays of pixel row 68 of 90 (1-based) look 90 degrees down its turn: their z is
// cos(-pi/2), 6e-17, so they run along the plane z = 0 that the bores along x and y touch, and graze them. POV-Ray
// 3.7's distances to the HollowBox, from `trace(HollowBox, <0,0,0>, <-1, -X0, cos(-pi/2)>)` (X0 = (col + 0.5) / 120
// - 0.5) printed with str(vlength(P), 0, 17); wardray's object-space cylinder met the bores 3e-8 further out.
TEST(CylinderPov, GrazingRaysMeetTheBoresWherePovRayDoes) {
    const scene::Object object = hollow_box();
    const auto inst = ShapeInstance::create(object, 0);
    ASSERT_TRUE(inst.has_value());
    const struct {
        int column;
        double distance;
    } expected[] = {{108, 1.06746790327347929}, {110, 1.03123267943438401}, {113, 0.98232435171718713},
                    {116, 0.93901436804624594}, {119, 0.90044516605366720}};
    const double cy = std::cos(-0.25 * (360 * 0.01745329251994329576));
    for (const auto& e : expected) {
        const double x0 = (e.column + 0.5) / 120 - 0.5;
        const Vec3 raw{-1.0, -x0, cy};
        const double inv = 1.0 / std::sqrt(raw.x * raw.x + raw.y * raw.y + raw.z * raw.z);
        const Vec3 dir{raw.x * inv, raw.y * inv, raw.z * inv};
        const auto hit = inst->nearest({0, 0, 0}, dir, 1e-4, 1e30);
        ASSERT_TRUE(hit.has_value()) << "column " << e.column;
        EXPECT_NEAR(hit->t, e.distance, 1e-14) << "column " << e.column;
    }
}

// Inside tests go through the same matrix, with POV-Ray's EPSILON margins: a closed cylinder excludes points within
// 1e-10 of its side (in unit-cylinder lengths), an open one includes them.
TEST(CylinderPov, InsideMarginsInUnitSpace) {
    for (const bool open : {false, true}) {
        scene::Cylinder c;
        c.base = {0, 0, 0};
        c.cap = {0, 0, 2};
        c.radius = 2.0;
        c.open = open;
        const auto inst = ShapeInstance::create(make_object(c, Transform::translation({1, 0, 0})), 0);
        ASSERT_TRUE(inst.has_value());
        EXPECT_TRUE(inst->inside({1, 0, 1}));
        EXPECT_EQ(inst->inside({3 - 1e-11, 0, 1}), open) << "open " << open;
        EXPECT_EQ(inst->inside({1, 0, 2 + 1e-11}), open) << "open " << open;
        EXPECT_FALSE(inst->inside({3.001, 0, 1}));
    }
}

}  // namespace
}  // namespace wardray::geometry
