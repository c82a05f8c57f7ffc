// Light choice on gather paths: the pick's chances are the importances', the weighted pick keeps the expectation of
// the sum over all lights, and a render with picks converges to the one that tests every light.
#include "lighting/light_choice.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "../parser/test_util.h"
#include "geometry/scene_geometry.h"
#include "lighting/integrator.h"

namespace wardray::lighting {
namespace {

TEST(LightChoice, PicksEachLightWithItsShareOfTheImportance) {
    const std::vector<double> importance{0.0, 2.0, 0.0, 1.0, 5.0, 0.5};
    double total = 0.0;
    for (double w : importance) total += w;
    // u on a fine regular grid stands for the uniform distribution: each light's share of it is its chance.
    const int n = 85000;
    std::vector<int> count(importance.size(), 0);
    for (int i = 0; i < n; ++i) {
        const LightPick pick = pick_light(importance, total, (i + 0.5) / n);
        ASSERT_LT(pick.index, importance.size());
        ASSERT_GT(importance[pick.index], 0.0) << "a light of no importance was picked";
        EXPECT_DOUBLE_EQ(pick.probability, importance[pick.index] / total);
        ++count[pick.index];
    }
    for (std::size_t k = 0; k < importance.size(); ++k)
        EXPECT_NEAR(static_cast<double>(count[k]) / n, importance[k] / total, 2.0 / n) << "light " << k;
    // The last uniform below 1 still picks a light that can be picked.
    EXPECT_EQ(pick_light(importance, total, std::nextafter(1.0, 0.0)).index, 5u);
    EXPECT_EQ(pick_light(importance, total, 0.0).index, 1u);
}

TEST(LightChoice, WeightedPickKeepsTheSumOverAllLights) {
    // Any contributions, nonzero only where the importance is: the mean of f_k / p_k over the picks is Σ f.
    const std::vector<double> importance{3.0, 0.25, 1.0, 0.0, 7.0};
    const std::vector<double> contribution{0.4, 2.0, -0.3, 0.0, 1.5};
    double total = 0.0, sum = 0.0;
    for (std::size_t k = 0; k < importance.size(); ++k) {
        total += importance[k];
        sum += contribution[k];
    }
    const int n = 1 << 16;
    double mean = 0.0;
    for (int i = 0; i < n; ++i) {
        const LightPick pick = pick_light(importance, total, (i + 0.5) / n);
        mean += contribution[pick.index] / pick.probability / n;
    }
    EXPECT_NEAR(mean, sum, 1e-3 * std::fabs(sum));
}

// A room lit by lights of different strengths, a fade, a spotlight and a shadowless fill light; `extra` adds objects.
std::string lit_room(const std::string& colour_a, const std::string& colour_b, const std::string& extra) {
    return "global_settings { radiosity { count 50 recursion_limit 2 } }\n"
           "camera { location <0, 1, 0> look_at <0, 0, 0.1> }\n"
           "box { <-3, 0, -3>, <3, 2, 3> inverse pigment { rgb 0.7 } finish { diffuse 0.8 ambient 0 } }\n"
           "light_source { <0, 1.5, 0> " + colour_a + " }\n"
           "light_source { <2, 1.2, 1> " + colour_b + " fade_distance 1 fade_power 2 }\n"
           "light_source { <-1, 0.5, 2> rgb 2 spotlight point_at <-1, 2, 2> radius 30 falloff 60 }\n"
           "light_source { <-2, 1.8, -2> rgb 0.7 }\n"
           "light_source { <0.5, 1, -2> rgb 0.3 shadowless }\n" + extra;
}

struct Rendered {
    double sum = 0.0;          ///< the green channel summed over the points
    std::uint64_t shadow = 0;  ///< shadow rays traced
};

// Looks down at a grid of floor points in reference mode, `picks` lights tested per gather-path hit.
Rendered render_floor(const scene::Scene& scene, int picks, int rays) {
    const geometry::SceneGeometry geometry(scene);
    IntegratorOptions options;
    options.gi = GiMode::Reference;
    options.reference_rays = rays;
    options.gather_light_picks = picks;
    const Integrator integrator(scene, geometry, options);
    Rendered out;
    TraceContext ctx;
    for (int i = 0; i < 6; ++i) {
        for (int j = 0; j < 6; ++j) {
            const Vec3 origin{-2.5 + i, 1.0, -2.5 + j};
            out.sum += integrator.trace_camera_ray(geometry::Ray{origin, {0, -1, 0}}, ctx).y;
        }
    }
    out.shadow = ctx.rays.shadow;
    return out;
}

TEST(LightChoice, UnshadowedGreyLightsArePickedWithoutNoise) {
    // Without blockers and with grey lights, the importance is each light's exact share, so the picked estimate is
    // the sum over all lights itself: the render equals the one that tests every light (the same gather rays).
    const scene::Scene scene = parser::test::parse_ok(lit_room("rgb 1", "rgb 0.5", ""));
    const Rendered all = render_floor(scene, 0, 32);
    const Rendered one = render_floor(scene, 1, 32);
    EXPECT_NEAR(one.sum, all.sum, 1e-9 * all.sum);
    // Four lights need shadow rays at every gather hit when all are tested; one when one is picked.
    EXPECT_LT(one.shadow * 2, all.shadow);
}

TEST(LightChoice, ShadowedColouredLightsConvergeToTheSumOverAllLights) {
    // Blockers between lights and walls, and lights of different colours: the picks add noise but no bias.
    const scene::Scene scene = parser::test::parse_ok(lit_room(
        "rgb <1, 0.2, 0.1>", "rgb <0.1, 0.6, 1>",
        "box { <-0.5, 0.2, -0.5>, <0.5, 1.3, 0.5> translate <1, 0, 0.5> pigment { rgb 0.5 } }\n"
        "sphere { <-1, 1.4, 1.2>, 0.4 pigment { rgb 0.9 } }\n"));
    const Rendered all = render_floor(scene, 0, 512);
    const Rendered one = render_floor(scene, 1, 512);
    const Rendered two = render_floor(scene, 2, 512);
    std::cout << "[ light choice] one pick " << 100 * (one.sum / all.sum - 1) << " %, two picks "
              << 100 * (two.sum / all.sum - 1) << " % from every light; shadow rays " << one.shadow << ", "
              << two.shadow << ", " << all.shadow << "\n";
    EXPECT_NEAR(one.sum, all.sum, 0.0025 * all.sum);
    EXPECT_NEAR(two.sum, all.sum, 0.0025 * all.sum);
    EXPECT_LT(one.shadow, two.shadow);
    EXPECT_LT(two.shadow, all.shadow);
}

// A floor half in the penumbra of a black bar under a jittered 4x4 area light (full subdivision: adaptive 5), with
// a radiosity block whose indirect light is black (nothing but the floor reflects).
std::string penumbra_scene() {
    return "global_settings { radiosity { count 20 recursion_limit 1 } }\n"
           "camera { location <0, 0.3, 0> look_at <0, 0, 0.1> }\n"
           "plane { y, 0 pigment { rgb 1 } finish { diffuse 1 ambient 0 } }\n"
           "box { <-0.05, 0.5, -5>, <0.05, 0.52, 5> pigment { rgb 0 } finish { diffuse 0 ambient 0 } }\n"
           "light_source { <0, 1, 0> rgb 1 area_light 0.6*x, 0.6*z, 4, 4 jitter adaptive 5 }\n";
}

double floor_radiance(const Integrator& integrator, double x) {
    TraceContext ctx;
    return integrator.trace_camera_ray(geometry::Ray{{x, 0.3, 0.013}, {0, -1, 0}}, ctx).y;
}

TEST(AreaLightReference, FineGridHasTheExpectationOfPovRaysJitteredGrid) {
    // The reference samples a jittered area light on a fine jittered grid over the same grid coordinates POV-Ray's
    // jitter covers, [−½, n − ½]²: its value in the penumbra must be the mean of POV-Ray's 4x4 grid over many seeds.
    const scene::Scene scene = parser::test::parse_ok(penumbra_scene());
    const geometry::SceneGeometry geometry(scene);
    IntegratorOptions fine_options;
    fine_options.gi = GiMode::Reference;
    fine_options.reference_rays = 4096;
    const Integrator fine(scene, geometry, fine_options);
    const std::vector<double> xs{0.0, 0.1, 0.3, 0.35, 0.4, 0.45};
    std::vector<double> mean(xs.size(), 0.0);
    const int seeds = 2000;
    for (int seed = 1; seed <= seeds; ++seed) {
        IntegratorOptions grid_options;
        grid_options.seed = static_cast<std::uint64_t>(seed);
        const Integrator grid(scene, geometry, grid_options);
        for (std::size_t i = 0; i < xs.size(); ++i) mean[i] += floor_radiance(grid, xs[i]) / seeds;
    }
    for (std::size_t i = 0; i < xs.size(); ++i) {
        const double sampled = floor_radiance(fine, xs[i]);
        EXPECT_GT(sampled, 0.0) << "x " << xs[i];
        EXPECT_NEAR(sampled, mean[i], 0.01) << "x " << xs[i];
        std::cout << "[ area light] x " << xs[i] << ": fine " << sampled << ", POV-Ray's grid over " << seeds
                  << " seeds " << mean[i] << "\n";
    }
}

}  // namespace
}  // namespace wardray::lighting
