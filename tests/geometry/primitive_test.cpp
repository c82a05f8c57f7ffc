// Tests of the primitives beyond sphere, box and plane: random rays hit the surface, normals point outward,
// entering flags and inside tests agree, and POV-Ray's parameter conventions hold.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "geometry/instance.h"
#include "geometry/superellipsoid.h"
#include "test_util.h"

namespace wardray::geometry {
namespace {

using test::check_shape;
using test::make_object;
using test::Random;

TEST(Primitives, Cylinder) {
    check_shape([](Random& r) {
        return scene::Cylinder{r.vec(-1, 1), r.vec(-1, 1), r.uniform(0.2, 1.0), r.chance(0.3)};
    }, true, 11);
}

TEST(Primitives, CylinderNormalInPovRaysArithmetic) {
    // POV-Ray compat: language/trace.pov traces straight down onto cylinder { <-1, 0, -0.003>, <-1, 0, 0.11>, 0.5 }
    // from <-1.499, 2, 0> and prints the normal with vstr(). POV-Ray turns its unit cylinder half round (the axis runs
    // from the second point to the first, along -z) by a sine of pi that is not 0, so the normal's z is -7.74e-18
    // (POV-Ray's #debug prints -0.000000000000000007741472787214), which prints as "-0.00" rather than "0.00".
    const auto inst = ShapeInstance::create(make_object(scene::Cylinder{{-1, 0, -0.003}, {-1, 0, 0.11}, 0.5}), 0);
    ASSERT_TRUE(inst);
    const auto hit = inst->nearest({-1.499, 2, 0}, {0, -1, 0}, 0.0, 1e30);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->normal.x, -0.998, 1e-12);
    EXPECT_LT(hit->normal.z, 0.0);
    EXPECT_NEAR(hit->normal.z, -7.741472787214e-18, 1e-27);
    // Along +z the turn is none at all: the normal has no z part.
    const auto up = ShapeInstance::create(make_object(scene::Cylinder{{-1, 0, 0.11}, {-1, 0, -0.003}, 0.5}), 0);
    ASSERT_TRUE(up);
    const auto hit_up = up->nearest({-1.499, 2, 0}, {0, -1, 0}, 0.0, 1e30);
    ASSERT_TRUE(hit_up);
    EXPECT_EQ(hit_up->normal.z, 0.0);
}

TEST(Primitives, Cone) {
    check_shape([](Random& r) {
        return scene::Cone{r.vec(-1, 1), r.uniform(0.0, 1.0), r.vec(-1, 1), r.uniform(0.1, 1.0), r.chance(0.3)};
    }, true, 12);
}

TEST(Primitives, Torus) {
    check_shape([](Random& r) { return scene::Torus{r.uniform(0.5, 1.5), r.uniform(0.1, 0.5)}; }, true, 13);
}

TEST(Primitives, Disc) {
    check_shape([](Random& r) {
        return scene::Disc{r.vec(-0.3, 0.3), r.direction(), r.uniform(0.8, 1.5), r.uniform(0.0, 0.5)};
    }, false, 14, 1e-9, 60);
}

TEST(Primitives, QuadricEllipsoidAndHyperboloid) {
    check_shape([](Random& r) {
        const double sign = r.chance(0.5) ? 1.0 : -1.0;
        return scene::Quadric{{r.uniform(0.5, 2), sign * r.uniform(0.5, 2), r.uniform(0.5, 2)}, r.vec(-0.2, 0.2),
                               r.vec(-0.3, 0.3), -r.uniform(0.3, 1.0)};
    }, true, 15);
}

TEST(Primitives, Superellipsoid) {
    check_shape([](Random& r) { return scene::Superellipsoid{r.uniform(0.2, 2.0), r.uniform(0.2, 2.0)}; }, true,
                16, 1e-8);
}

// Exponents above 2 make thin concave spikes along the axes, and a ray passing near one crosses the surface over a
// chord shorter than even sampling steps (objects/superel3.pov lost pixels of its silhouettes so). Every ray of
// that scene's superellipsoid { <0.3, 3> scale 2 rotate <-15, 30, 0> translate <10, 10, 0> } over its pixels of
// a 120x90 orthographic view that dips clearly below zero when sampled densely must hit, and no other.
TEST(Primitives, SuperellipsoidFindsThinSpikes) {
    const auto shape = SuperellipsoidShape::create(scene::Superellipsoid{0.3, 3.0});
    ASSERT_TRUE(shape);
    const Transform to_world = Transform::scaling({2, 2, 2})
                                   .then(Transform::rotation({-15, 30, 0}))
                                   .then(Transform::translation({10, 10, 0}));
    int dipping = 0;
    for (int py = 0; py < 21; ++py) {
        for (int px = 85; px < 106; ++px) {
            const Vec3 origin{-50.0 / 3.0 + (px + 0.5) / 120.0 * 100.0 / 3.0, 12.5 - (py + 0.5) / 90.0 * 25.0, -10.0};
            const LocalRay ray{to_world.inverse_point(origin), to_world.inverse_vector({0, 0, 1})};
            double lowest = 1e9;
            for (int k = 0; k <= 10000; ++k) lowest = std::fmin(lowest, shape->implicit(ray.origin + (k * 2e-3) * ray.direction));
            const std::size_t hits = shape->intersect_all(ray, 0.0, 20.0).size();
            if (lowest < -1e-3) {
                ++dipping;
                EXPECT_GE(hits, 2u) << "pixel " << px << ", " << py << " dips to " << lowest;
            } else if (lowest > 1e-3) {
                EXPECT_EQ(hits, 0u) << "pixel " << px << ", " << py;
            }
        }
    }
    EXPECT_GT(dipping, 20);
}

// The sampling with glibc's vector pow (four points at a time, within a few ulp) finds the crossings the scalar
// sampling finds, at the same places: random rays through random superellipsoids, from spiky to boxy.
TEST(Primitives, SuperellipsoidVectorSamplingFindsWhatScalarSamplingFinds) {
    if (!SuperellipsoidShape::use_vector_pow(true)) GTEST_SKIP() << "no AVX2 or no libmvec: only the scalar sampling";
    Random r(2718);
    int crossings = 0;
    for (int shape_index = 0; shape_index < 40; ++shape_index) {
        const auto shape = SuperellipsoidShape::create(scene::Superellipsoid{r.uniform(0.1, 3.0), r.uniform(0.1, 3.0)});
        ASSERT_TRUE(shape);
        for (int k = 0; k < 200; ++k) {
            // From anywhere around it towards a point of its box: most rays cross the surface.
            const Vec3 origin = r.vec(-3.0, 3.0);
            const LocalRay ray{origin, r.vec(-0.8, 0.8) - origin};
            SuperellipsoidShape::use_vector_pow(false);
            const SurfaceHits scalar = shape->intersect_all(ray, 0.0, 10.0);
            SuperellipsoidShape::use_vector_pow(true);
            const SurfaceHits vector = shape->intersect_all(ray, 0.0, 10.0);
            ASSERT_EQ(vector.size(), scalar.size()) << "shape " << shape_index << ", ray " << k;
            for (std::size_t i = 0; i < scalar.size(); ++i) {
                EXPECT_NEAR(vector[i].t, scalar[i].t, 1e-12 * (1.0 + scalar[i].t));
                EXPECT_EQ(vector[i].entering, scalar[i].entering);
            }
            crossings += static_cast<int>(scalar.size());
        }
    }
    EXPECT_GT(crossings, 8000);
}

// A closed tetrahedron with outward faces and an inside_vector, as a mesh.
scene::Mesh tetrahedron(Random& r) {
    scene::Mesh m;
    m.vertices = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
    for (Vec3& v : m.vertices) v = v + r.vec(-0.2, 0.2);
    // Orient each face so that its normal, (p3 - p1) x (p2 - p1) as in POV-Ray, points away from the opposite vertex.
    const int faces[4][3] = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
    for (int f = 0; f < 4; ++f) {
        scene::Mesh::Face face;
        face.v = {faces[f][0], faces[f][1], faces[f][2]};
        const int opposite = 6 - faces[f][0] - faces[f][1] - faces[f][2];
        const Vec3 n = cross(m.vertices[face.v[1]] - m.vertices[face.v[0]], m.vertices[face.v[2]] - m.vertices[face.v[0]]);
        if (dot(n, m.vertices[opposite] - m.vertices[face.v[0]]) < 0) std::swap(face.v[1], face.v[2]);
        m.faces.push_back(face);
    }
    m.inside_vector = {0.3, 0.7, 0.1};
    return m;
}

TEST(Primitives, ClosedMeshWithInsideVector) { check_shape(tetrahedron, true, 17); }

// A random star-shaped outline (closed by repeating its first point), with a square hole half of the time.
scene::Prism random_prism(Random& r) {
    scene::Prism p;
    p.conic = r.chance(0.4);
    p.height1 = p.conic ? r.uniform(0.2, 0.5) : r.uniform(-1.0, 0.0);
    p.height2 = p.conic ? r.uniform(0.8, 1.2) : r.uniform(0.3, 1.0);
    const int n = r.integer(3, 9);
    for (int i = 0; i < n; ++i) {
        const double a = 2 * M_PI * i / n;
        const double radius = (i % 2 == 0 ? 1.0 : 0.6) * r.uniform(0.8, 1.2);
        p.points.push_back({radius * std::cos(a), radius * std::sin(a), 0});
    }
    p.points.push_back(p.points.front());
    if (r.chance(0.5)) {
        for (Vec3 q : {Vec3{-0.2, -0.2, 0}, Vec3{0.2, -0.2, 0}, Vec3{0.2, 0.2, 0}, Vec3{-0.2, 0.2, 0}, Vec3{-0.2, -0.2, 0}})
            p.points.push_back(q);
    }
    return p;
}

TEST(Primitives, PrismLinearAndConic) { check_shape(random_prism, true, 19); }

TEST(Primitives, PrismInsideFollowsTheOutline) {
    scene::Prism p;
    p.height1 = 0;
    p.height2 = 1;
    p.points = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}, {0, 0, 0},
                {0.5, 0.5, 0}, {1.5, 0.5, 0}, {1.5, 1.5, 0}, {0.5, 1.5, 0}, {0.5, 0.5, 0}};
    const auto inst = ShapeInstance::create(make_object(p), 0);
    ASSERT_TRUE(inst);
    EXPECT_TRUE(inst->inside({0.25, 0.5, 0.25}));
    EXPECT_FALSE(inst->inside({1.0, 0.5, 1.0}));  // the hole
    EXPECT_FALSE(inst->inside({0.25, 1.5, 0.25}));  // above
    // Straight down onto the top cap (outline v is z).
    const auto h = inst->nearest({0.25, 5, 0.25}, {0, -1, 0}, 0.0, 1e30);
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 4.0, 1e-12);
    EXPECT_NEAR(h->normal.y, 1.0, 1e-12);
}

TEST(Primitives, PrismLinearRayLevelWithTheCapMeetsTheWalls) {
    // POV-Ray compat: interior/atten2.pov's prism, scaled by 12 and moved up by 30, whose top cap lies at y = 36, the
    // height of the centres of pixel row 4 at 120x90 under its orthographic camera. POV-Ray's walls include both
    // heights, so a level ray in the cap's plane crosses the walls (in and out); a hair above, it misses.
    scene::Prism p;
    p.height1 = -0.5;
    p.height2 = 0.5;
    p.points = {{-1, -0.3, 0}, {1, 0, 0}, {-1, 0.3, 0}, {-1, -0.3, 0}};
    const Transform xf = Transform::scaling({12, 12, 12}).then(Transform::translation({-15, 30, 0}));
    const auto inst = ShapeInstance::create(make_object(p, xf), 0);
    ASSERT_TRUE(inst);
    const SurfaceHits level = inst->intersect_all({-15, 36, -100}, {0, 0, 1}, 0.0, 1e30);
    ASSERT_EQ(level.size(), 2u);
    EXPECT_TRUE(level[0].entering);
    EXPECT_FALSE(level[1].entering);
    EXPECT_NEAR(level[0].t, 100 - 0.15 * 12, 1e-9);
    EXPECT_NEAR(level[1].t, 100 + 0.15 * 12, 1e-9);
    EXPECT_EQ(inst->intersect_all({-15, 24, -100}, {0, 0, 1}, 0.0, 1e30).size(), 2u);  // level with the base
    EXPECT_TRUE(inst->intersect_all({-15, std::nextafter(36.0, 40.0), -100}, {0, 0, 1}, 0.0, 1e30).empty());
    // POV-Ray compat (Prism::Inside): the base belongs to the inside, the top cap does not.
    const auto unit = ShapeInstance::create(make_object(p), 0);
    ASSERT_TRUE(unit);
    EXPECT_TRUE(unit->inside({0, -0.5, 0.05}));
    EXPECT_TRUE(unit->inside({0, 0.25, 0.05}));
    EXPECT_FALSE(unit->inside({0, 0.5, 0.05}));
}

TEST(Primitives, PrismLinearUnclosedOutlineIsClosed) {
    // POV-Ray compat (Parse_Prism): a linear outline that does not end on its first point is closed.
    scene::Prism p;
    p.height1 = 0;
    p.height2 = 1;
    p.points = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}};
    const auto inst = ShapeInstance::create(make_object(p), 0);
    ASSERT_TRUE(inst);
    const SurfaceHits hits = inst->intersect_all({-1, 0.5, 1}, {1, 0, 0}, 0.0, 1e30);
    ASSERT_EQ(hits.size(), 2u);
    EXPECT_NEAR(hits[0].t, 1.0, 1e-12);  // the closing wall at x = 0
    EXPECT_NEAR(hits[0].normal.x, -1.0, 1e-12);
    EXPECT_NEAR(hits[1].t, 3.0, 1e-12);
}

// A round outline through (±1, 0) and (0, ±1) in each spline type (control points as POV-Ray expects them).
scene::Prism spline_prism(scene::Prism::Spline spline, bool conic) {
    using Spline = scene::Prism::Spline;
    scene::Prism p;
    p.spline = spline;
    p.conic = conic;
    p.height1 = conic ? 0.5 : 0.0;
    p.height2 = 1.0;
    if (spline == Spline::Quadratic)
        p.points = {{0.8, -0.8, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}, {1, 0, 0}, {0, 1, 0}};
    else if (spline == Spline::Cubic)
        p.points = {{0, -1, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}};
    else
        p.points = {{1, 0, 0},  {1, 0.55, 0},   {0.55, 1, 0},  {0, 1, 0},  {0, 1, 0},   {-0.55, 1, 0},
                    {-1, 0.55, 0}, {-1, 0, 0},   {-1, 0, 0},    {-1, -0.55, 0}, {-0.55, -1, 0}, {0, -1, 0},
                    {0, -1, 0},  {0.55, -1, 0}, {1, -0.55, 0}, {1, 0, 0}};
    return p;
}

TEST(Primitives, PrismSplinesRandomRays) {
    using Spline = scene::Prism::Spline;
    std::uint64_t seed = 61;
    for (const Spline s : {Spline::Quadratic, Spline::Cubic, Spline::Bezier})
        for (const bool conic : {false, true})
            check_shape([=](Random&) { return spline_prism(s, conic); }, true, seed++, 1e-9, 10, 80);
}

TEST(Primitives, PrismSplineSubPolygonCutsAHole) {
    // A cubic outline of radius 1 with a second cubic sub-polygon of radius 0.3 inside it: the even-odd rule
    // makes the inner one a hole through both caps.
    scene::Prism p;
    p.spline = scene::Prism::Spline::Cubic;
    p.height1 = 0;
    p.height2 = 0.5;
    // Each sub-polygon: a control point, the curve points back to the first, a control point.
    p.points = {{0, -1, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}, {1, 0, 0}, {0, 1, 0},
                {0, -0.3, 0}, {0.3, 0, 0}, {0, 0.3, 0}, {-0.3, 0, 0}, {0, -0.3, 0}, {0.3, 0, 0}, {0, 0.3, 0}};
    const auto inst = ShapeInstance::create(make_object(p), 0);
    ASSERT_TRUE(inst);
    EXPECT_FALSE(inst->nearest({0, 5, 0}, {0, -1, 0}, 0.0, 1e30));  // down the hole
    const auto cap = inst->nearest({0.6, 5, 0}, {0, -1, 0}, 0.0, 1e30);
    ASSERT_TRUE(cap);
    EXPECT_NEAR(cap->t, 4.5, 1e-12);
    EXPECT_NEAR(cap->normal.y, 1.0, 1e-12);
    // Along x at mid-height: outer wall, hole wall, hole wall, outer wall.
    const SurfaceHits hits = inst->intersect_all({-5, 0.25, 0}, {1, 0, 0}, 0.0, 1e30);
    ASSERT_EQ(hits.size(), 4u);
    EXPECT_NEAR(hits[1].t, 5 - 0.3, 1e-9);
    EXPECT_FALSE(hits[1].entering);
    EXPECT_NEAR(hits[1].normal.x, 1.0, 1e-9);  // out of the solid, into the hole
    EXPECT_FALSE(inst->inside({0, 0.25, 0}));
    EXPECT_TRUE(inst->inside({0.6, 0.25, 0}));
}

TEST(Primitives, PrismSplinesRunThroughTheirPointsWithCurveNormals) {
    using Spline = scene::Prism::Spline;
    for (const Spline s : {Spline::Quadratic, Spline::Cubic, Spline::Bezier}) {
        const auto inst = ShapeInstance::create(make_object(spline_prism(s, false)), 0);
        ASSERT_TRUE(inst);
        // Along x at mid-height the wall is met at the curve point (-1, 0) with a normal along -x.
        const auto hit = inst->nearest({-5, 0.5, 0}, {1, 0, 0}, 0.0, 1e30);
        ASSERT_TRUE(hit);
        EXPECT_NEAR(hit->position.x, -1.0, 1e-9);
        // POV-Ray's quadratic outline has a kink at its points; the others are smooth there.
        if (s != Spline::Quadratic) {
            EXPECT_NEAR(hit->normal.x, -1.0, 1e-3);
        }
        EXPECT_TRUE(inst->inside({0, 0.5, 0}));
        EXPECT_FALSE(inst->inside({0.8, 0.5, 0.8}));
    }
}

TEST(Primitives, PolygonWithHoleByEvenOddRule) {
    // A 2 x 2 square with a 1 x 1 square hole: POV-Ray's sub-polygons close when their first point repeats.
    scene::Polygon poly;
    poly.points = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}, {0, 0, 0},
                   {0.5, 0.5, 0}, {1.5, 0.5, 0}, {1.5, 1.5, 0}, {0.5, 1.5, 0}, {0.5, 0.5, 0}};
    const auto inst = ShapeInstance::create(make_object(poly), 0);
    ASSERT_TRUE(inst);
    auto hit_at = [&](double x, double y) { return inst->nearest({x, y, -5}, {0, 0, 1}, 0.0, 1e30).has_value(); };
    EXPECT_TRUE(hit_at(0.25, 0.25));
    EXPECT_TRUE(hit_at(1.75, 1.0));
    EXPECT_FALSE(hit_at(1.0, 1.0));  // in the hole
    EXPECT_FALSE(hit_at(2.5, 1.0));  // outside
    const auto h = inst->nearest({0.2, 0.3, -5}, {0, 0, 1}, 0.0, 1e30);
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 5.0, 1e-12);
}

TEST(Primitives, SmoothTriangleInterpolatesNormals) {
    scene::Mesh m;
    m.kind = scene::Mesh::Kind::SmoothTriangle;
    m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    m.normals = {{-1, 0, 1}, {1, 0, 1}, {0, 1, 1}};
    scene::Mesh::Face f;
    f.v = {0, 1, 2};
    f.n = {0, 1, 2};
    m.faces.push_back(f);
    const auto inst = ShapeInstance::create(make_object(m), 0);
    ASSERT_TRUE(inst);
    const auto near0 = inst->nearest({0.01, 0.01, -1}, {0, 0, 1}, 0.0, 1e30);
    ASSERT_TRUE(near0);
    EXPECT_LT(near0->normal.x, -0.6);  // close to vertex 0's normal
    const auto near1 = inst->nearest({0.98, 0.01, -1}, {0, 0, 1}, 0.0, 1e30);
    ASSERT_TRUE(near1);
    EXPECT_GT(near1->normal.x, 0.6);
}

// POV-Ray's side of a flat face: a triangle's normal is (p3 - p1) x (p2 - p1) and a polygon's its points' Newell
// normal, whichever side the ray comes from (trace() returns them so, and interior_texture follows them); a smooth
// triangle's interpolated normal is kept as given even where it faces away from the geometric one. Measured with
// POV-Ray 3.7's trace() on the same shapes.
TEST(Primitives, FlatFaceNormalsFollowPovRaysVertexOrder) {
    scene::Mesh tri;
    tri.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 0, 1}};
    scene::Mesh::Face f;
    f.v = {0, 1, 2};
    tri.faces.push_back(f);
    scene::Mesh reversed = tri;
    reversed.faces[0].v = {0, 2, 1};
    scene::Polygon poly;
    poly.points = {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}};
    scene::Mesh smooth = tri;
    smooth.kind = scene::Mesh::Kind::SmoothTriangle;
    smooth.normals = {{0.1, -1, 0}, {0.1, -1, 0}, {0.1, -1, 0}};
    smooth.faces[0].n = {0, 1, 2};
    const struct {
        scene::Shape shape;
        double normal_y;
    } cases[] = {{tri, 1.0}, {reversed, -1.0}, {poly, -1.0}, {smooth, -1.0}};
    for (const auto& c : cases) {
        const auto inst = ShapeInstance::create(make_object(c.shape), 0);
        ASSERT_TRUE(inst);
        for (const double side : {1.0, -1.0}) {
            const auto hit = inst->nearest({0.2, side, 0.2}, {0, -side, 0}, 0.0, 1e30);
            ASSERT_TRUE(hit);
            EXPECT_NEAR(normalize(hit->normal).y, c.normal_y, 0.01) << "from y = " << side;
        }
    }
}

TEST(Primitives, CylinderCapsAndOpen) {
    const scene::Cylinder closed{{0, 0, 0}, {0, 2, 0}, 1.0, false};
    scene::Cylinder open = closed;
    open.open = true;
    const auto a = ShapeInstance::create(make_object(closed), 0);
    const auto b = ShapeInstance::create(make_object(open), 0);
    ASSERT_TRUE(a && b);
    // Straight down the axis: the closed one is hit on its top cap, the open one not at all.
    const auto h = a->nearest({0, 5, 0}, {0, -1, 0}, 0.0, 1e30);
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 3.0, 1e-12);
    EXPECT_NEAR(h->normal.y, 1.0, 1e-12);
    EXPECT_FALSE(b->nearest({0, 5, 0}, {0, -1, 0}, 0.0, 1e30));
    // Open cylinders stay solid for inside tests.
    EXPECT_TRUE(b->inside({0, 1, 0}));
    // POV-Ray compat: their end planes and side count as inside (EPSILON beyond them); a closed one's do not.
    EXPECT_TRUE(b->inside({0.5, 2.0, 0}));
    EXPECT_TRUE(b->inside({0.5, 0.0, 0}));
    EXPECT_TRUE(b->inside({1.0, 1.0, 0}));
    EXPECT_FALSE(b->inside({0.5, 2.0 + 1e-6, 0}));
    EXPECT_FALSE(b->inside({1.0 + 1e-6, 1.0, 0}));
    EXPECT_FALSE(a->inside({0.5, 2.0, 0}));
    EXPECT_FALSE(a->inside({0.5, 0.0, 0}));
}

TEST(Primitives, ABowlCutByAnOpenConeKeepsNoLid) {
    // A cone with an open cone of the same height taken away (a user's bowl): the solid cone's top cap lies on
    // the open cone's end plane, so it is inside the open cone and goes; a ray down the axis meets the bowl's
    // floor only where the open cone does not reach, i.e. not at all here.
    scene::Cone outer{{0, 0, 0}, 1.5, {0, 1.75, 0}, 2.0, false};
    scene::Cone inner{{0, 0, 0}, 1.4, {0, 1.75, 0}, 1.95, true};
    const auto o = ShapeInstance::create(make_object(outer), 0);
    const auto i = ShapeInstance::create(make_object(inner), 0);
    ASSERT_TRUE(o && i);
    EXPECT_TRUE(i->inside({0.5, 1.75, 0}));   // the solid's top cap, on the open end's plane
    EXPECT_TRUE(i->inside({0.5, 0.0, 0}));    // its bottom cap likewise
    EXPECT_FALSE(i->inside({1.45, 0.0, 0}));  // the rim between the radii stays
    EXPECT_FALSE(o->inside({0.5, 1.75, 0}));
}

TEST(Primitives, TorusFourCrossingsAlongItsDiameter) {
    const auto inst = ShapeInstance::create(make_object(scene::Torus{2.0, 0.5}), 0);
    ASSERT_TRUE(inst);
    const SurfaceHits hits = inst->intersect_all({-10, 0, 0}, {1, 0, 0}, 0.0, 1e30);
    ASSERT_EQ(hits.size(), 4u);
    const double want[4] = {7.5, 8.5, 11.5, 12.5};
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(hits[i].t, want[i], 1e-12);
    // A far origin keeps the precision (the quartic is solved from the point nearest the centre).
    const SurfaceHits far = inst->intersect_all({-1e6, 0, 0}, {1, 0, 0}, 0.0, 1e30);
    ASSERT_EQ(far.size(), 4u);
    EXPECT_NEAR(far[0].t, 1e6 - 2.5, 1e-7);
}

// POV-Ray's torus written as a general quartic: (x² + y² + z² + R² - r²)² - 4R²(x² + z²).
scene::Quartic torus_quartic(double major, double minor) {
    scene::Quartic q;
    const double k = major * major - minor * minor;
    auto& c = q.coefficients;
    c[0] = 1;                                 // x⁴
    c[4] = 2;                                 // x²y²
    c[7] = 2;                                 // x²z²
    c[9] = 2 * k - 4 * major * major;         // x²
    c[20] = 1;                                // y⁴
    c[23] = 2;                                // y²z²
    c[25] = 2 * k;                            // y²
    c[30] = 1;                                // z⁴
    c[32] = 2 * k - 4 * major * major;        // z²
    c[34] = k * k;                            // 1
    return q;
}

TEST(Primitives, QuarticMatchesTheTorus) {
    Random rng(18);
    for (int trial = 0; trial < 300; ++trial) {
        const double major = rng.uniform(0.5, 1.5), minor = rng.uniform(0.1, 0.4);
        const Transform xf = rng.transform();
        // Sturm sequences: POV-Ray's closed-form quartic loses digits.
        scene::Quartic quartic = torus_quartic(major, minor);
        quartic.sturm = true;
        const auto q = ShapeInstance::create(make_object(quartic, xf), 0);
        const auto t = ShapeInstance::create(make_object(scene::Torus{major, minor}, xf), 0);
        ASSERT_TRUE(q && t);
        const Vec3 target = xf.point(rng.vec(-1, 1));
        const Vec3 origin = target + rng.direction() * rng.uniform(1.0, 20.0);
        const Vec3 dir = (target - origin) * rng.uniform(0.1, 10.0);
        const SurfaceHits hq = q->intersect_all(origin, dir, 0.0, 1e30);
        const SurfaceHits ht = t->intersect_all(origin, dir, 0.0, 1e30);
        ASSERT_EQ(hq.size(), ht.size()) << "trial " << trial;
        for (std::size_t i = 0; i < hq.size(); ++i) {
            EXPECT_NEAR(hq[i].t, ht[i].t, 1e-9 * ht[i].t);
            EXPECT_NEAR(dot(hq[i].normal, ht[i].normal), 1.0, 1e-9);
        }
        EXPECT_EQ(q->inside(target), t->inside(target));
    }
}

TEST(Primitives, ThinTorusKeepsEveryCrossingOfRaysNearItsTube) {
    // A ring as thin as patio-radio's arches (r/R = 2/130): rays aimed close to the tube, from every side, cross
    // it where the general quartic says, so the torus's quick miss test drops no crossing.
    Random rng(19);
    int crossed = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        const double major = 1.0, minor = rng.uniform(0.008, 0.03);
        const Transform xf = rng.transform();
        const auto q = ShapeInstance::create(make_object(torus_quartic(major, minor), xf), 0);
        const auto t = ShapeInstance::create(make_object(scene::Torus{major, minor}, xf), 0);
        ASSERT_TRUE(q && t);
        // A point within a few tube radii of the ring's centre circle.
        const double a = rng.uniform(0.0, 2.0 * M_PI);
        const Vec3 on_ring{major * std::cos(a), 0.0, major * std::sin(a)};
        const Vec3 target = xf.point(on_ring + rng.direction() * (minor * rng.uniform(0.0, 3.0)));
        const Vec3 origin = target + rng.direction() * rng.uniform(0.5, 20.0);
        const Vec3 dir = (target - origin) * rng.uniform(0.1, 10.0);
        const SurfaceHits hq = q->intersect_all(origin, dir, 0.0, 1e30);
        const SurfaceHits ht = t->intersect_all(origin, dir, 0.0, 1e30);
        ASSERT_EQ(hq.size(), ht.size()) << "trial " << trial;
        for (std::size_t i = 0; i < hq.size(); ++i) EXPECT_NEAR(hq[i].t, ht[i].t, 1e-7 * (1.0 + ht[i].t));
        crossed += !ht.empty();
    }
    // Both kinds of ray occur: those that cross the tube and those that pass it by.
    EXPECT_GT(crossed, 300);
    EXPECT_LT(crossed, 1700);
}

TEST(Primitives, TorusSearchesOnlyAheadOfTheRayAndStopsAtItsNearestCrossing) {
    // Gather and shadow rays start on a surface with t_min a small offset, most of the chord through the torus's
    // bounding sphere behind them: the torus searches only the stretch within (t_min, t_max), and nearest() and
    // crosses() stop at the first crossing. Their answers are those of the search over the whole chord (t_min far
    // behind the origin) kept beyond t_min, also for rays that leave the tube's own surface.
    Random rng(20);
    int from_surface = 0, hit = 0;
    for (int trial = 0; trial < 600; ++trial) {
        const double major = rng.uniform(0.5, 1.5), minor = rng.uniform(0.1, 0.4);
        const Transform xf = rng.transform();
        const auto t = ShapeInstance::create(make_object(scene::Torus{major, minor}, xf), 0);
        ASSERT_TRUE(t);
        Vec3 origin = xf.point(rng.vec(-2, 2));
        // Rays aimed near the ring, or (every other one) leaving a point of the tube's surface as a gather ray does.
        const double b = rng.uniform(0.0, 2.0 * M_PI);
        const Vec3 near_ring = xf.point(Vec3{major * std::cos(b), 0.0, major * std::sin(b)} + rng.vec(-0.5, 0.5));
        Vec3 dir = (near_ring - origin) * rng.uniform(0.1, 10.0);
        double t_min = 0.0;
        if (trial % 2 == 0) {
            dir = rng.direction() * rng.uniform(0.1, 10.0);
            const double a = rng.uniform(0.0, 2.0 * M_PI);
            const Vec3 towards = xf.point(Vec3{major * std::cos(a), 0.0, major * std::sin(a)}) - origin;
            const SurfaceHits first = t->intersect_all(origin, towards, 0.0, 1e30);
            if (!first.empty()) {
                origin = origin + first[0].t * towards;
                if (dot(dir, first[0].normal) < 0.0) dir = -dir;
                t_min = 1e-6 / length(dir);
                ++from_surface;
            }
        }
        const SurfaceHits whole = t->intersect_all(origin, dir, -1e30, 1e30);
        std::vector<double> ahead;
        for (const SurfaceHit& h : whole)
            if (h.t > t_min) ahead.push_back(h.t);
        const SurfaceHits ht = t->intersect_all(origin, dir, t_min, 1e30);
        ASSERT_EQ(ht.size(), ahead.size()) << "trial " << trial;
        for (std::size_t i = 0; i < ht.size(); ++i) EXPECT_NEAR(ht[i].t, ahead[i], 1e-12 * (1.0 + ahead[i]));
        const std::optional<Hit> nearest = t->nearest(origin, dir, t_min, 1e30);
        ASSERT_EQ(nearest.has_value(), !ht.empty()) << "trial " << trial;
        EXPECT_EQ(t->crosses(origin, dir, t_min, 1e30), !ht.empty()) << "trial " << trial;
        if (nearest) {
            ++hit;
            EXPECT_EQ(nearest->t, ht[0].t) << "trial " << trial;
            EXPECT_NEAR(dot(nearest->normal, ht[0].normal), 1.0, 1e-12);
            // A shadow ray ending just short of the first crossing does not cross.
            EXPECT_FALSE(t->crosses(origin, dir, t_min, ht[0].t * (1.0 - 1e-9))) << "trial " << trial;
        }
    }
    EXPECT_GT(from_surface, 250);
    EXPECT_GT(hit, 150);
}

}  // namespace
}  // namespace wardray::geometry
