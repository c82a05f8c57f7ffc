// Mesh surfaces: uv coordinates interpolated across a face, and the corner weights of a three-texture triangle.
#include <gtest/gtest.h>

#include "lighting/mesh_texture.h"

namespace wardray::lighting {
namespace {

scene::Mesh one_triangle() {
    scene::Mesh m;
    m.vertices = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}};
    m.uvs = {{0.5, 0.5, 0}, {1.5, 0.5, 0}, {0.5, 2.5, 0}};
    scene::Mesh::Face f;
    f.v = {0, 1, 2};
    f.uv = {0, 1, 2};
    m.faces = {f};
    return m;
}

TEST(MeshTexture, UvIsTheBarycentricMixOfTheCorners) {
    const scene::Mesh m = one_triangle();
    geometry::Hit hit;
    hit.face = 0;
    hit.bary_u = 0.25;  // weight of the second corner
    hit.bary_v = 0.5;   // weight of the third
    const Vec3 uv = mesh_uv(m, hit);
    EXPECT_DOUBLE_EQ(uv.x, 0.25 * 0.5 + 0.25 * 1.5 + 0.5 * 0.5);
    EXPECT_DOUBLE_EQ(uv.y, 0.25 * 0.5 + 0.25 * 0.5 + 0.5 * 2.5);
    EXPECT_EQ(uv.z, 0.0);
    // Corners without uv_vectors sit at (0, 0).
    scene::Mesh bare = m;
    bare.faces[0].uv = {-1, -1, -1};
    EXPECT_EQ(mesh_uv(bare, hit), (Vec3{}));
}

TEST(MeshTexture, SmoothTIsTheFractionFromTheCornerToTheOppositeSide) {
    const Vec3 a{0, 0, 0}, b{2, 0, 0}, c{0, 2, 0};
    EXPECT_NEAR(smooth_t(a, a, b, c), 0.0, 1e-12);
    EXPECT_NEAR(smooth_t({1, 1, 0}, a, b, c), 1.0, 1e-12);       // on the opposite side
    EXPECT_NEAR(smooth_t({0.5, 0.5, 0}, a, b, c), 0.5, 1e-12);   // half way there
    EXPECT_NEAR(smooth_t({0.5, 0.25, 0}, a, b, c), 0.375, 1e-12);
}

TEST(MeshTexture, ThreeTexturesWeighTheirCorners) {
    scene::Mesh m = one_triangle();
    m.textures.resize(3);
    m.faces[0].tex = {0, 1, 2};
    scene::Object o;
    o.transform = Transform::translation({10, 0, 0});
    geometry::Hit hit;
    hit.face = 0;
    hit.position = {10.0 + 2.0 / 3.0, 2.0 / 3.0, 0.0};  // the centroid, in world space
    std::array<const scene::Texture*, 3> t{};
    std::array<double, 3> w{};
    ASSERT_EQ(mesh_face_textures(m, o, hit, t, w), 3);
    for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(t[k], &m.textures[k]);
        EXPECT_NEAR(w[k], 1.0 / 3.0, 1e-6);
    }
    hit.position = {10.0, 0.0, 0.0};  // at the first corner
    ASSERT_EQ(mesh_face_textures(m, o, hit, t, w), 3);
    EXPECT_NEAR(w[0], 1.0, 1e-6);
    m.faces[0].tex = {2, -1, -1};
    ASSERT_EQ(mesh_face_textures(m, o, hit, t, w), 1);
    EXPECT_EQ(t[0], &m.textures[2]);
}

}  // namespace
}  // namespace wardray::lighting
