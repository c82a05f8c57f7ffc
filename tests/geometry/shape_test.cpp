// Tests of the primitive shapes through ShapeInstance: hits on the surface, outward unit normals, POV-Ray semantics.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>
#include <string_view>

#include "geometry/instance.h"
#include "parser/keywords.h"
#include "parser/parse.h"
#include "test_util.h"

namespace wardray::geometry {
namespace {

using test::make_object;
using test::Random;

// Checks every crossing of random rays against one random object: on the surface, unit outward normal,
// entering flags that match the normal and the inside test.
void check_random_hits(bool inverse, int shape_kind_seed) {
    Random rng(1234 + shape_kind_seed + (inverse ? 1000 : 0));
    int checked = 0;
    for (int trial = 0; trial < 300; ++trial) {
        scene::Object obj = make_object(test::random_shape(rng, true), rng.transform());
        obj.inverse = inverse;
        const auto inst = ShapeInstance::create(obj, 7);
        ASSERT_TRUE(inst.has_value());
        const double scale = test::object_scale(*inst);
        const test::AimedRay ray = test::aim_random_ray(rng, obj, 1.0);
        const SurfaceHits hits = inst->intersect_all(ray.origin, ray.direction, 0.0, 1e30);
        for (std::size_t i = 0; i < hits.size(); ++i) {
            const SurfaceHit& h = hits[i];
            const Vec3 p = ray.origin + h.t * ray.direction;
            test::expect_valid_crossing(*inst, hits, i, ray, 1e-10);
            // Outward (after inverse): a small step along the normal is outside, against it inside.
            const double eps = 1e-6 * scale;
            EXPECT_FALSE(inst->inside(p + eps * h.normal)) << "trial " << trial;
            EXPECT_TRUE(inst->inside(p - eps * h.normal)) << "trial " << trial;
            ++checked;
        }
        // The nearest hit agrees with the first crossing, to the bit; shadow rays see a crossing exactly then.
        const auto nearest = inst->nearest(ray.origin, ray.direction, 0.0, 1e30);
        ASSERT_EQ(nearest.has_value(), !hits.empty());
        EXPECT_EQ(inst->crosses(ray.origin, ray.direction, 0.0, 1e30), !hits.empty());
        if (nearest) {
            EXPECT_EQ(nearest->t, hits[0].t);
            EXPECT_EQ(nearest->normal, hits[0].normal);
            EXPECT_EQ(nearest->object, 7u);
        }
    }
    EXPECT_GT(checked, 150);
}

TEST(Shapes, RandomRaysHitSurfaceWithOutwardUnitNormals) {
    for (int seed = 0; seed < 3; ++seed) check_random_hits(false, seed);
}

TEST(Shapes, InverseFlipsNormalsAndInside) {
    for (int seed = 0; seed < 3; ++seed) check_random_hits(true, seed);
}

// sort_by_t is stable with few crossings (held inline) and with many (on the heap): equal t keep their order.
TEST(Shapes, SurfaceHitsSortIsStable) {
    for (const std::size_t n : {std::size_t{5}, SurfaceHits::inline_capacity + 4}) {
        SurfaceHits hits;
        for (std::size_t i = 0; i < n; ++i) hits.push({static_cast<double>((n - i) / 2), Vec3{double(i), 0, 0}});
        hits.sort_by_t();
        ASSERT_EQ(hits.size(), n);
        for (std::size_t i = 1; i < n; ++i) {
            EXPECT_LE(hits[i - 1].t, hits[i].t);
            if (hits[i - 1].t == hits[i].t) {
                EXPECT_LT(hits[i - 1].normal.x, hits[i].normal.x);
            }
        }
        const SurfaceHits copy = hits;
        for (std::size_t i = 0; i < n; ++i) EXPECT_EQ(copy[i].normal.x, hits[i].normal.x);
    }
}

TEST(Shapes, InverseSphereNormalPointsTowardCentre) {
    scene::Object obj = make_object(scene::Sphere{{0, 0, 0}, 2.0});
    obj.inverse = true;
    const auto inst = ShapeInstance::create(obj, 0);
    ASSERT_TRUE(inst);
    const auto hit = inst->nearest({0, 0, -10}, {0, 0, 1}, 0.0, 1e30);
    ASSERT_TRUE(hit);
    EXPECT_DOUBLE_EQ(hit->t, 8.0);
    EXPECT_DOUBLE_EQ(hit->normal.z, 1.0);
    EXPECT_FALSE(inst->inside({0, 0, 0}));
    EXPECT_TRUE(inst->inside({0, 0, 5}));
}

TEST(Shapes, PlaneDistanceIsAlongUnitNormal) {
    // POV-Ray compat (checked with povray 3.7): plane { <0,2,0>, 1 } is the plane y = 1, inside below.
    const auto inst = ShapeInstance::create(make_object(scene::Plane{{0, 2, 0}, 1.0}), 0);
    ASSERT_TRUE(inst);
    const auto hit = inst->nearest({3, 5, -2}, {0, -1, 0}, 0.0, 1e30);
    ASSERT_TRUE(hit);
    EXPECT_DOUBLE_EQ(hit->position.y, 1.0);
    EXPECT_DOUBLE_EQ(hit->normal.y, 1.0);
    EXPECT_TRUE(inst->inside({0, 0.9, 0}));
    EXPECT_FALSE(inst->inside({0, 1.1, 0}));
    // A ray from below crosses going out, a ray in the plane's direction never hits.
    const auto hits = inst->intersect_all({0, 0, 0}, {0, 1, 0}, 0.0, 1e30);
    ASSERT_EQ(hits.size(), 1u);
    EXPECT_FALSE(hits[0].entering);
    EXPECT_TRUE(inst->intersect_all({0, 1, 0}, {1, 0, 0}, -1e30, 1e30).empty());
}

TEST(Shapes, TiltedPlaneSurface) {
    const auto inst = ShapeInstance::create(make_object(scene::Plane{{1, 1, 0}, 2.0}), 0);
    ASSERT_TRUE(inst);
    const auto hit = inst->nearest({0, 0, 0}, {1, 0, 0}, 0.0, 1e30);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->position.x, 2.0 * std::sqrt(2.0), 1e-14);
    EXPECT_NEAR(hit->normal.x, std::sqrt(0.5), 1e-15);
}

TEST(Shapes, BoxCornersInAnyOrder) {
    // POV-Ray compat (checked with povray 3.7): box { <1,-1,1>, <-1,1,-1> } renders as the box from -1 to 1.
    const auto a = ShapeInstance::create(make_object(scene::Box{{1, -1, 1}, {-1, 1, -1}}), 0);
    const auto b = ShapeInstance::create(make_object(scene::Box{{-1, -1, -1}, {1, 1, 1}}), 0);
    ASSERT_TRUE(a && b);
    Random rng(5);
    for (int i = 0; i < 100; ++i) {
        const Vec3 o = rng.vec(-4, 4);
        const Vec3 d = rng.direction();
        const auto ha = a->nearest(o, d, 0.0, 1e30);
        const auto hb = b->nearest(o, d, 0.0, 1e30);
        ASSERT_EQ(ha.has_value(), hb.has_value());
        if (ha) {
            EXPECT_EQ(ha->t, hb->t);
            EXPECT_EQ(ha->normal, hb->normal);
        }
    }
}

TEST(Shapes, NegativeRadiusActsLikeItsAbsoluteValue) {
    // POV-Ray compat (checked with povray 3.7): sphere { 0, -1 } renders like sphere { 0, 1 }.
    const auto inst = ShapeInstance::create(make_object(scene::Sphere{{0, 0, 0}, -1.0}), 0);
    ASSERT_TRUE(inst);
    const auto hit = inst->nearest({0, 0, -5}, {0, 0, 1}, 0.0, 1e30);
    ASSERT_TRUE(hit);
    EXPECT_DOUBLE_EQ(hit->t, 4.0);
    EXPECT_DOUBLE_EQ(hit->normal.z, -1.0);
}

TEST(Shapes, DegenerateObjectsAreRejected) {
    EXPECT_FALSE(ShapeInstance::create(make_object(scene::Sphere{{0, 0, 0}, 1.0}, Transform::scaling({1, 0, 1})), 0));
    EXPECT_FALSE(ShapeInstance::create(make_object(scene::Sphere{{0, 0, 0}, 0.0}), 0));
    EXPECT_FALSE(ShapeInstance::create(make_object(scene::Plane{{0, 0, 0}, 1.0}), 0));
    EXPECT_FALSE(ShapeInstance::create(make_object(scene::Box{{0, 0, 0}, {1, NAN, 1}}), 0));
    EXPECT_FALSE(ShapeInstance::create(make_object(scene::Sphere{{0, 0, 0}, INFINITY}), 0));
    EXPECT_FALSE(ShapeInstance::create(make_object(scene::Plane{{0, 1, 0}, 0.0}, Transform::scaling({0, 0, 0})), 0));
}

TEST(Shapes, SphereStableForDistantOrigins) {
    // The naive discriminant b^2 - a c loses every digit here; the stable form keeps the hit on the surface.
    Random rng(77);
    int hits = 0;
    for (int i = 0; i < 500; ++i) {
        const double r = rng.uniform(0.5, 2.0);
        const auto inst = ShapeInstance::create(make_object(scene::Sphere{{0, 0, 0}, r}), 0);
        const double dist = std::pow(10.0, rng.uniform(4.0, 9.0));
        const Vec3 origin = rng.direction() * dist;
        const Vec3 target = rng.vec(-r, r);
        const Vec3 dir = normalize(target - origin);
        const auto hit = inst->nearest(origin, dir, 0.0, 1e30);
        if (!hit) continue;
        ++hits;
        // Rounding of o + t d is about eps * dist; the surface error must not be larger than a few of those.
        EXPECT_NEAR(length(hit->position) - r, 0.0, 1e-14 * dist + 1e-13) << "dist " << dist;
        EXPECT_NEAR(dot(hit->normal, normalize(hit->position)), 1.0, 1e-9);
    }
    EXPECT_GT(hits, 300);
}

TEST(Shapes, GrazingRaysNeverGiveNaN) {
    Random rng(99);
    const auto sphere = ShapeInstance::create(make_object(scene::Sphere{{0, 0, 0}, 1.0}, rng.transform()), 0);
    const auto box = ShapeInstance::create(make_object(scene::Box{{-1, -1, -1}, {1, 1, 1}}), 1);
    const auto flat = ShapeInstance::create(make_object(scene::Box{{-1, 0, -1}, {1, 0, 1}}), 2);
    ASSERT_TRUE(sphere && box && flat);
    const auto check = [](const SurfaceHits& hits) {
        for (const SurfaceHit& h : hits) {
            EXPECT_TRUE(std::isfinite(h.t));
            EXPECT_TRUE(is_finite(h.normal));
        }
    };
    for (int i = 0; i < 2000; ++i) {
        // Tangent to the unit sphere (in object space) up to a relative 1e-12 either way.
        const Vec3 n = rng.direction();
        Vec3 tangent = normalize(cross(n, rng.direction()));
        const Vec3 p_obj = n * (1.0 + rng.uniform(-1e-12, 1e-12));
        const Vec3 o_obj = p_obj - 3.0 * tangent;
        check(sphere->intersect_all(sphere->transform().point(o_obj), sphere->transform().vector(tangent), 0.0, 1e30));
        // Along box faces and edges: origins exactly on a face plane, direction parallel to it.
        Vec3 o = rng.vec(-2, 2);
        Vec3 d = rng.direction();
        const int axis = rng.integer(0, 2);
        o[axis] = rng.chance(0.5) ? 1.0 : -1.0;
        d[axis] = 0.0;
        if (rng.chance(0.3)) {
            const int other = (axis + 1) % 3;
            o[other] = 1.0;
            d[other] = 0.0;
        }
        check(box->intersect_all(o, d, -1e30, 1e30));
        check(flat->intersect_all(o, d, -1e30, 1e30));
    }
}

TEST(Shapes, TransformedSphereBoundsAreTight) {
    Random rng(3);
    const scene::Object obj = make_object(scene::Sphere{{0.5, 0, 0}, 1.0}, rng.transform());
    const auto inst = ShapeInstance::create(obj, 0);
    ASSERT_TRUE(inst && inst->world_bounds());
    // Every surface point lies in the bounds, and the bounds are touched along each axis.
    const Bounds b = *inst->world_bounds();
    Vec3 lo{1e30, 1e30, 1e30};
    Vec3 hi{-1e30, -1e30, -1e30};
    for (int i = 0; i < 20000; ++i) {
        const Vec3 p = obj.transform.point(Vec3{0.5, 0, 0} + rng.direction());
        lo = min(lo, p);
        hi = max(hi, p);
    }
    for (int k = 0; k < 3; ++k) {
        EXPECT_LE(b.lower[k], lo[k]);
        EXPECT_GE(b.upper[k], hi[k]);
        EXPECT_NEAR(b.lower[k], lo[k], 0.05);
        EXPECT_NEAR(b.upper[k], hi[k], 0.05);
    }
}

// One small valid statement per keyword of WARDRAY_SHAPES (scene/shapes.h): a new shape adds its line here.
const std::map<std::string_view, std::string> k_shape_samples = {
    {"sphere", "sphere { 0, 1 }"},
    {"box", "box { -1, 1 }"},
    {"plane", "plane { y, 0 }"},
    {"cylinder", "cylinder { 0, y, 1 }"},
    {"cone", "cone { 0, 1, y, 0.5 }"},
    {"disc", "disc { 0, y, 1 }"},
    {"torus", "torus { 1, 0.25 }"},
    {"ovus", "ovus { 1, 0.5 }"},
    {"blob", "blob { threshold 0.5 sphere { 0, 1, 1 } }"},
    {"bicubic_patch", "bicubic_patch { type 1 u_steps 2 v_steps 2 <0,0,0>,<1,0,0>,<2,0,0>,<3,0,0>, <0,1,0>,<1,1,1>,"
                      "<2,1,1>,<3,1,0>, <0,2,0>,<1,2,1>,<2,2,1>,<3,2,0>, <0,3,0>,<1,3,0>,<2,3,0>,<3,3,0> }"},
    {"triangle", "triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 0> }"},
    {"smooth_triangle", "smooth_triangle { <0, 0, 0>, y, <1, 0, 0>, y, <0, 0, 1>, y }"},
    {"mesh", "mesh { triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 0> } }"},
    {"mesh2", "mesh2 { vertex_vectors { 3, <0, 0, 0>, <1, 0, 0>, <0, 1, 0> } face_indices { 1, <0, 1, 2> } }"},
    {"polygon", "polygon { 4, <0, 0>, <1, 0>, <0, 1>, <0, 0> }"},
    {"quadric", "quadric { <1, 1, 1>, <0, 0, 0>, <0, 0, 0>, -1 }"},
    {"superellipsoid", "superellipsoid { <1, 1> }"},
    {"quartic", "quartic { <0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, "
                "0, 0, 1, 0, -1> }"},
    {"cubic", "cubic { <0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, -1> }"},
    {"poly", "poly { 2, <1, 0, 0, 0, 1, 0, 0, 1, 0, -1> sturm }"},
    {"polynomial", "polynomial { 2, xyz(2, 0, 0): 1, xyz(0, 2, 0): 1, xyz(0, 0, 2): 1, xyz(0, 0, 0): -1 }"},
    {"julia_fractal", "julia_fractal { <-0.083, 0, -0.83, -0.025> quaternion sqr max_iteration 8 precision 15 }"},
    {"prism", "prism { linear_sweep 0, 1, 4, <0, 0>, <1, 0>, <0, 1>, <0, 0> }"},
    {"lathe", "lathe { linear_spline 3, <0, 0>, <1, 0.5>, <0, 1> }"},
    {"sor", "sor { 4, <0, 0>, <1, 0.25>, <1, 0.75>, <0, 1> }"},
    {"sphere_sweep", "sphere_sweep { b_spline 4, <0, 0, 0>, 0.2, <1, 0, 0>, 0.3, <1, 1, 0>, 0.2, 0, 0.1 tolerance 1e-3 }"},
    {"text", "text { ttf \"timrom.ttf\" \"A\", 0.5, 0 }"},
    {"isosurface", "isosurface { function { x*x + y*y + z*z - 1 } contained_by { sphere { 0, 2 } } }"},
    {"parametric", "parametric { function { u } function { v } function { 0 } <0, 0>, <1, 1> }"},
    {"height_field", "height_field { function 4, 3 { x + y } smooth water_level 0.1 }"},
};

// Parses one statement as a scene of one object.
std::optional<scene::Object> parse_single_object(const std::string& statement) {
    parser::ParseOptions options;
    options.library_paths = {"/usr/share/povray-3.7/include"};
    const parser::ParseResult r =
        parser::parse_string("global_settings { assumed_gamma 1 }\n" + statement, "list.pov", options);
    if (!r.ok() || !r.scene || r.scene->objects.size() != 1) return std::nullopt;
    return r.scene->objects.front();
}

// The shape list is consistent: each keyword is reserved, parses to its scene type, is named by it in --check,
// and builds a geometry.
TEST(ShapeList, EveryKeywordParsesToItsKindAndHasAGeometry) {
    int checked = 0;
#define WARDRAY_CHECK_SHAPE(keyword, Type)                                                                  \
    {                                                                                                       \
        SCOPED_TRACE(#keyword);                                                                             \
        EXPECT_TRUE(parser::is_keyword(#keyword));                                                          \
        const auto sample = k_shape_samples.find(#keyword);                                                 \
        ASSERT_NE(sample, k_shape_samples.end()) << "add a sample statement for the new shape";             \
        const auto object = parse_single_object(sample->second);                                            \
        ASSERT_TRUE(object.has_value());                                                                    \
        EXPECT_TRUE(std::holds_alternative<scene::Type>(object->shape));                                    \
        EXPECT_EQ(std::string_view(scene::shape_keyword(object->shape)), #keyword);                         \
        EXPECT_TRUE(ShapeInstance::create(*object, 0).has_value());                                         \
        ++checked;                                                                                          \
    }
    WARDRAY_SHAPES(WARDRAY_CHECK_SHAPE)
#undef WARDRAY_CHECK_SHAPE
    EXPECT_EQ(checked, static_cast<int>(scene::k_shape_keywords.size()));
    EXPECT_EQ(k_shape_samples.size(), scene::k_shape_keywords.size());
    // A keyword of the list is no user name.
    EXPECT_FALSE(parse_single_object("#declare torus = 1;\nsphere { 0, 1 }").has_value());
}

}  // namespace
}  // namespace wardray::geometry
