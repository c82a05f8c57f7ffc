// Tests of the isosurface against brute force: hits on f = threshold, normals by finite differences, the inside
// test against sampling, POV-Ray's caps and max_trace, finite results at extreme scales, the max_gradient warning.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "geometry/instance.h"
#include "geometry/isosurface.h"
#include "parser/parse.h"
#include "test_util.h"

namespace wardray::geometry {
namespace {

using test::Random;

// The one object of a scene made of `statement`.
scene::Object parse_object(const std::string& statement) {
    parser::ParseOptions options;
    options.library_paths = {"/usr/share/povray-3.7/include"};
    const parser::ParseResult r = parser::parse_string(
        "global_settings { assumed_gamma 1 }\n#include \"functions.inc\"\n" + statement, "iso.pov", options);
    EXPECT_TRUE(r.ok());
    if (!r.ok() || !r.scene || r.scene->objects.size() != 1) return {};
    return r.scene->objects.front();
}

const IsosurfaceShape& iso_of(const ShapeInstance& inst) { return std::get<IsosurfaceShape>(inst.shape()); }

// Isosurfaces whose max_gradient is a true bound of the function's slope, so POV-Ray's solver finds every root.
const char* const k_surfaces[] = {
    "isosurface { function { sqrt(x*x + y*y + z*z) - 0.8 } contained_by { box { -1, 1 } } all_intersections }",
    "isosurface { function { f_torus(x, y, z, 0.7, 0.25) } contained_by { sphere { 0, 1.2 } } all_intersections }",
    "isosurface { function { y - 0.3*sin(3*x)*cos(2*z) } max_gradient 1.8 open all_intersections "
    "contained_by { box { -1, 1 } } }",
    "isosurface { function { sqrt(x*x + y*y + z*z) - 0.7 + f_noise3d(3*x, 3*y, 3*z)*0.2 } max_gradient 2.5 "
    "all_intersections contained_by { sphere { 0, 1 } } }",
    "isosurface { function { f_rounded_box(x, y, z, 0.2, 0.6, 0.5, 0.4) } threshold 0.05 all_intersections "
    "contained_by { box { -1, 1 } } scale <1, 2, 0.5> rotate <30, 40, 50> translate <0.5, -1, 2> }",
};

// Random rays through the surfaces' region: every crossing is on f = threshold (within what accuracy allows) or on
// the container, its normal follows the gradient, and sampling the ray between crossings agrees with inside().
TEST(Isosurface, HitsNormalsAndInsideAgreeWithBruteForce) {
    Random rng(77);
    int crossings = 0;
    for (const char* text : k_surfaces) {
        SCOPED_TRACE(text);
        const scene::Object obj = parse_object(text);
        const auto inst = ShapeInstance::create(obj, 0);
        ASSERT_TRUE(inst.has_value());
        const IsosurfaceShape& iso = iso_of(*inst);
        const double acc = iso.description().accuracy;
        const double slope = iso.description().max_gradient;
        for (int trial = 0; trial < 200; ++trial) {
            const Vec3 target = obj.transform.point(rng.vec(-0.9, 0.9));
            const Vec3 origin = target - 6.0 * rng.direction();
            const Vec3 dir = normalize(target - origin);
            const SurfaceHits hits = inst->intersect_all(origin, dir, 1e-6, INFINITY);
            for (const SurfaceHit& h : hits) {
                const Vec3 p = obj.transform.inverse_point(origin + h.t * dir);
                const double len = length(obj.transform.inverse_vector(dir));
                // The crossing is within one accuracy step along the ray of a root, or on the container.
                EXPECT_LE(std::fabs(iso.implicit(p)), slope * acc * len * 1.01 + 1e-9) << "t " << h.t;
                EXPECT_NEAR(length(h.normal), 1.0, 1e-9);
                const double fd = 1e-5;
                const Vec3 g{iso.field(p + Vec3{fd, 0, 0}) - iso.field(p - Vec3{fd, 0, 0}),
                             iso.field(p + Vec3{0, fd, 0}) - iso.field(p - Vec3{0, fd, 0}),
                             iso.field(p + Vec3{0, 0, fd}) - iso.field(p - Vec3{0, 0, fd})};
                const bool on_function = std::fabs(iso.field(p)) <= slope * acc * len * 1.01 + 1e-9;
                if (on_function && length(g) > 1e-9 && iso.implicit(p) > -1e-9) {
                    const Vec3 n_world = normalize(obj.transform.normal(g));
                    EXPECT_GT(dot(n_world, h.normal), 0.98) << "normal at t " << h.t;
                }
                ++crossings;
            }
            // Between crossings (and away from them) inside() is constant and flips at each crossing; an open
            // surface has no caps, so there the container's walls change it too.
            if (iso.description().open) continue;
            double t_prev = 1e-6;
            bool expect_inside = inst->inside(origin + t_prev * dir);
            for (std::size_t i = 0; i <= hits.size(); ++i) {
                const double t_next = i < hits.size() ? hits[i].t : 12.0;
                if (t_next - t_prev > 20 * acc) {
                    for (int k = 1; k < 8; ++k) {
                        const double t = t_prev + 5 * acc + (t_next - t_prev - 10 * acc) * k / 8.0;
                        EXPECT_EQ(inst->inside(origin + t * dir), expect_inside) << "t " << t;
                    }
                }
                if (i < hits.size()) {
                    EXPECT_EQ(hits[i].entering, !expect_inside) << "crossing " << i;
                    expect_inside = !expect_inside;
                    t_prev = t_next;
                }
            }
        }
    }
    EXPECT_GT(crossings, 500);
}

// The sphere f = |p| - r is found where the analytic sphere is, within accuracy, also from inside.
TEST(Isosurface, SphereFunctionMatchesTheAnalyticSphere) {
    const scene::Object obj = parse_object(
        "isosurface { function { sqrt(x*x + y*y + z*z) - 0.6 } accuracy 0.0001 contained_by { box { -1, 1 } } }");
    const auto inst = ShapeInstance::create(obj, 0);
    ASSERT_TRUE(inst.has_value());
    Random rng(5);
    for (int trial = 0; trial < 300; ++trial) {
        const Vec3 origin = rng.chance(0.3) ? rng.vec(-0.3, 0.3) : 4.0 * rng.direction();
        const Vec3 dir = rng.chance(0.5) ? normalize(rng.vec(-0.4, 0.4) - origin) : rng.direction();
        // Analytic: |o + t d| = 0.6.
        const double b = dot(origin, dir), c = dot(origin, origin) - 0.36, disc = b * b - c;
        const auto hit = inst->nearest(origin, dir, 1e-6, INFINITY);
        if (disc <= 1e-6) {
            EXPECT_FALSE(hit.has_value() && std::fabs(length(hit->position) - 0.6) < 1e-3);
            continue;
        }
        const double t0 = -b - std::sqrt(disc), t1 = -b + std::sqrt(disc);
        const double expected = t0 > 1e-3 ? t0 : t1;
        if (expected < 1e-3) continue;
        ASSERT_TRUE(hit.has_value()) << trial;
        EXPECT_NEAR(hit->t, expected, 2e-4) << trial;
        EXPECT_NEAR(dot(hit->normal, hit->position / length(hit->position)), 1.0, 1e-3);
    }
}

// POV-Ray's caps: a closed isosurface shows the container where f < threshold; open shows none; max_trace 1
// stops at the first crossing, all_intersections finds both walls.
TEST(Isosurface, ContainerCapsOpenAndMaxTrace) {
    const Vec3 o{0.0, 0.0, -5.0}, d{0.0, 0.0, 1.0};
    const auto closed = ShapeInstance::create(
        parse_object("isosurface { function { sqrt(x*x + y*y + z*z) - 2 } contained_by { box { -1, 1 } } }"), 0);
    ASSERT_TRUE(closed.has_value());
    const SurfaceHits caps = closed->intersect_all(o, d, 1e-6, INFINITY);
    ASSERT_EQ(caps.size(), 1u);  // POV-Ray compat: the entry cap uses up max_trace 1, the exit is not looked for
    EXPECT_NEAR(caps[0].t, 4.0, 1e-12);
    EXPECT_NEAR(caps[0].normal.z, -1.0, 1e-12);
    EXPECT_TRUE(caps[0].entering);
    // From inside the container the far cap is reported where the field is negative there.
    const SurfaceHits from_inside = closed->intersect_all({0.0, 0.0, 0.0}, d, 1e-6, INFINITY);
    ASSERT_EQ(from_inside.size(), 1u);
    EXPECT_NEAR(from_inside[0].t, 1.0, 1e-12);
    EXPECT_FALSE(from_inside[0].entering);
    const auto open = ShapeInstance::create(
        parse_object("isosurface { function { sqrt(x*x + y*y + z*z) - 2 } open contained_by { box { -1, 1 } } }"), 0);
    EXPECT_TRUE(open->intersect_all(o, d, 1e-6, INFINITY).empty());
    const char* shell = "isosurface { function { abs(sqrt(x*x + y*y + z*z) - 0.7) - 0.1 } %s "
                        "contained_by { sphere { 0, 1 } } }";
    char text[256];
    std::snprintf(text, sizeof text, shell, "");
    EXPECT_EQ(ShapeInstance::create(parse_object(text), 0)->intersect_all(o, d, 1e-6, INFINITY).size(), 1u);
    std::snprintf(text, sizeof text, shell, "all_intersections");
    const SurfaceHits all = ShapeInstance::create(parse_object(text), 0)->intersect_all(o, d, 1e-6, INFINITY);
    ASSERT_EQ(all.size(), 4u);
    const double expected[] = {4.2, 4.4, 5.6, 5.8};
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(all[i].t, expected[i], 2e-3);
}

// POV-Ray compat: a shadow ray walking through the surfaces it crosses is a new ray from each crossing in POV-Ray,
// so past the entry cap of a closed isosurface (the ray now inside the container) it meets the far cap, which the
// ray from its first origin does not report (ContainerCapsOpenAndMaxTrace).
TEST(Isosurface, ARayGoingOnFromInsideTheContainerMeetsTheFarCap) {
    const Vec3 o{0.0, 0.0, -5.0}, d{0.0, 0.0, 1.0};
    const auto closed = ShapeInstance::create(
        parse_object("isosurface { function { sqrt(x*x + y*y + z*z) - 2 } contained_by { box { -1, 1 } } }"), 0);
    ASSERT_TRUE(closed.has_value());
    ASSERT_EQ(closed->intersect_all(o, d, 1e-6, INFINITY).size(), 1u);  // the entry cap at t = 4
    const SurfaceHits on = closed->intersect_all(o, d, 4.0 + 1e-4, INFINITY);
    ASSERT_EQ(on.size(), 1u);
    EXPECT_NEAR(on[0].t, 6.0, 1e-9);
    EXPECT_NEAR(on[0].normal.z, 1.0, 1e-12);
    EXPECT_FALSE(on[0].entering);
    // Where the field is positive at the far cap (a sphere inside the container), the walk meets the sphere instead.
    const auto ball = ShapeInstance::create(
        parse_object("isosurface { function { sqrt(x*x + y*y + z*z) - 0.5 } contained_by { box { -1, 1 } } }"), 0);
    const SurfaceHits ball_on = ball->intersect_all(o, d, 4.0 + 1e-4, INFINITY);
    ASSERT_EQ(ball_on.size(), 1u);
    EXPECT_NEAR(ball_on[0].t, 4.5, 2e-3);
}

// Scaled by 1e-4 and 1e4, an isosurface gives finite hits and normals. POV-Ray compat: accuracy is measured along
// the world ray, so the tiny one needs an accuracy scaled with it (POV-Ray draws nothing of it otherwise).
TEST(Isosurface, ExtremeScalesStayFinite) {
    for (const double s : {1e-4, 1.0, 1e4}) {
        SCOPED_TRACE(s);
        char text[300];
        std::snprintf(text, sizeof text,
                      "isosurface { function { f_torus(x, y, z, 0.7, 0.25) + f_noise3d(4*x, 4*y, 4*z)*0.1 } "
                      "max_gradient 1.5 accuracy %g contained_by { box { -1, 1 } } scale %g }",
                      0.001 * std::min(s, 1.0), s);
        const auto inst = ShapeInstance::create(parse_object(text), 0);
        ASSERT_TRUE(inst.has_value());
        Random rng(9);
        int hits = 0;
        for (int trial = 0; trial < 200; ++trial) {
            const Vec3 origin = 5.0 * s * rng.direction();
            const Vec3 dir = normalize(s * rng.vec(-0.8, 0.8) - origin);
            for (const SurfaceHit& h : inst->intersect_all(origin, dir, 1e-9 * s, INFINITY)) {
                EXPECT_TRUE(std::isfinite(h.t));
                EXPECT_TRUE(is_finite(h.normal));
                ++hits;
            }
        }
        EXPECT_GT(hits, 50);
    }
}

// After rendering, a max_gradient below the slopes the solver met warns with the value found, as POV-Ray does.
TEST(Isosurface, MaxGradientTooLowWarnsWithTheGradientFound) {
    const auto inst = ShapeInstance::create(
        parse_object("isosurface { function { y - sin(8*x)*0.5 } max_gradient 1 contained_by { box { -1, 1 } } }"),
        0);
    ASSERT_TRUE(inst.has_value());
    const IsosurfaceShape& iso = iso_of(*inst);
    EXPECT_FALSE(iso.gradient_warning().has_value());  // nothing traced yet
    for (int i = 0; i < 50; ++i) inst->intersect_all({-0.9 + 0.036 * i, 3.0, -0.3}, {0.0, -1.0, 0.1}, 1e-6, INFINITY);
    for (int i = 0; i < 50; ++i) inst->intersect_all({-3.0, 0.1 * std::sin(i), -0.3 + 0.01 * i}, {1.0, 0.05, 0.0}, 1e-6, INFINITY);
    ASSERT_GT(iso.gradient_found(), 1.5);
    const auto w = iso.gradient_warning();
    ASSERT_TRUE(w.has_value());
    EXPECT_NE(w->message.find("was set to 1.000"), std::string::npos) << w->message;
    EXPECT_NE(w->message.find("holes"), std::string::npos) << w->message;
    EXPECT_EQ(w->loc.line, 3u);
}

// With `evaluate`, POV-Ray 3.7 keeps the gradient bound a ray ended with for the next ray, so rays traced after
// steep ones search more finely: shapes.inc's Supertorus (portfolio/o_shapes.pov's last frame, evaluate 1, 10, 0.1)
// shows its grazing silhouette only when the rays before it have raised the bound.
TEST(Isosurface, EvaluateCarriesTheGradientBoundFromRayToRay) {
    const std::string text = "#include \"shapes.inc\"\nobject { Supertorus(0.6, 0.3, 0.50, 0.2, 0.0001, 0) }";
    const auto silhouette_hits = [](const ShapeInstance& inst) {
        int hits = 0;
        for (int i = 0; i < 400; ++i) {
            const double x = 0.85 + 0.0001 * i;  // across the outer silhouette at |x| = 0.9
            if (!inst.intersect_all({x, 0.05, -3.0}, {0.0, 0.0, 1.0}, 1e-6, INFINITY).empty()) ++hits;
        }
        return hits;
    };
    const auto fresh = ShapeInstance::create(parse_object(text), 0);
    const auto warmed = ShapeInstance::create(parse_object(text), 0);
    ASSERT_TRUE(fresh.has_value() && warmed.has_value());
    ASSERT_TRUE(iso_of(*warmed).description().evaluate);
    // Rays across the tube's steep walls first raise the carried bound.
    for (int i = 0; i < 200; ++i) warmed->intersect_all({-0.9 + 0.009 * i, 0.02, -3.0}, {0.0, 0.0, 1.0}, 1e-6, INFINITY);
    const int fresh_hits = silhouette_hits(*fresh);
    const int warmed_hits = silhouette_hits(*warmed);
    EXPECT_GT(warmed_hits, fresh_hits);
    // Without `evaluate` the bound is max_gradient on every ray: the order of rays changes nothing.
    const std::string fixed = "isosurface { function { y - sin(8*x)*0.5 } max_gradient 1 contained_by { box { -1, 1 } } }";
    const auto a = ShapeInstance::create(parse_object(fixed), 0);
    const auto b = ShapeInstance::create(parse_object(fixed), 0);
    ASSERT_TRUE(a.has_value() && b.has_value());
    for (int i = 0; i < 50; ++i) b->intersect_all({-0.9 + 0.036 * i, 3.0, -0.3}, {0.0, -1.0, 0.1}, 1e-6, INFINITY);
    for (int i = 0; i < 100; ++i) {
        const Vec3 o{-3.0, 0.01 * i - 0.5, 0.1}, d{1.0, 0.02, 0.0};
        EXPECT_EQ(a->intersect_all(o, d, 1e-6, INFINITY).size(), b->intersect_all(o, d, 1e-6, INFINITY).size());
    }
}

}  // namespace
}  // namespace wardray::geometry
