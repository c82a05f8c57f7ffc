// Cameras: each projection's rays against the geometry POV-Ray's CreateCameraRay gives them, and focal blur.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "camera/camera.h"
#include "camera/focal_blur.h"

namespace wardray::camera {
namespace {

constexpr double kPi = std::numbers::pi;

scene::Camera looking_along_z(scene::Camera::Type type) {
    scene::Camera c;
    c.type = type;
    c.location = {0.0, 0.0, 0.0};
    c.direction = {0.0, 0.0, 1.0};
    c.right = {1.0, 0.0, 0.0};
    c.up = {0.0, 1.0, 0.0};
    return c;
}

void expect_near(const Vec3& a, const Vec3& b) {
    EXPECT_NEAR(a.x, b.x, 1e-9);
    EXPECT_NEAR(a.y, b.y, 1e-9);
    EXPECT_NEAR(a.z, b.z, 1e-9);
}

TEST(Cameras, FisheyeAngleFromTheAxisGrowsWithTheRadius) {
    scene::Camera c = looking_along_z(scene::Camera::Type::Fisheye);
    c.angle = 180.0;
    const CameraModel cam(c, 100, 100);
    expect_near(cam.ray(50.0, 50.0)->direction, {0.0, 0.0, 1.0});
    // The right edge of the circle looks 90 degrees off the axis, half way out 45 degrees.
    expect_near(cam.ray(100.0, 50.0)->direction, {1.0, 0.0, 0.0});
    expect_near(cam.ray(50.0, 25.0)->direction, {0.0, std::sqrt(0.5), std::sqrt(0.5)});
    EXPECT_FALSE(cam.ray(2.0, 2.0).has_value());  // outside the circle no ray is traced
}

TEST(Cameras, PanoramicSweepsHalfATurnAcross) {
    const CameraModel cam(looking_along_z(scene::Camera::Type::Panoramic), 200, 100);
    expect_near(cam.ray(0.0, 50.0)->direction, {-1.0, 0.0, 0.0});
    expect_near(cam.ray(100.0, 50.0)->direction, {0.0, 0.0, 1.0});
    // A quarter of the way up from the centre the elevation is 45 degrees: tan = 1.
    expect_near(cam.ray(100.0, 25.0)->direction, normalize(Vec3{0.0, 1.0, 1.0}));
}

TEST(Cameras, SphericalMapsLongitudeAndLatitude) {
    scene::Camera c = looking_along_z(scene::Camera::Type::Spherical);
    c.h_angle = 360.0;
    c.v_angle = 180.0;
    const CameraModel cam(c, 360, 180);
    // 90 pixels right of the centre is 90 degrees of longitude; 45 pixels up, 45 degrees of latitude.
    const Vec3 side = cam.ray(270.0, 90.0)->direction;
    EXPECT_NEAR(std::fabs(side.x), 1.0, 1e-9);
    EXPECT_NEAR(side.z, 0.0, 1e-9);
    expect_near(cam.ray(180.0, 45.0)->direction, {0.0, std::sqrt(0.5), std::sqrt(0.5)});
}

TEST(Cameras, UltraWideAngleTurnsByTheAngleAcross) {
    scene::Camera c = looking_along_z(scene::Camera::Type::UltraWideAngle);
    c.angle = 180.0;
    const CameraModel cam(c, 100, 100);
    // The right edge is half the angle, 90 degrees, off the axis.
    expect_near(cam.ray(100.0, 50.0)->direction, {1.0, 0.0, 0.0});
}

TEST(Cameras, CylinderThreeMovesTheOriginUpTheAxis) {
    scene::Camera c = looking_along_z(scene::Camera::Type::Cylinder);
    c.cylinder = 3;
    c.angle = 90.0;
    c.up = {0.0, 2.0, 0.0};
    const CameraModel cam(c, 100, 100);
    const geometry::Ray top = *cam.ray(50.0, 0.0);
    expect_near(top.origin, {0.0, 1.0, 0.0});  // half the up vector's length
    expect_near(top.direction, {0.0, 0.0, 1.0});
    const geometry::Ray right = *cam.ray(100.0, 50.0);
    expect_near(right.direction, {std::sin(kPi / 4.0), 0.0, std::cos(kPi / 4.0)});
}

TEST(Cameras, PixelCentresAreAtPovRaysImageCoordinatesToTheBit) {
    // POV-Ray compat (CreateCameraRay): y0 = ((height - 1) - (y - 0.5)) / height - 0.5 for pixel row y. For row 4 of
    // 90 that is 0.44999999999999996, where 0.5 - 4.5 / 90 would give 0.45: interior/atten2.pov's orthographic rows
    // lie in its prisms' cap planes, so such a bit decides a hit.
    scene::Camera c = looking_along_z(scene::Camera::Type::Orthographic);
    const CameraModel cam(c, 120, 90);
    const auto ray = cam.ray(60.5, 4.5);
    ASSERT_TRUE(ray);
    EXPECT_EQ(ray->origin.y, 0.44999999999999996);
    EXPECT_EQ(ray->origin.x, 0.004166666666666652);  // x0 = 60.5 / 120 - 0.5
    // The direction scaled by the reciprocal of its length (VNormalize), not divided by it.
    scene::Camera p = looking_along_z(scene::Camera::Type::Perspective);
    const CameraModel persp(p, 120, 90);
    const auto r = persp.ray(0.5, 0.5);
    ASSERT_TRUE(r);
    const double x0 = 0.5 / 120 - 0.5, y0 = (89 - (0.5 - 1.0)) / 90 - 0.5;
    const double inv = 1.0 / std::sqrt(x0 * x0 + y0 * y0 + 1.0);
    EXPECT_EQ(r->direction.x, x0 * inv);
    EXPECT_EQ(r->direction.y, y0 * inv);
    EXPECT_EQ(r->direction.z, 1.0 * inv);
}

TEST(Cameras, FocalBlurKeepsThePointInFocusFixed) {
    scene::Camera c = looking_along_z(scene::Camera::Type::Perspective);
    c.aperture = 2.0;
    c.blur_samples = 10;
    c.focal_distance = 5.0;
    const CameraModel cam(c, 100, 100);
    for (const double lx : {-0.5, 0.0, 0.3}) {
        const geometry::Ray r = *cam.ray(70.0, 40.0, lx, 0.2);
        // Every lens point's ray passes through the pinhole ray's point at depth 5.
        const Vec3 focus = Vec3{0.2, 0.1, 1.0} * 5.0;
        const Vec3 to_focus = focus - r.origin;
        expect_near(normalize(to_focus), r.direction);
    }
}

TEST(Cameras, InverseChiSquareMatchesClosedForms) {
    // Two degrees of freedom: P(X > x) = exp(-x / 2); one: P(X > 2.705543) = 0.1.
    EXPECT_NEAR(inverse_chi_square_complement(2.0, 0.9), -2.0 * std::log(0.9), 1e-9);
    EXPECT_NEAR(inverse_chi_square_complement(2.0, 0.05), -2.0 * std::log(0.05), 1e-9);
    EXPECT_NEAR(inverse_chi_square_complement(1.0, 0.1), 2.705543, 1e-5);
}

TEST(Cameras, FocalBlurIsTheSameForTheSamePosition) {
    scene::Camera c = looking_along_z(scene::Camera::Type::Perspective);
    c.aperture = 1.0;
    c.blur_samples = 20;
    c.variance = 0.0;
    const CameraModel cam(c, 100, 100);
    const FocalBlur blur(c);
    int rays = 0;
    auto trace = [&](const geometry::Ray& r) {
        ++rays;
        return Vec3{r.origin.x, r.origin.y, 1.0};
    };
    const Vec3 a = blur.sample(cam, trace, 10.5, 20.5);
    EXPECT_EQ(rays, 20);  // variance 0: every sample is taken
    const Vec3 b = blur.sample(cam, trace, 10.5, 20.5);
    EXPECT_EQ(a, b);
    // The lens points average to about the lens centre.
    EXPECT_NEAR(a.x, 0.0, 0.1);
    EXPECT_NEAR(a.y, 0.0, 0.1);
}

TEST(Cameras, FocalBlurSeedMovesTheSamplesAndZeroKeepsThem) {
    scene::Camera c = looking_along_z(scene::Camera::Type::Perspective);
    c.aperture = 1.0;
    c.blur_samples = 20;
    c.variance = 0.0;
    const CameraModel cam(c, 100, 100);
    auto trace = [](const geometry::Ray& r) { return Vec3{r.origin.x, r.origin.y, 1.0}; };
    const Vec3 unseeded = FocalBlur(c).sample(cam, trace, 10.5, 20.5);
    EXPECT_EQ(FocalBlur(c, 0).sample(cam, trace, 10.5, 20.5), unseeded);
    const Vec3 one = FocalBlur(c, 1).sample(cam, trace, 10.5, 20.5);
    EXPECT_NE(one, unseeded);
    EXPECT_NE(one, FocalBlur(c, 2).sample(cam, trace, 10.5, 20.5));
    EXPECT_EQ(one, FocalBlur(c, 1).sample(cam, trace, 10.5, 20.5));
}

// A mesh camera of two unit squares' worth of triangles in the z = 0 plane, each face one pixel.
scene::Camera mesh_camera(int distribution, int rays, int meshes) {
    scene::Camera c = looking_along_z(scene::Camera::Type::MeshCamera);
    c.location = {0.0, 0.0, 0.25};
    c.mesh_camera.distribution = distribution;
    c.mesh_camera.rays_per_pixel = rays;
    std::vector<scene::MeshCameraSpec::PlacedMesh> placed;
    for (int m = 0; m < meshes; ++m) {
        scene::MeshCameraSpec::PlacedMesh pm;
        // Faces wound so that POV-Ray's normal (P3 − P1) × (P2 − P1) is +z: four faces, one per pixel of 2 × 2.
        for (int i = 0; i < 4; ++i) {
            const double x = i;
            pm.mesh.vertices.mut().insert(pm.mesh.vertices.mut().end(), {{x, 0, 0}, {x, 1, 0}, {x + 1, 0, 0}});
            scene::Mesh::Face f;
            f.v = {3 * i, 3 * i + 1, 3 * i + 2};
            pm.mesh.faces.push_back(f);
        }
        pm.transform = Transform::translation({0.0, 10.0 * m, 0.0});
        placed.push_back(pm);
    }
    c.mesh_camera.meshes = std::make_shared<const std::vector<scene::MeshCameraSpec::PlacedMesh>>(placed);
    return c;
}

TEST(Cameras, MeshCameraRaysLeaveFaceCentroidsAlongTheirNormals) {
    const CameraModel cam(mesh_camera(0, 1, 1), 2, 2);
    // Pixel (1, 1): POV-Ray's y − 0.5 makes row 1 use face row 0, so face 1; its centroid is (4/3, 1/3, 0),
    // moved by location.z = 0.25 along the normal.
    const auto r = cam.ray(1.5, 1.5);
    ASSERT_TRUE(r);
    expect_near(r->origin, {4.0 / 3.0, 1.0 / 3.0, 0.25});
    expect_near(r->direction, {0.0, 0.0, 1.0});
    expect_near(cam.ray(0.5, 0.5)->origin, {1.0 / 3.0, 1.0 / 3.0, 0.25});
    // Row 1 of the second column is face 1 too; a direction with negative z reverses the ray.
    scene::Camera back = mesh_camera(0, 1, 1);
    back.direction = {0.0, 0.0, -1.0};
    const CameraModel reversed(back, 2, 2);
    expect_near(reversed.ray(1.5, 0.5)->direction, {0.0, 0.0, -1.0});
    expect_near(reversed.ray(1.5, 0.5)->origin, {4.0 / 3.0, 1.0 / 3.0, 0.25});
}

TEST(Cameras, MeshCameraDistributions) {
    // Distribution 0 with two rays: the second ray leaves the second (translated) mesh.
    const CameraModel two(mesh_camera(0, 2, 2), 2, 2);
    EXPECT_EQ(two.rays_per_pixel(), 2);
    expect_near(two.ray(0.5, 0.5, 1)->origin, {1.0 / 3.0, 10.0 + 1.0 / 3.0, 0.25});
    // Distribution 1: the faces of both meshes in one sequence; later samples find no face.
    const CameraModel summed(mesh_camera(1, 2, 2), 4, 2);
    expect_near(summed.ray(0.5, 2.5)->origin, {1.0 / 3.0, 10.0 + 1.0 / 3.0, 0.25});
    EXPECT_FALSE(summed.ray(0.5, 0.5, 1));
    // Distribution 2: side by side, the face index counted from the image's left edge.
    const CameraModel side(mesh_camera(2, 1, 2), 4, 1);
    expect_near(side.ray(2.5, 0.5)->origin, {2.0 + 1.0 / 3.0, 10.0 + 1.0 / 3.0, 0.25});
    // Beyond the faces no ray.
    const CameraModel big(mesh_camera(0, 1, 1), 4, 4);
    EXPECT_FALSE(big.ray(0.5, 3.5));
}

TEST(Cameras, MeshCameraUvDistributionFindsThePointOfEachUv) {
    scene::Camera c = mesh_camera(3, 1, 1);
    std::vector<scene::MeshCameraSpec::PlacedMesh> placed = *c.mesh_camera.meshes;
    scene::Mesh& m = placed[0].mesh;
    // One square face pair spanning uv [0, 1]², vertices (0..2, 0..2) in x, y.
    m.vertices = {{0, 0, 0}, {0, 2, 0}, {2, 2, 0}, {2, 0, 0}};
    m.uvs = {{0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}};
    scene::Mesh::Face a, b;
    a.v = a.uv = {0, 1, 2};
    b.v = b.uv = {0, 2, 3};
    m.faces = {a, b};
    c.mesh_camera.meshes = std::make_shared<const std::vector<scene::MeshCameraSpec::PlacedMesh>>(placed);
    const CameraModel cam(c, 10, 10);
    // Column 3 of 10: u = 3/10; row 4: v = 1 − 4/10 (POV-Ray samples the pixel's upper-left corner in uv).
    const auto r = cam.ray(3.5, 4.5);
    ASSERT_TRUE(r);
    expect_near(r->origin, {0.6, 1.2, 0.25});
    expect_near(r->direction, {0.0, 0.0, 1.0});
}

}  // namespace
}  // namespace wardray::camera
