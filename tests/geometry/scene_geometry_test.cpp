// Tests of SceneGeometry: Embree's nearest hit against a brute-force double loop, ray kinds, shadows, scale invariance.
#include <gtest/gtest.h>

#include <cmath>
#include <thread>
#include <vector>

#include "geometry/instance.h"
#include "geometry/scene_geometry.h"
#include "test_util.h"

namespace wardray::geometry {
namespace {

using test::make_object;
using test::Random;

// A random scene of spheres and boxes (and optionally planes) with random transforms and flags.
scene::Scene random_scene(Random& rng, int count, bool planes, bool flags) {
    scene::Scene scene;
    for (int i = 0; i < count; ++i) {
        scene::Object o = make_object(test::random_shape(rng, false), rng.transform(20.0));
        if (flags) {
            o.inverse = rng.chance(0.1);
            o.no_image = rng.chance(0.15);
            o.no_reflection = rng.chance(0.15);
            o.no_shadow = rng.chance(0.15);
            o.no_radiosity = rng.chance(0.15);
        }
        scene.objects.push_back(o);
    }
    if (planes) {
        for (int i = 0; i < 3; ++i) {
            scene::Object o = make_object(scene::Plane{rng.direction(), rng.uniform(25.0, 40.0)}, rng.transform(3.0));
            o.inverse = flags && rng.chance(0.3);
            o.no_shadow = flags && rng.chance(0.3);
            o.no_image = flags && rng.chance(0.3);
            scene.objects.push_back(o);
        }
    }
    return scene;
}

// The nearest hit over all objects by a plain loop over their double-precision intersections.
std::optional<Hit> brute_force(const scene::Scene& scene, const Ray& ray) {
    std::optional<Hit> best;
    for (std::uint32_t i = 0; i < scene.objects.size(); ++i) {
        const auto inst = ShapeInstance::create(scene.objects[i], i);
        if (!inst || !inst->visible_to(ray.kind)) continue;
        const auto hit = inst->nearest(ray.origin, ray.direction, ray.t_min, best ? best->t : ray.t_max);
        if (hit) best = hit;
    }
    return best;
}

Ray random_ray(Random& rng, double range = 30.0) {
    Ray ray;
    ray.origin = rng.vec(-range, range);
    // Half the rays aim at the middle of the scene, the rest go anywhere.
    ray.direction = rng.chance(0.5) ? normalize(rng.vec(-10, 10) - ray.origin) : rng.direction();
    ray.direction *= rng.uniform(0.2, 5.0);
    ray.kind = static_cast<RayKind>(rng.integer(0, 3));
    if (rng.chance(0.3)) ray.t_max = rng.uniform(1.0, 40.0);
    return ray;
}

void expect_same_hit(const std::optional<Hit>& got, const std::optional<Hit>& want, const char* what) {
    ASSERT_EQ(got.has_value(), want.has_value()) << what;
    if (!got) return;
    EXPECT_EQ(got->object, want->object) << what << " t " << got->t << " vs " << want->t;
    EXPECT_NEAR(got->t, want->t, 1e-12 * std::fabs(want->t)) << what;
    EXPECT_NEAR(length(got->normal), 1.0, 1e-12);
    EXPECT_TRUE(is_finite(got->position));
}

// A point to aim a ray at so that many rays graze silhouettes: near the object, or on an edge of a box nudged by up
// to 1e-6 either way.
Vec3 aim_at(Random& rng, const scene::Object& obj) {
    Vec3 toward = obj.transform.point(rng.vec(-1.5, 1.5));
    if (const auto* box = std::get_if<scene::Box>(&obj.shape)) {
        for (int k = 0; k < 3; ++k) toward[k] = rng.chance(0.5) ? box->corner1[k] : box->corner2[k];
        const int along = rng.integer(0, 2);
        toward[along] = rng.uniform(box->corner1[along], box->corner2[along]);
        toward += rng.vec(-1e-6, 1e-6);
    }
    return toward;
}

TEST(SceneGeometry, NearestHitMatchesBruteForce) {
    Random rng(42);
    const scene::Scene scene = random_scene(rng, 300, true, true);
    const SceneGeometry geometry(scene);
    EXPECT_TRUE(geometry.skipped_objects().empty());
    int hits = 0;
    for (int i = 0; i < 20000; ++i) {
        const Ray ray = random_ray(rng);
        const auto got = geometry.intersect(ray);
        expect_same_hit(got, brute_force(scene, ray), "random ray");
        hits += got.has_value();
        if (::testing::Test::HasFailure()) return;
    }
    EXPECT_GT(hits, 10000);
}

// A camera far away compared with the objects: Embree's float ray must not lose silhouette hits.
TEST(SceneGeometry, DistantOriginsMatchBruteForce) {
    Random rng(17);
    scene::Scene scene;
    for (int i = 0; i < 50; ++i) {
        // Half are axis-aligned boxes, whose faces coincide with their bounds: the worst case for a float ray.
        if (i % 2 == 0) {
            const Vec3 lo = rng.vec(-3.0, 3.0);
            scene.objects.push_back(make_object(scene::Box{lo, lo + rng.vec(0.1, 2.0)}));
        } else {
            scene.objects.push_back(make_object(test::random_shape(rng, false), rng.transform(3.0)));
        }
    }
    const SceneGeometry g(scene);
    int hits = 0;
    for (int i = 0; i < 20000; ++i) {
        Ray ray;
        ray.origin = rng.direction() * std::pow(10.0, rng.uniform(3.0, 7.0));
        ray.direction = normalize(aim_at(rng, scene.objects[rng.integer(0, 49)]) - ray.origin);
        const auto got = g.intersect(ray);
        expect_same_hit(got, brute_force(scene, ray), "distant ray");
        hits += got.has_value();
        if (::testing::Test::HasFailure()) return;
    }
    EXPECT_GT(hits, 5000);
}

// One huge object (a sky sphere of radius 1e6) around small ones: rays from near them take the BVH of tight boxes,
// rays from far the scene-wide one; both must find what the double loop finds, flagged objects and shadows included.
TEST(SceneGeometry, HugeObjectKeepsNearAndFarRaysExact) {
    Random rng(29);
    scene::Scene scene;
    for (int i = 0; i < 60; ++i) {
        if (i % 2 == 0) {
            const Vec3 lo = rng.vec(-3.0, 3.0);
            scene.objects.push_back(make_object(scene::Box{lo, lo + rng.vec(0.01, 1.0)}));
        } else {
            scene.objects.push_back(make_object(test::random_shape(rng, false), rng.transform(3.0)));
        }
        scene.objects.back().no_shadow = rng.chance(0.15);
        scene.objects.back().no_image = rng.chance(0.15);
    }
    scene::Object sky = make_object(scene::Sphere{{0, 0, 0}, 1.0});
    sky.transform = Transform::scaling({1e6, 1e6, 3e5});
    scene.objects.push_back(sky);
    const SceneGeometry g(scene);
    int hits = 0, blocked = 0;
    for (int i = 0; i < 20000; ++i) {
        Ray ray;
        const bool far = rng.chance(0.5);
        ray.origin = far ? rng.direction() * std::pow(10.0, rng.uniform(1.5, 5.4)) : rng.vec(-5.0, 5.0);
        ray.direction = normalize(aim_at(rng, scene.objects[rng.integer(0, 59)]) - ray.origin);
        ray.kind = static_cast<RayKind>(rng.integer(0, 3));
        const auto want = brute_force(scene, ray);
        expect_same_hit(g.intersect(ray), want, far ? "far ray" : "near ray");
        hits += want.has_value() && want->object < 60;
        ray.kind = RayKind::Shadow;
        const bool occ = g.occluded(ray);
        ASSERT_EQ(occ, brute_force(scene, ray).has_value()) << "ray " << i;
        blocked += occ;
        if (::testing::Test::HasFailure()) return;
    }
    EXPECT_GT(hits, 5000);
    EXPECT_GT(blocked, 5000);
}

TEST(SceneGeometry, OnlyBoundedObjectsAndOnlyPlanes) {
    Random rng(8);
    const scene::Scene bounded = random_scene(rng, 50, false, false);
    scene::Scene planes;
    planes.objects.push_back(make_object(scene::Plane{{0, 1, 0}, -1.0}));
    planes.objects.push_back(make_object(scene::Plane{{0, 0, -1}, -20.0}));
    const SceneGeometry g_bounded(bounded);
    const SceneGeometry g_planes(planes);
    EXPECT_TRUE(g_bounded.bounds().has_value());
    EXPECT_FALSE(g_planes.bounds().has_value());
    for (int i = 0; i < 2000; ++i) {
        const Ray ray = random_ray(rng);
        expect_same_hit(g_bounded.intersect(ray), brute_force(bounded, ray), "bounded");
        expect_same_hit(g_planes.intersect(ray), brute_force(planes, ray), "planes");
    }
    const SceneGeometry empty(scene::Scene{});
    EXPECT_FALSE(empty.intersect(Ray{{0, 0, 0}, {0, 0, 1}}));
    EXPECT_FALSE(empty.occluded(Ray{{0, 0, 0}, {0, 0, 1}}));
}

TEST(SceneGeometry, OccludedAgreesWithIntersect) {
    Random rng(43);
    const scene::Scene scene = random_scene(rng, 200, true, true);
    const SceneGeometry geometry(scene);
    int blocked = 0;
    for (int i = 0; i < 20000; ++i) {
        Ray ray = random_ray(rng);
        ray.kind = RayKind::Shadow;
        const bool occ = geometry.occluded(ray);
        ASSERT_EQ(occ, geometry.intersect(ray).has_value()) << "ray " << i;
        ASSERT_EQ(occ, brute_force(scene, ray).has_value()) << "ray " << i;
        blocked += occ;
    }
    EXPECT_GT(blocked, 2000);
    EXPECT_LT(blocked, 19000);
}

TEST(SceneGeometry, RayKindsSkipFlaggedObjects) {
    scene::Scene scene;
    scene.objects.push_back(make_object(scene::Sphere{{0, 0, 5}, 1.0}));
    scene.objects.push_back(make_object(scene::Sphere{{0, 0, 10}, 1.0}));
    scene.objects.push_back(make_object(scene::Plane{{0, 0, -1}, -20.0}));
    scene.objects[0].no_image = true;
    scene.objects[1].no_reflection = true;
    scene.objects[1].no_shadow = true;
    scene.objects[2].no_radiosity = true;
    const SceneGeometry g(scene);
    const auto hit_of = [&](RayKind kind) {
        const auto h = g.intersect(Ray{{0, 0, 0}, {0, 0, 1}, 0.0, 1e30, kind});
        return h ? static_cast<int>(h->object) : -1;
    };
    EXPECT_EQ(hit_of(RayKind::Camera), 1);       // no_image sphere skipped
    EXPECT_EQ(hit_of(RayKind::Reflection), 0);
    EXPECT_EQ(hit_of(RayKind::Shadow), 0);
    EXPECT_EQ(hit_of(RayKind::Gather), 0);
    // Shadow rays: the no_image sphere still casts a shadow, the no_shadow one does not.
    EXPECT_TRUE(g.occluded(Ray{{0, 0, 0}, {0, 0, 1}, 0.0, 7.0, RayKind::Shadow}));
    EXPECT_FALSE(g.occluded(Ray{{0, 0, 7}, {0, 0, 1}, 0.0, 12.0, RayKind::Shadow}));
    EXPECT_TRUE(g.occluded(Ray{{0, 0, 7}, {0, 0, 1}, 0.0, 14.0, RayKind::Shadow}));  // the plane at z = 20
    // Gather rays skip the no_radiosity plane.
    EXPECT_FALSE(g.intersect(Ray{{0, 0, 12}, {0, 0, 1}, 0.0, 1e30, RayKind::Gather}));
    EXPECT_TRUE(g.intersect(Ray{{0, 0, 12}, {0, 0, 1}, 0.0, 1e30, RayKind::Camera}));
}

TEST(SceneGeometry, TRangeIsOpen) {
    scene::Scene scene;
    scene.objects.push_back(make_object(scene::Box{{-1, -1, -1}, {1, 1, 1}}));
    const SceneGeometry g(scene);
    // Hits at exactly t_min (the entry at t = 2) or t_max (the exit at t = 4) are excluded.
    const auto h = g.intersect(Ray{{0, 0, -3}, {0, 0, 1}, 2.0, 5.0});
    ASSERT_TRUE(h);
    EXPECT_DOUBLE_EQ(h->t, 4.0);
    EXPECT_FALSE(g.intersect(Ray{{0, 0, -3}, {0, 0, 1}, 0.0, 2.0}));
    EXPECT_FALSE(g.occluded(Ray{{0, 0, -3}, {0, 0, 1}, 0.0, 2.0}));
    EXPECT_FALSE(g.intersect(Ray{{0, 0, -3}, {0, 0, 1}, 2.0, 4.0}));
    // A negative t_min reaches behind the origin.
    const auto behind = g.intersect(Ray{{0, 0, 3}, {0, 0, 1}, -10.0, 0.0});
    ASSERT_TRUE(behind);
    EXPECT_DOUBLE_EQ(behind->t, -4.0);
}

// POV-Ray compat (MIN_ISECT_DEPTH): no crossing nearer than 1e-4 to a ray's origin is seen, so a surface a hair
// (1e-8) past another is skipped by the ray that starts on the first; one 2e-4 past it is seen. A scene smaller
// than one unit keeps the proportion: the same rays at 1e-3 of the size skip and see the same surfaces.
TEST(SceneGeometry, CrossingsNearerThanMinIsectDepthAreNotSeen) {
    for (const double s : {1.0, 1e-3}) {
        scene::Scene scene;
        scene.objects.push_back(make_object(scene::Sphere{{0, 0, 0}, 1.0 * s}));
        scene.objects.push_back(make_object(scene::Sphere{{0, 0, 0}, (1.0 + 1e-8) * s}));
        scene.objects.push_back(make_object(scene::Sphere{{0, 0, 0}, (1.0 + 2e-4) * s}));
        const SceneGeometry g(scene);
        const Ray outward{{0, 0, 1.0 * s}, {0, 0, 1}, 1e-12 * s, 1e30};
        const auto h = g.intersect(outward);
        ASSERT_TRUE(h) << s;
        EXPECT_EQ(h->object, 2u) << s;
        EXPECT_NEAR(h->t, 2e-4 * s, 1e-9 * s) << s;
        EXPECT_TRUE(g.occluded(Ray{{0, 0, 1.0 * s}, {0, 0, 1}, 1e-12 * s, 3e-4 * s})) << s;
        EXPECT_FALSE(g.occluded(Ray{{0, 0, 1.0 * s}, {0, 0, 1}, 1e-12 * s, 1.5e-4 * s})) << s;
        EXPECT_DOUBLE_EQ(g.min_isect_parameter({0, 0, 2}), 0.5e-4 * std::fmin(1.0, (1.0 + 2e-4) * s)) << s;
    }
}

// The same scene and rays scaled by s give the same t (rays keep their direction vectors scaled by s too).
TEST(SceneGeometry, ScaleInvariance) {
    Random rng(11);
    const scene::Scene base = random_scene(rng, 100, true, false);
    std::vector<Ray> rays;
    for (int i = 0; i < 3000; ++i) rays.push_back(random_ray(rng));
    const SceneGeometry g1(base);
    for (double s : {1e-6, 1e6}) {
        scene::Scene scaled = base;
        for (auto& o : scaled.objects) o.transform = o.transform.then(Transform::scaling({s, s, s}));
        const SceneGeometry gs(scaled);
        int compared = 0;
        for (const Ray& r : rays) {
            Ray rs = r;
            rs.origin = r.origin * s;
            rs.direction = r.direction * s;
            const auto a = g1.intersect(r);
            const auto b = gs.intersect(rs);
            // POV-Ray compat (BOUND_HUGE): scaled up, a crossing 2e10 or farther away is not seen.
            if (a && a->t * length(rs.direction) >= 2e10) {
                EXPECT_FALSE(b.has_value()) << "scale " << s;
                continue;
            }
            ASSERT_EQ(a.has_value(), b.has_value()) << "scale " << s;
            if (!a) continue;
            ++compared;
            EXPECT_EQ(a->object, b->object);
            EXPECT_NEAR(a->t, b->t, 1e-9 * std::fabs(a->t)) << "scale " << s;
            EXPECT_NEAR(dot(a->normal, b->normal), 1.0, 1e-9);
            EXPECT_NEAR(length(b->position - a->position * s), 0.0, 1e-9 * s * (1.0 + max_abs_component(a->position)));
            EXPECT_NEAR(gs.self_intersection_offset(b->position), s * g1.self_intersection_offset(a->position),
                        1e-6 * s * g1.self_intersection_offset(a->position));
            EXPECT_EQ(gs.occluded(rs), g1.occluded(r));
        }
        EXPECT_GT(compared, 1000);
    }
}

// A ray leaving a surface from its hit point, offset by self_intersection_offset, never hits that surface at once.
TEST(SceneGeometry, OffsetAvoidsSelfIntersection) {
    for (double s : {1e-6, 1.0, 1e6}) {
        Random rng(21);
        scene::Scene scene = random_scene(rng, 60, true, false);
        for (auto& o : scene.objects) o.transform = o.transform.then(Transform::scaling({s, s, s}));
        const SceneGeometry g(scene);
        int tested = 0;
        for (int i = 0; i < 5000; ++i) {
            Ray ray = random_ray(rng);
            ray.origin *= s;
            ray.direction *= s;
            const auto hit = g.intersect(ray);
            if (!hit) continue;
            const Vec3 d = normalize(ray.direction);
            // Reflected and transmitted continuations, each offset to the side it travels into.
            const Vec3 n_facing = dot(d, hit->normal) < 0.0 ? hit->normal : -hit->normal;
            const double off = g.self_intersection_offset(hit->position);
            const Vec3 reflected = d - 2.0 * dot(d, n_facing) * n_facing;
            const auto r = g.intersect(Ray{hit->position + off * n_facing, reflected, 0.0, 1e30, ray.kind});
            if (r && r->object == hit->object) {
                EXPECT_GT(r->t, 1e-4 * s) << "scale " << s;
            }
            const auto tr = g.intersect(Ray{hit->position - off * n_facing, d, 0.0, 1e30, ray.kind});
            if (tr && tr->object == hit->object) {
                EXPECT_GT(tr->t, 1e-4 * s) << "scale " << s;
            }
            ++tested;
        }
        EXPECT_GT(tested, 1000);
    }
    EXPECT_GT(self_intersection_offset({0, 0, 0}), 0.0);
    EXPECT_DOUBLE_EQ(self_intersection_offset({1e6, -2e6, 0}), 2e-3);
}

TEST(SceneGeometry, DegenerateObjectsSkipped) {
    scene::Scene scene;
    scene.objects.push_back(make_object(scene::Sphere{{0, 0, 5}, 1.0}, Transform::scaling({0, 1, 1})));
    scene.objects.push_back(make_object(scene::Sphere{{0, 0, 10}, 1.0}));
    scene.objects.push_back(make_object(scene::Plane{{0, 0, 0}, 1.0}));
    const SceneGeometry g(scene);
    ASSERT_EQ(g.skipped_objects().size(), 2u);
    EXPECT_EQ(g.skipped_objects()[0], 0u);
    EXPECT_EQ(g.skipped_objects()[1], 2u);
    ASSERT_EQ(g.skip_reasons().size(), 2u);
    EXPECT_FALSE(g.skip_reasons()[0].too_deep);
    EXPECT_FALSE(g.skip_reasons()[1].too_deep);
    const auto h = g.intersect(Ray{{0, 0, 0}, {0, 0, 1}});
    ASSERT_TRUE(h);
    EXPECT_EQ(h->object, 1u);
    EXPECT_DOUBLE_EQ(h->t, 9.0);
}

TEST(SceneGeometry, BadRaysGiveNothing) {
    scene::Scene scene;
    scene.objects.push_back(make_object(scene::Sphere{{0, 0, 5}, 1.0}));
    const SceneGeometry g(scene);
    EXPECT_FALSE(g.intersect(Ray{{0, 0, 0}, {0, 0, 0}}));
    EXPECT_FALSE(g.intersect(Ray{{NAN, 0, 0}, {0, 0, 1}}));
    EXPECT_FALSE(g.occluded(Ray{{0, 0, 0}, {0, INFINITY, 1}}));
    // Coordinates beyond float range still work (brute-force fallback).
    const auto far = g.intersect(Ray{{0, 0, -1e300}, {0, 0, 1e-300}});
    EXPECT_TRUE(!far || std::isfinite(far->t));
}

TEST(SceneGeometry, GrazingRaysGiveNoNaN) {
    Random rng(31);
    scene::Scene scene;
    for (int i = 0; i < 20; ++i) scene.objects.push_back(make_object(scene::Sphere{rng.vec(-10, 10), 1.0}));
    const SceneGeometry g(scene);
    for (int i = 0; i < 5000; ++i) {
        const auto& s = std::get<scene::Sphere>(scene.objects[rng.integer(0, 19)].shape);
        const Vec3 n = rng.direction();
        const Vec3 t = normalize(cross(n, rng.direction()));
        const Vec3 p = s.center + n * (1.0 + rng.uniform(-1e-13, 1e-13));
        const auto hit = g.intersect(Ray{p - 30.0 * t, t});
        if (hit) {
            EXPECT_TRUE(std::isfinite(hit->t));
            EXPECT_TRUE(is_finite(hit->normal));
            EXPECT_NEAR(length(hit->normal), 1.0, 1e-12);
        }
    }
}

TEST(SceneGeometry, ConcurrentQueriesMatchSerial) {
    Random rng(55);
    const scene::Scene scene = random_scene(rng, 200, true, true);
    const SceneGeometry g(scene);
    std::vector<Ray> rays;
    for (int i = 0; i < 8000; ++i) rays.push_back(random_ray(rng));
    std::vector<std::optional<Hit>> serial;
    std::vector<char> serial_occ;
    for (const Ray& r : rays) {
        serial.push_back(g.intersect(r));
        serial_occ.push_back(g.occluded(r));
    }
    std::vector<int> mismatches(4, 0);
    std::vector<std::thread> threads;
    for (int t = 0; t < 4; ++t) {
        threads.emplace_back([&, t] {
            for (std::size_t i = t; i < rays.size(); i += 4) {
                const auto h = g.intersect(rays[i]);
                if (h.has_value() != serial[i].has_value() || (h && (h->t != serial[i]->t)) ||
                    g.occluded(rays[i]) != static_cast<bool>(serial_occ[i]))
                    ++mismatches[t];
            }
        });
    }
    for (auto& th : threads) th.join();
    for (int m : mismatches) EXPECT_EQ(m, 0);
}

// POV-Ray compat (BOUND_HUGE): no crossing 2e10 or farther along the ray is seen. A `poly` sphere of radius 1e9
// (no distance limit of its own, as POV-Ray's poly has none) is drawn by POV-Ray 3.7 at 120x90 with its centre at
// z = 1.9e10 and not at z = 2.2e10 (checked with /usr/bin/povray); the ray's length must not matter.
TEST(SceneGeometry, NothingBeyondBoundHuge) {
    for (const double centre : {1.9e10, 2.2e10}) {
        const double r = 1e9;
        scene::Poly sphere;
        sphere.order = 2;
        sphere.coefficients = {1, 0, 0, 0, 1, 0, 0, 1, -2 * centre, centre * centre - r * r};
        scene::Scene scene;
        scene.objects.push_back(make_object(sphere));
        const SceneGeometry geometry(scene);
        for (const double scale : {0.5, 1.0, 4.0}) {
            const auto hit = geometry.intersect(Ray{{0, 0, 0}, {0, 0, scale}});
            EXPECT_EQ(hit.has_value(), centre - r < 2e10) << centre << " scale " << scale;
            if (hit) {
                EXPECT_NEAR(hit->t * scale, centre - r, 1e-6 * centre);
            }
        }
    }
}

}  // namespace
}  // namespace wardray::geometry
