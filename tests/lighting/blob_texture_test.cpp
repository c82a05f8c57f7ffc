// Blob surfaces: component textures weighted by the components' densities, read from a scene and rendered.
#include <gtest/gtest.h>

#include <string>

#include "../parser/test_util.h"
#include "geometry/scene_geometry.h"
#include "lighting/blob_texture.h"
#include "lighting/integrator.h"

namespace wardray::lighting {
namespace {

// Two components one unit either side of the blob's centre (moved to x = 10 in the first test), red on the left;
// the right one blue or, without a texture of its own, showing the blob's.
const std::string k_two_components =
    "sphere { <-1, 0, 0>, 1.5, 1 pigment { rgb <1, 0, 0> } finish { ambient 1 diffuse 0 } } ";

TEST(BlobTexture, ComponentsWeighTheirTexturesByDensity) {
    const scene::Scene s = parser::test::parse_ok(
        "blob { threshold 0.5 " + k_two_components + "sphere { <1, 0, 0>, 1.5, 1 } pigment { rgb <0, 1, 0> } "
        "translate <10, 0, 0> }");
    ASSERT_EQ(s.objects.size(), 1u);
    const auto& blob = std::get<scene::Blob>(s.objects[0].shape);
    ASSERT_EQ(blob.textures.size(), 1u);
    WeightedTextures w;
    // Half way between the centres the two densities are equal.
    blob_textures(blob, *s.objects[0].texture, {10.0, 0.0, 0.0}, w);
    ASSERT_EQ(w.size(), 2u);
    EXPECT_NEAR(w[0].second, 0.5, 1e-12);
    EXPECT_NEAR(w[1].second, 0.5, 1e-12);
    // At the left centre only the left component reaches: its own red texture alone, moved with the blob.
    blob_textures(blob, *s.objects[0].texture, {9.0, 0.0, 0.0}, w);
    ASSERT_EQ(w.size(), 1u);
    EXPECT_EQ(w[0].first->pigment.color.r, 1.0);
    EXPECT_NEAR(w[0].second, 1.0, 1e-12);
    // At the right centre, the blob's own green.
    blob_textures(blob, *s.objects[0].texture, {11.0, 0.0, 0.0}, w);
    ASSERT_EQ(w.size(), 1u);
    EXPECT_EQ(w[0].first, &s.objects[0].texture.get());
}

TEST(BlobTexture, ACameraRaySeesTheBlendedColour) {
    const scene::Scene scene = parser::test::parse_ok(
        "blob { threshold 0.5 " + k_two_components +
        "sphere { <1, 0, 0>, 1.5, 1 pigment { rgb <0, 0, 1> } finish { ambient 1 diffuse 0 } } }");
    EXPECT_TRUE(scene.warnings.empty());
    const geometry::SceneGeometry geometry(scene);
    const Integrator integrator(scene, geometry, {});
    TraceContext ctx;
    // Along x = 0 the components weigh the same: half red, half blue.
    const Vec3 c = integrator.trace_camera_ray(geometry::Ray{{0.0, 0.0, -5.0}, {0.0, 0.0, 1.0}}, ctx);
    EXPECT_NEAR(c.x, 0.5, 1e-9);
    EXPECT_NEAR(c.y, 0.0, 1e-9);
    EXPECT_NEAR(c.z, 0.5, 1e-9);
}

}  // namespace
}  // namespace wardray::lighting
