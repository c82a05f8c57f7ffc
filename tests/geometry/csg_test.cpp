// Tests of CSG: inside tests against POV-Ray's truth tables, crossings on the kept surfaces, leaves, bounds.
#include <gtest/gtest.h>

#include <cmath>

#include "geometry/instance.h"
#include "test_util.h"

namespace wardray::geometry {
namespace {

using test::make_object;
using test::Random;

// Two or three random closed shapes (optionally a plane) under a CSG operation, with a random transform.
scene::Object random_csg(Random& rng, scene::Csg::Op op, bool allow_plane) {
    scene::Csg csg;
    csg.op = op;
    const int n = rng.integer(2, 3);
    for (int i = 0; i < n; ++i) {
        scene::Object child = make_object(test::random_shape(rng, allow_plane && i > 0), rng.transform(0.5));
        child.inverse = rng.chance(0.15);
        csg.children.push_back(child);
    }
    return make_object(csg, rng.transform());
}

bool expected_inside(const scene::Csg& csg, const std::vector<bool>& in) {
    bool result = csg.op == scene::Csg::Op::Intersection || csg.op == scene::Csg::Op::Difference;
    for (std::size_t i = 0; i < in.size(); ++i) {
        switch (csg.op) {
            case scene::Csg::Op::Union:
            case scene::Csg::Op::Merge: result = result || in[i]; break;
            case scene::Csg::Op::Intersection: result = result && in[i]; break;
            case scene::Csg::Op::Difference: result = result && (i == 0 ? in[i] : !in[i]); break;
        }
    }
    return result;
}

constexpr scene::Csg::Op kOps[] = {scene::Csg::Op::Union, scene::Csg::Op::Intersection,
                                     scene::Csg::Op::Difference, scene::Csg::Op::Merge};

TEST(Csg, InsideFollowsTheTruthTables) {
    Random rng(5);
    for (scene::Csg::Op op : kOps) {
        for (int trial = 0; trial < 100; ++trial) {
            const scene::Object obj = random_csg(rng, op, true);
            const auto inst = ShapeInstance::create(obj, 0);
            ASSERT_TRUE(inst);
            const auto& csg = std::get<scene::Csg>(obj.shape);
            for (int k = 0; k < 20; ++k) {
                const Vec3 p_world = obj.transform.point(rng.vec(-2, 2));
                const Vec3 p_local = obj.transform.inverse_point(p_world);
                std::vector<bool> in;
                for (const scene::Object& c : csg.children) in.push_back(ShapeInstance::create(c, 0)->inside(p_local));
                EXPECT_EQ(inst->inside(p_world), expected_inside(csg, in));
            }
        }
    }
}

// The nearest hit and the shadow test agree to the bit with the first of all crossings (they map only the
// normals they need).
TEST(Csg, NearestAndCrossesAgreeWithAllCrossings) {
    Random rng(9);
    for (scene::Csg::Op op : kOps) {
        int hit = 0;
        for (int trial = 0; trial < 200; ++trial) {
            const scene::Object obj = random_csg(rng, op, true);
            const auto inst = ShapeInstance::create(obj, 3);
            ASSERT_TRUE(inst);
            const Vec3 target = obj.transform.point(rng.vec(-1, 1));
            const Vec3 origin = target + rng.direction() * rng.uniform(1.0, 15.0);
            const Vec3 dir = normalize(target - origin);
            const SurfaceHits hits = inst->intersect_all(origin, dir, 0.0, 1e30);
            const auto nearest = inst->nearest(origin, dir, 0.0, 1e30);
            ASSERT_EQ(nearest.has_value(), !hits.empty());
            EXPECT_EQ(inst->crosses(origin, dir, 0.0, 1e30), !hits.empty());
            if (!nearest) continue;
            ++hit;
            EXPECT_EQ(nearest->t, hits[0].t);
            EXPECT_EQ(nearest->normal, hits[0].normal);
            EXPECT_EQ(nearest->leaf, hits[0].leaf);
        }
        EXPECT_GT(hit, 10);
    }
}

// Every crossing of an intersection, difference or merge separates inside from outside of the whole CSG,
// lies on the surface of the leaf it names, and (for bounded results) inside the CSG's bounds.
TEST(Csg, CrossingsSeparateInsideFromOutside) {
    Random rng(6);
    for (scene::Csg::Op op : kOps) {
        int checked = 0;
        int failures = 0;
        for (int trial = 0; trial < 200; ++trial) {
            const scene::Object obj = random_csg(rng, op, true);
            const auto inst = ShapeInstance::create(obj, 0);
            ASSERT_TRUE(inst);
            const Vec3 target = obj.transform.point(rng.vec(-1, 1));
            const Vec3 origin = target + rng.direction() * rng.uniform(1.0, 15.0);
            const Vec3 dir = normalize(target - origin);
            const SurfaceHits hits = inst->intersect_all(origin, dir, 0.0, 1e30);
            const auto& bounds = inst->world_bounds();
            for (const SurfaceHit& h : hits) {
                const Vec3 p = origin + h.t * dir;
                ASSERT_NE(h.leaf, nullptr);
                // The leaf is one of the children, and the point is on that child's surface.
                const auto& csg = std::get<scene::Csg>(obj.shape);
                const scene::Object* leaf = h.leaf;
                const auto it = std::find_if(csg.children.begin(), csg.children.end(),
                                             [&](const scene::Object& c) { return &c == leaf; });
                ASSERT_NE(it, csg.children.end());
                const auto leaf_inst = ShapeInstance::create(*leaf, 0);
                const Vec3 p_csg = obj.transform.inverse_point(p);
                EXPECT_NEAR(leaf_inst->object_implicit(p_csg), 0.0, 1e-8);
                if (bounds) {
                    const double pad = 1e-9 * (bounds->magnitude() + 1);
                    for (int k = 0; k < 3; ++k) {
                        EXPECT_GE(p[k], bounds->lower[k] - pad);
                        EXPECT_LE(p[k], bounds->upper[k] + pad);
                    }
                }
                if (op == scene::Csg::Op::Union) continue;  // unions keep inner surfaces
                const double eps = 1e-7;
                failures += inst->inside(p + eps * h.normal) || !inst->inside(p - eps * h.normal);
                ++checked;
            }
        }
        if (op == scene::Csg::Op::Union) continue;
        EXPECT_GT(checked, 50);
        EXPECT_LE(failures, checked / 100) << "op " << static_cast<int>(op);
    }
}

TEST(Csg, TwoCutsSharingAFaceLeaveNoSheetBetweenThem) {
    // POV-Ray compat: a box's faces count as inside it, so the face the two cut-away boxes share (y = 0 here)
    // is removed from both, and a ray down through the upper cut goes on into the lower one (a user's car body
    // with its roof and a slot cut away at the same height).
    scene::Csg csg;
    csg.op = scene::Csg::Op::Difference;
    csg.children.push_back(make_object(scene::Box{{-2, -1, -1}, {2, 1, 1}}));
    csg.children.push_back(make_object(scene::Box{{-1, 0, -2}, {1, 2, 2}}));
    csg.children.push_back(make_object(scene::Box{{-3, -0.5, -0.5}, {3, 0, 0.5}}));
    const scene::Object obj = make_object(csg);
    const auto inst = ShapeInstance::create(obj, 0);
    ASSERT_TRUE(inst);
    const auto h = inst->nearest({0.5, 5, 0}, {0, -1, 0}, 0.0, 1e30);
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 5.5, 1e-12);  // the slot's floor, not a sheet at y = 0
    // Beside the slot the upper cut's floor stays.
    const auto b = inst->nearest({0.5, 5, 0.8}, {0, -1, 0}, 0.0, 1e30);
    ASSERT_TRUE(b);
    EXPECT_NEAR(b->t, 5.0, 1e-12);
}

TEST(Csg, DifferenceCutsAHoleAndFlipsTheNormal) {
    scene::Csg csg;
    csg.op = scene::Csg::Op::Difference;
    csg.children.push_back(make_object(scene::Box{{-1, -1, -1}, {1, 1, 1}}));
    csg.children.push_back(make_object(scene::Sphere{{0, 0, -1}, 0.5}));
    const scene::Object obj = make_object(csg);
    const auto inst = ShapeInstance::create(obj, 4);
    ASSERT_TRUE(inst);
    // Through the hole: the sphere's inner surface at z = -0.5, facing the ray.
    const auto h = inst->nearest({0, 0, -5}, {0, 0, 1}, 0.0, 1e30);
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 4.5, 1e-12);
    EXPECT_NEAR(h->normal.z, -1.0, 1e-12);
    EXPECT_EQ(h->object, 4u);
    EXPECT_EQ(h->leaf, &std::get<scene::Csg>(obj.shape).children[1]);
    // Beside the hole: the box's face.
    const auto b = inst->nearest({0.8, 0.8, -5}, {0, 0, 1}, 0.0, 1e30);
    ASSERT_TRUE(b);
    EXPECT_NEAR(b->t, 4.0, 1e-12);
    EXPECT_EQ(b->leaf, &std::get<scene::Csg>(obj.shape).children[0]);
}

TEST(Csg, MergeRemovesInnerSurfacesUnionKeepsThem) {
    scene::Csg csg;
    csg.children.push_back(make_object(scene::Sphere{{-0.5, 0, 0}, 1}));
    csg.children.push_back(make_object(scene::Sphere{{0.5, 0, 0}, 1}));
    csg.op = scene::Csg::Op::Union;
    const auto u = ShapeInstance::create(make_object(csg), 0);
    csg.op = scene::Csg::Op::Merge;
    const auto m = ShapeInstance::create(make_object(csg), 0);
    EXPECT_EQ(u->intersect_all({-5, 0, 0}, {1, 0, 0}, 0.0, 1e30).size(), 4u);
    EXPECT_EQ(m->intersect_all({-5, 0, 0}, {1, 0, 0}, 0.0, 1e30).size(), 2u);
}

// POV-Ray compat: `inverse` on a CSG inverts its children and turns a union into an intersection, so a union cut
// away by a difference leaves no wall of one child inside another (qtvrpanorama.pov's hollow box showed them).
TEST(Csg, InvertedUnionKeepsNoInnerSurface) {
    scene::Csg lens;
    lens.op = scene::Csg::Op::Union;
    lens.children.push_back(make_object(scene::Sphere{{-0.5, 0, 0}, 1}));
    lens.children.push_back(make_object(scene::Sphere{{0.5, 0, 0}, 1}));
    scene::Object inverted = make_object(lens);
    inverted.inverse = true;
    const auto inv = ShapeInstance::create(inverted, 0);
    ASSERT_TRUE(inv);
    const SurfaceHits hits = inv->intersect_all({-5, 0, 0}, {1, 0, 0}, 0.0, 1e30);
    ASSERT_EQ(hits.size(), 2u);
    EXPECT_NEAR(hits[0].t, 3.5, 1e-9);
    EXPECT_NEAR(hits[1].t, 6.5, 1e-9);
    EXPECT_FALSE(hits[0].entering);  // into the complement's outside, that is into the union
    EXPECT_FALSE(inv->inside({0, 0, 0}));
    EXPECT_TRUE(inv->inside({0, 3, 0}));

    scene::Csg cut;
    cut.op = scene::Csg::Op::Difference;
    cut.children.push_back(make_object(scene::Box{{-3, -3, -3}, {3, 3, 3}}));
    cut.children.push_back(make_object(lens));
    const auto hole = ShapeInstance::create(make_object(cut), 0);
    ASSERT_TRUE(hole);
    EXPECT_EQ(hole->intersect_all({-5, 0, 0}, {1, 0, 0}, 0.0, 1e30).size(), 4u);  // box, lens, lens, box
}

TEST(Csg, IntersectionWithPlaneIsBounded) {
    scene::Csg csg;
    csg.op = scene::Csg::Op::Intersection;
    csg.children.push_back(make_object(scene::Box{{-1, -1, -1}, {1, 1, 1}}));
    csg.children.push_back(make_object(scene::Plane{{0, 1, 0}, 0.25}));
    const auto inst = ShapeInstance::create(make_object(csg), 0);
    ASSERT_TRUE(inst && inst->world_bounds());
    // POV-Ray compat (CSG intersection's Compute_BBox): a plane facing along an axis cuts the box.
    EXPECT_NEAR(inst->world_bounds()->upper.y, 0.25, 1e-6);
    EXPECT_NEAR(inst->world_bounds()->lower.x, -1.0, 1e-6);
    // The box clipped at y = 0.25: a ray from above hits the cut.
    const auto h = inst->nearest({0, 5, 0}, {0, -1, 0}, 0.0, 1e30);
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 4.75, 1e-12);
}

// POV-Ray compat: a plane's inside includes the points on it (Plane::Inside's EPSILON), and `inverse` negates
// the plane, so they stay inside then too. radiosity_36.pov's walls cut a box and a tunnel whose floors coincide
// at y = 0.3: the box cut's floor is kept wherever rounding puts the hit, and no ray falls through the floor.
TEST(Csg, CoincidentFloorOfABoxCutAndAnInversePlaneIsKept) {
    scene::Csg tunnel;
    tunnel.op = scene::Csg::Op::Intersection;
    tunnel.children.push_back(make_object(scene::Box{{-2, -1, -12}, {2, 2.3, 12}}));
    scene::Object above = make_object(scene::Plane{{0, 1, 0}, 0.3});
    above.inverse = true;
    tunnel.children.push_back(above);
    scene::Csg walls;
    walls.op = scene::Csg::Op::Difference;
    walls.children.push_back(make_object(scene::Box{{-10, -0.1, -10}, {10, 4, 10}}));
    walls.children.push_back(make_object(scene::Box{{-9, 0.3, -9}, {9, 3.5, 9}}));
    walls.children.push_back(make_object(tunnel));
    const auto inst = ShapeInstance::create(make_object(walls), 0);
    ASSERT_TRUE(inst);
    Random rng(11);
    int through = 0;
    for (int k = 0; k < 2000; ++k) {
        const Vec3 origin{rng.uniform(-1.5, 1.5), rng.uniform(0.5, 3.0), rng.uniform(-8, 8)};
        const Vec3 dir = normalize(Vec3{rng.uniform(-0.5, 0.5), -1.0, rng.uniform(-0.5, 0.5)});
        const auto h = inst->nearest(origin, dir, 0.0, 1e30);
        ASSERT_TRUE(h);
        if (std::fabs(h->position.y - 0.3) > 1e-9) ++through;
    }
    EXPECT_EQ(through, 0);
    const auto plane = ShapeInstance::create(above, 0);
    EXPECT_TRUE(plane->inside({0, 0.3, 0}));
    EXPECT_TRUE(plane->inside({0, 0.3 - 1e-11, 0}));
    EXPECT_FALSE(plane->inside({0, 0.2, 0}));
}

TEST(Csg, ClippedByKeepsOnlyTheSurfaceInsideTheClip) {
    scene::Object obj = make_object(scene::Sphere{{0, 0, 0}, 1});
    obj.clipped_by.push_back(make_object(scene::Plane{{0, 0, 1}, 0.0}));
    const auto inst = ShapeInstance::create(obj, 0);
    ASSERT_TRUE(inst);
    // The front half (z < 0) remains; a ray along +z meets it at z = -1 and then sees the inside of nothing else.
    const SurfaceHits hits = inst->intersect_all({0, 0, -5}, {0, 0, 1}, 0.0, 1e30);
    ASSERT_EQ(hits.size(), 1u);
    EXPECT_NEAR(hits[0].t, 4.0, 1e-12);
    // From behind, the ray passes the missing back half and hits the inside of the front half.
    const SurfaceHits back = inst->intersect_all({0, 0, 5}, {0, 0, -1}, 0.0, 1e30);
    ASSERT_EQ(back.size(), 1u);
    EXPECT_NEAR(back[0].t, 6.0, 1e-12);
    EXPECT_FALSE(inst->inside({0, 0, 0.5}));
    EXPECT_TRUE(inst->inside({0, 0, -0.5}));
    // A plane's inside is unbounded, so the clip keeps the sphere's bounds.
    EXPECT_NEAR(inst->world_bounds()->upper.z, 1.0, 1e-12);
}

TEST(Csg, BoundedByHidesTheShapeFromRaysThatMissTheBound) {
    // POV-Ray compat (Ray_In_Bound): a unit sphere bounded by a sphere of radius 0.5 at the origin.
    scene::Object obj = make_object(scene::Sphere{{0, 0, 0}, 1});
    obj.bounded_by.push_back(make_object(scene::Sphere{{0, 0, 0}, 0.5}));
    const auto inst = ShapeInstance::create(obj, 0);
    ASSERT_TRUE(inst);
    // Through the bound: both crossings count, also the ones outside the bound.
    const SurfaceHits through = inst->intersect_all({0, 0, -5}, {0, 0, 1}, 0.0, 1e30);
    ASSERT_EQ(through.size(), 2u);
    EXPECT_NEAR(through[0].t, 4.0, 1e-12);
    // Past the bound (0.7 from the centre) the sphere is not seen although the ray crosses it.
    EXPECT_TRUE(inst->intersect_all({0.7, 0, -5}, {0, 0, 1}, 0.0, 1e30).empty());
    // A ray starting inside the bound sees it whatever its direction; one leaving the bound behind does not.
    EXPECT_EQ(inst->intersect_all({0, 0.2, 0}, {1, 0, 0}, 0.0, 1e30).size(), 1u);
    EXPECT_TRUE(inst->intersect_all({0, 0.7, 0}, {1, 0, 0}, 0.0, 1e30).empty());
    // Bounds move with the object.
    scene::Object moved = obj;
    moved.transform = Transform::translation({3, 0, 0});
    const auto moved_inst = ShapeInstance::create(moved, 0);
    ASSERT_TRUE(moved_inst);
    EXPECT_EQ(moved_inst->intersect_all({3, 0, -5}, {0, 0, 1}, 0.0, 1e30).size(), 2u);
    EXPECT_TRUE(moved_inst->intersect_all({3.7, 0, -5}, {0, 0, 1}, 0.0, 1e30).empty());
}


bool within(const Bounds& b, const Vec3& p) {
    return p.x >= b.lower.x && p.x <= b.upper.x && p.y >= b.lower.y && p.y <= b.upper.y && p.z >= b.lower.z &&
           p.z <= b.upper.z;
}

// A hyperboloid (x² - y² + z² < 1, shapes.inc's Hyperboloid_Y) cut by two planes, as chess2.pov's pawns are built:
// unbounded child by child, bounded together. The node's box is finite and holds every inside point and crossing.
TEST(Csg, PlanesAndAQuadricBoundAnIntersection) {
    Random rng(11);
    for (int trial = 0; trial < 40; ++trial) {
        scene::Csg csg;
        csg.op = scene::Csg::Op::Intersection;
        const double top = rng.uniform(0.5, 3.0), bottom = rng.uniform(-3.0, 0.0);
        csg.children.push_back(make_object(scene::Plane{{0, 1, 0}, top}));
        const Transform placed = Transform::translation(rng.vec(-1, 1)).then(Transform::scaling(rng.vec(0.3, 2.0)));
        csg.children.push_back(make_object(scene::Quadric{{1, -1, 1}, {}, {}, -1}, placed));
        csg.children.push_back(make_object(scene::Plane{{0, -1, 0}, -bottom}));
        // A tilted plane on half the trials: it bounds nothing (as in POV-Ray) but cuts the inside.
        if (trial % 2) csg.children.push_back(make_object(scene::Plane{{0.3, 1, 0.2}, top - 0.2}));
        const scene::Object obj = make_object(csg, rng.transform(2.0));
        const auto inst = ShapeInstance::create(obj, 0);
        ASSERT_TRUE(inst);
        ASSERT_TRUE(inst->world_bounds()) << trial;
        const Bounds box = *inst->world_bounds();
        EXPECT_LT(box.magnitude(), 1e3) << trial;
        int inside = 0, crossings = 0;
        // Half the points around the box (twice its size), half over a wide cube of the node's space.
        const Vec3 centre = (box.lower + box.upper) * 0.5, half = box.upper - centre;
        for (int k = 0; k < 4000; ++k) {
            const Vec3 u = rng.vec(-2, 2);
            const Vec3 p = k % 2 ? centre + Vec3{u.x * half.x, u.y * half.y, u.z * half.z}
                                 : obj.transform.point(rng.vec(-12, 12));
            if (inst->inside(p)) {
                ++inside;
                EXPECT_TRUE(within(box, p)) << trial;
            }
        }
        for (int k = 0; k < 300; ++k) {
            const Vec3 o = obj.transform.point(rng.vec(-4, 4)) + rng.direction() * 20.0;
            const Vec3 d = obj.transform.point(rng.vec(-2, 2)) - o;
            // Tested as a bare shape, not through the culled box (ShapeInstance tests the box only with clips).
            for (const SurfaceHit& h : inst->intersect_all(o, d, 0.0, 1e30)) {
                ++crossings;
                EXPECT_TRUE(within(box, o + h.t * d)) << trial;
            }
        }
        EXPECT_GT(inside, 0) << trial;
        EXPECT_GT(crossings, 0) << trial;
    }
}

}  // namespace
}  // namespace wardray::geometry
