// Lighting of the material features against analytic answers: crand graininess, double_illuminate, light groups,
// interior textures and projected_through.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "geometry/scene_geometry.h"
#include "lighting/integrator.h"

namespace wardray::lighting {
namespace {

// A white Lambertian floor (diffuse 1, no ambient) at y = 0.
scene::Object white_floor() {
    scene::Object floor;
    floor.shape = scene::Plane{{0, 1, 0}, 0.0};
    floor.texture->pigment.color = {1, 1, 1};
    floor.texture->finish.ambient = {0, 0, 0};
    floor.texture->finish.diffuse = 1.0;
    return floor;
}

scene::Light point_light(const Vec3& p) {
    scene::Light l;
    l.position = p;
    return l;
}

// Radiance (green) seen along a ray from `from` in direction `dir`.
double radiance(const scene::Scene& scene, const Vec3& from, const Vec3& dir) {
    const geometry::SceneGeometry geometry(scene);
    const Integrator integrator(scene, geometry, {});
    TraceContext ctx;
    return integrator.trace_camera_ray(geometry::Ray{from, dir}, ctx).y;
}

// Radiance looking straight down at floor point (x, 0, z) from height 1.
double floor_radiance(const scene::Scene& scene, double x, double z) {
    return radiance(scene, {x, 1.0, z}, {0, -1, 0});
}

TEST(Crand, TakesAUniformRandomPartOfTheDiffuseLightAndRepeats) {
    scene::Scene scene;
    scene.objects.push_back(white_floor());
    scene.objects[0].texture->finish.crand = 0.2;
    scene::Light l = point_light({0, 10, 0});
    l.type = scene::Light::Type::Parallel;
    l.point_at = {0, 0, 0};  // straight down: cos = 1 everywhere
    scene.lights.push_back(l);
    const geometry::SceneGeometry geometry(scene);
    const Integrator integrator(scene, geometry, {});
    TraceContext ctx;
    const int n = 4000;
    double sum = 0.0, lowest = 1.0, highest = 0.0;
    for (int i = 0; i < n; ++i) {
        const geometry::Ray ray{{0.013 * i, 1.0, 0.007 * i}, {0, -1, 0}};
        const double v = integrator.trace_camera_ray(ray, ctx).y;
        sum += v;
        lowest = std::min(lowest, v);
        highest = std::max(highest, v);
        // The same point gives the same value: a render repeats for any thread count.
        EXPECT_EQ(integrator.trace_camera_ray(ray, ctx).y, v);
    }
    // 1 − 0.2·ξ, ξ uniform: mean 0.9 (standard error 0.2/√(12·4000) ≈ 0.0009), range [0.8, 1].
    EXPECT_NEAR(sum / n, 0.9, 0.004);
    EXPECT_GE(lowest, 0.8);
    EXPECT_LT(lowest, 0.81);
    EXPECT_LE(highest, 1.0);
    EXPECT_GT(highest, 0.99);
}

TEST(DoubleIlluminate, LightsASurfaceFromBehind) {
    scene::Scene scene;
    scene.objects.push_back(white_floor());
    scene.lights.push_back(point_light({0, -2, 0}));
    EXPECT_EQ(floor_radiance(scene, 0.0, 0.0), 0.0);
    scene.objects[0].double_illuminate = true;
    EXPECT_NEAR(floor_radiance(scene, 0.0, 0.0), 1.0, 1e-9);
    EXPECT_NEAR(floor_radiance(scene, 2.0, 0.0), 2.0 / std::sqrt(8.0), 1e-9);
}

TEST(LightGroup, GroupLightsLightOnlyTheirObjectsAndGlobalLightsCanBeTurnedOff) {
    scene::Scene scene;
    scene.objects.push_back(white_floor());
    scene.lights.push_back(point_light({0, 2, 0}));  // global
    scene::Light grouped = point_light({0, 2, 0});
    grouped.color = {0.5, 0.5, 0.5};
    grouped.group = 7;
    scene.lights.push_back(grouped);
    EXPECT_NEAR(floor_radiance(scene, 0.0, 0.0), 1.0, 1e-9);  // not in the group
    scene.objects[0].light_groups = {7};
    EXPECT_NEAR(floor_radiance(scene, 0.0, 0.0), 1.5, 1e-9);  // both
    scene.objects[0].no_global_lights = true;
    EXPECT_NEAR(floor_radiance(scene, 0.0, 0.0), 0.5, 1e-9);  // the group's only
}

TEST(InteriorTexture, IsSeenFromInsideOnly) {
    scene::Scene scene;
    scene::Object ball;
    ball.shape = scene::Sphere{{0, 0, 0}, 1.0};
    ball.texture->pigment.color = {0, 0.25, 0};
    ball.texture->finish.ambient = {1, 1, 1};
    ball.texture->finish.diffuse = 0.0;
    scene::Texture inside = ball.texture;
    inside.pigment.color = {0, 0.75, 0};
    ball.interior_texture = {inside};
    scene.objects.push_back(ball);
    EXPECT_NEAR(radiance(scene, {0, 0, -5}, {0, 0, 1}), 0.25, 1e-9);
    EXPECT_NEAR(radiance(scene, {0, 0, 0}, {0, 0, 1}), 0.75, 1e-9);
}

TEST(ProjectedThrough, LightReachesOnlyThroughTheObjectWhichCastsNoShadow) {
    scene::Scene scene;
    scene.objects.push_back(white_floor());
    scene::Light l = point_light({0, 2, 0});
    scene::Object window;
    window.shape = scene::Sphere{{0, 1, 0}, 0.25};
    l.projected_through = {window};
    scene.lights.push_back(l);
    EXPECT_NEAR(floor_radiance(scene, 0.0, 0.0), 1.0, 1e-9);  // straight through the sphere
    EXPECT_EQ(floor_radiance(scene, 1.0, 0.0), 0.0);          // the sphere is not on the way
    // An object between the point and the window still casts its shadow; one beyond the window does not.
    // (Seen from the side, so the blockers are not in view.)
    const Vec3 eye{1.0, 0.2, 0.0};
    const Vec3 to_origin = normalize(Vec3{-1.0, -0.2, 0.0});
    EXPECT_NEAR(radiance(scene, eye, to_origin), 1.0, 1e-9);
    scene::Object blocker = white_floor();
    blocker.shape = scene::Sphere{{0, 0.5, 0}, 0.1};
    scene.objects.push_back(blocker);
    EXPECT_EQ(radiance(scene, eye, to_origin), 0.0);
    scene.objects.back().shape = scene::Sphere{{0, 1.6, 0}, 0.1};
    EXPECT_NEAR(radiance(scene, eye, to_origin), 1.0, 1e-9);
}

}  // namespace
}  // namespace wardray::lighting
