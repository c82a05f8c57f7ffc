// Direct lighting against analytic answers: the cosine law, fading, spotlight profile, shadows, ambient rules.
#include "lighting/integrator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "geometry/scene_geometry.h"

namespace wardray::lighting {
namespace {

// A white Lambertian floor (diffuse 1, no ambient) at y = 0.
scene::Scene floor_scene() {
    scene::Scene scene;
    scene::Object floor;
    floor.shape = scene::Plane{{0, 1, 0}, 0.0};
    floor.texture->pigment.color = {1, 1, 1};
    floor.texture->finish.ambient = {0, 0, 0};
    floor.texture->finish.diffuse = 1.0;
    scene.objects.push_back(floor);
    return scene;
}

scene::Light point_light(const Vec3& p, double intensity = 1.0) {
    scene::Light l;
    l.position = p;
    l.color = {intensity, intensity, intensity};
    return l;
}

// Radiance seen looking straight down at floor point (x, 0, z) from height 1. The camera is put where the ray
// starts (above the floor: at the default location it would lie on the floor plane, which counts as inside it).
double radiance_at(scene::Scene scene, double x, double z, GiMode gi = GiMode::Off) {
    scene.camera.location = {x, 1.0, z};
    const geometry::SceneGeometry geometry(scene);
    IntegratorOptions options;
    options.gi = gi;
    const Integrator integrator(scene, geometry, options);
    TraceContext counters;
    geometry::Ray ray{{x, 1.0, z}, {0, -1, 0}};
    return integrator.trace_camera_ray(ray, counters).y;
}

TEST(DirectLighting, PointLightFollowsTheCosineLawWithoutInverseSquare) {
    scene::Scene scene = floor_scene();
    scene.lights.push_back(point_light({0, 2, 0}));
    for (double x : {0.0, 0.5, 1.0, 2.0, 5.0}) {
        const double cos_theta = 2.0 / std::sqrt(4.0 + x * x);
        EXPECT_NEAR(radiance_at(scene, x, 0.0), cos_theta, 1e-9) << x;
    }
}

TEST(DirectLighting, BrillianceRaisesTheCosine) {
    scene::Scene scene = floor_scene();
    scene.objects[0].texture->finish.brilliance = 3.0;
    scene.lights.push_back(point_light({0, 2, 0}));
    const double cos_theta = 2.0 / std::sqrt(4.0 + 1.0);
    EXPECT_NEAR(radiance_at(scene, 1.0, 0.0), std::pow(cos_theta, 3.0), 1e-9);
}

TEST(DirectLighting, FadeIsTwoOverOnePlusDistanceRatioToThePower) {
    scene::Scene scene = floor_scene();
    scene::Light l = point_light({0, 3, 0});
    l.fade_distance = 1.5;
    l.fade_power = 2.0;
    scene.lights.push_back(l);
    EXPECT_NEAR(radiance_at(scene, 0.0, 0.0), 2.0 / (1.0 + 4.0), 1e-9);
}

TEST(DirectLighting, SpotlightIsFullInsideRadiusDarkOutsideFalloffSmoothBetween) {
    scene::Scene scene = floor_scene();
    scene::Light l = point_light({0, 1, 0});
    l.type = scene::Light::Type::Spot;
    l.point_at = {0, 0, 0};
    l.radius = 20;
    l.falloff = 40;
    scene.lights.push_back(l);
    auto angle_x = [](double deg) { return std::tan(deg * std::numbers::pi / 180.0); };
    const double cos10 = std::cos(10 * std::numbers::pi / 180);
    EXPECT_NEAR(radiance_at(scene, angle_x(10), 0.0), cos10, 1e-9);
    EXPECT_EQ(radiance_at(scene, angle_x(45), 0.0), 0.0);
    const double cos30 = std::cos(30 * std::numbers::pi / 180);
    const double lo = std::cos(40 * std::numbers::pi / 180), hi = std::cos(20 * std::numbers::pi / 180);
    const double t = (cos30 - lo) / (hi - lo);
    EXPECT_NEAR(radiance_at(scene, angle_x(30), 0.0), cos30 * t * t * (3 - 2 * t), 1e-9);
}

TEST(DirectLighting, ASpotlightWhoseFalloffIsBelowItsRadiusLightsTheWholeRadius) {
    // POV-Ray compat: the ramp applies only beyond radius, so `radius 30 falloff 4` is full (cos^tightness) up to
    // 30 degrees and dark beyond, not dark beyond 4 degrees (a user's scene).
    scene::Scene scene = floor_scene();
    scene::Light l = point_light({0, 1, 0});
    l.type = scene::Light::Type::Spot;
    l.point_at = {0, 0, 0};
    l.radius = 30;
    l.falloff = 4;
    scene.lights.push_back(l);
    auto angle_x = [](double deg) { return std::tan(deg * std::numbers::pi / 180.0); };
    const double cos20 = std::cos(20 * std::numbers::pi / 180);
    EXPECT_NEAR(radiance_at(scene, angle_x(20), 0.0), cos20, 1e-9);
    EXPECT_EQ(radiance_at(scene, angle_x(35), 0.0), 0.0);
}

TEST(DirectLighting, ParallelLightHasOneDirectionEverywhere) {
    scene::Scene scene = floor_scene();
    scene::Light l = point_light({0, 10, -10});
    l.type = scene::Light::Type::Parallel;
    l.point_at = {0, 0, 0};
    scene.lights.push_back(l);
    const double expected = std::cos(std::numbers::pi / 4);
    EXPECT_NEAR(radiance_at(scene, 0.0, 0.0), expected, 1e-9);
    EXPECT_NEAR(radiance_at(scene, 7.0, 3.0), expected, 1e-9);
}


TEST(DirectLighting, ParallelLightLightsPointsPastItsPlaneWithoutShadows) {
    // POV-Ray compat: the light shines up (+y) from its plane y = -0.5, below the floor, which it still lights.
    scene::Scene scene = floor_scene();
    scene::Light light = point_light({0, -0.5, 0});
    light.type = scene::Light::Type::Parallel;
    light.point_at = {0, -1.5, 0};
    scene.lights.push_back(light);
    EXPECT_NEAR(radiance_at(scene, 0.0, 0.0), 1.0, 1e-9);
    // A blocker between floor and camera, past the plane too, casts no shadow.
    scene::Object blocker;
    blocker.shape = scene::Sphere{{0, 0.5, 0}, 0.1};
    blocker.no_image = true;
    scene.objects.push_back(blocker);
    EXPECT_NEAR(radiance_at(scene, 0.0, 0.0), 1.0, 1e-9);
}
TEST(DirectLighting, ShadowsBlockAndNoShadowObjectsDoNot) {
    scene::Scene scene = floor_scene();
    scene.lights.push_back(point_light({0, 4, 0}));
    scene::Object blocker;
    blocker.shape = scene::Sphere{{0, 2, 0}, 0.5};
    scene.objects.push_back(blocker);
    EXPECT_EQ(radiance_at(scene, 0.0, 0.0), 0.0);
    EXPECT_NEAR(radiance_at(scene, 3.0, 0.0), 4.0 / 5.0, 1e-9);  // outside the shadow
    scene.objects[1].no_shadow = true;
    EXPECT_NEAR(radiance_at(scene, 0.0, 0.0), 1.0, 1e-9);
    scene.objects[1].no_shadow = false;
    scene.lights[0].shadowless = true;
    EXPECT_NEAR(radiance_at(scene, 0.0, 0.0), 1.0, 1e-9);
}

TEST(DirectLighting, ShadowRaysThroughTransparencySeeNothingWithinSmallTolerance) {
    // POV-Ray compat (TracePointLightShadowRay): a shadow ray ignores crossings within SMALL_TOLERANCE (1e-3) of
    // where it starts (landscape.pov's overlapping leaf spheres a hair apart). A scene with something transparent
    // (here a filtering sphere under the floor) walks its shadow rays through every crossing; an opaque speck whose
    // two crossings lie within 1e-3 of the floor point does not shadow it, the same speck 1e-2 away does.
    scene::Scene scene = floor_scene();
    scene.lights.push_back(point_light({4, 4, 0}));
    scene::Object glass;
    glass.shape = scene::Sphere{{0, -10, 0}, 1.0};
    glass.texture->pigment.color = {1, 1, 1, 0, 0.5};
    scene.objects.push_back(glass);
    scene::Object speck;
    speck.shape = scene::Sphere{{4e-4, 4e-4, 0}, 2e-4};  // on the shadow ray of (0, 0, 0), off the camera ray
    scene.objects.push_back(speck);
    const double lit = 4.0 / std::sqrt(32.0);
    EXPECT_NEAR(radiance_at(scene, 0.0, 0.0), lit, 1e-9);
    scene.objects[2].shape = scene::Sphere{{1e-2, 1e-2, 0}, 2e-4};
    EXPECT_EQ(radiance_at(scene, 0.0, 0.0), 0.0);
}

TEST(DirectLighting, ShadowlessLightsCauseNoHighlights) {
    scene::Scene scene = floor_scene();
    scene.objects[0].texture->finish.diffuse = 0.0;
    scene.objects[0].texture->finish.phong = 1.0;
    scene.objects[0].texture->finish.specular = 1.0;
    scene.lights.push_back(point_light({0, 2, 0}));  // straight above: both highlights at full strength
    EXPECT_NEAR(radiance_at(scene, 0.0, 0.0), 2.0, 1e-9);
    scene.lights[0].shadowless = true;
    EXPECT_EQ(radiance_at(scene, 0.0, 0.0), 0.0);
}

TEST(DirectLighting, LightBelowTheFloorContributesNothing) {
    scene::Scene scene = floor_scene();
    scene.lights.push_back(point_light({0, -2, 0}));
    EXPECT_EQ(radiance_at(scene, 0.0, 0.0), 0.0);
}

TEST(DirectLighting, AmbientIsLightUnlessRadiosityInA37Scene) {
    scene::Scene scene = floor_scene();
    scene.objects[0].texture->finish.ambient = {0.2, 0.2, 0.2};
    scene.global.ambient_light = {0.5, 0.5, 0.5};
    EXPECT_NEAR(radiance_at(scene, 0, 0), 0.1, 1e-12);
    scene.global.radiosity = scene::RadiositySettings{};
    EXPECT_EQ(radiance_at(scene, 0, 0, GiMode::Off), 0.0);  // POV-Ray 3.7: ambient is not light under radiosity
    scene.version = 3.6;
    EXPECT_NEAR(radiance_at(scene, 0, 0, GiMode::Off), 0.1, 1e-12);
}

TEST(DirectLighting, EmissionAddsPigmentTimesEmission) {
    scene::Scene scene = floor_scene();
    scene.objects[0].texture->pigment.color = {0.5, 0.5, 0.5};
    scene.objects[0].texture->finish.emission = {0.4, 0.4, 0.4};
    EXPECT_NEAR(radiance_at(scene, 0, 0), 0.2, 1e-12);
}

TEST(DirectLighting, FogDimsLightsWithMediaAttenuationAndFillsOnlyHollowObjects) {
    // Black fog of distance 5: the camera ray (1 unit) keeps exp(-1/5); a light 10 units away with
    // media_attenuation is dimmed by exp(-10/5) more (POV-Ray's ComputeShadowMedia).
    scene::Scene scene = floor_scene();
    // The camera where radiance_at's rays start (its default, the origin, lies in the floor, which POV-Ray's plane
    // inside test counts as inside it).
    scene.camera.location = {0.0, 1.0, 0.0};
    scene.lights.push_back(point_light({0, 10, 0}));
    scene::Fog fog;
    fog.distance = 5.0;
    scene.fogs.push_back(fog);
    EXPECT_NEAR(radiance_at(scene, 0.0, 0.0), std::exp(-0.2), 1e-9);
    scene.lights[0].media_attenuation = true;
    EXPECT_NEAR(radiance_at(scene, 0.0, 0.0), std::exp(-2.2), 1e-9);
    scene.lights[0].media_interaction = false;
    EXPECT_NEAR(radiance_at(scene, 0.0, 0.0), std::exp(-0.2), 1e-9);
    scene.lights[0].media_interaction = true;
    // Inside a non-hollow sphere (around the camera, the floor point and the light) no ray passes fog.
    scene::Object shell;
    shell.shape = scene::Sphere{{0, 0, 0}, 100.0};
    scene.objects.push_back(shell);
    EXPECT_NEAR(radiance_at(scene, 0.0, 0.0), 1.0, 1e-9);
    scene.objects[1].interior.hollow = true;
    EXPECT_NEAR(radiance_at(scene, 0.0, 0.0), std::exp(-2.2), 1e-9);
}

TEST(DirectLighting, MissIsBackground) {
    scene::Scene scene;
    scene.background = {0.1, 0.2, 0.3};
    const geometry::SceneGeometry geometry(scene);
    const Integrator integrator(scene, geometry, {});
    TraceContext counters;
    const Vec3 c = integrator.trace_camera_ray({{0, 0, 0}, {0, 0, 1}}, counters);
    EXPECT_EQ(c, (Vec3{0.1, 0.2, 0.3}));
    EXPECT_EQ(counters.rays.camera, 1u);
}

}  // namespace
}  // namespace wardray::lighting
