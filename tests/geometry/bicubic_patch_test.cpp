// Tests of bicubic_patch tessellation: vertices on the Bézier surface with its normals, POV-Ray's subdivision
// rules (steps, flatness, measured after the transforms), and hits on the triangles.
#include <gtest/gtest.h>

#include <cmath>

#include "geometry/instance.h"
#include "parser/parse.h"
#include "test_util.h"

namespace wardray::geometry {
namespace {

using test::make_object;

// A height-field patch: x = 3u, y = 3v, z from the heights (Bézier curves reproduce linear functions).
scene::BicubicPatch height_patch(int u_steps, int v_steps, double flatness) {
    scene::BicubicPatch p;
    p.type = 1;
    p.u_steps = u_steps;
    p.v_steps = v_steps;
    p.flatness = flatness;
    const double h[4][4] = {{0, 1, 0.5, 0}, {0.3, 2, 1, -0.5}, {0, 1.5, 0.2, 0.4}, {-0.2, 0.1, 0.8, 0}};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) p.points[4 * i + j] = {double(i), double(j), h[i][j]};
    return p;
}

double bernstein(int i, double t) {
    const double c[4] = {1, 3, 3, 1};
    return c[i] * std::pow(t, i) * std::pow(1 - t, 3 - i);
}

double height(const scene::BicubicPatch& p, double u, double v) {
    double z = 0.0;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) z += bernstein(i, u) * bernstein(j, v) * p.points[4 * i + j].z;
    return z;
}

std::size_t face_count(const ShapeInstance& inst) { return std::get<MeshShape>(inst.shape()).faces().size(); }

TEST(BicubicPatch, StepsHalveEachDirectionAndVerticesLieOnTheSurface) {
    const scene::BicubicPatch p = height_patch(3, 2, 0.0);
    const auto inst = ShapeInstance::create(make_object(p), 0);
    ASSERT_TRUE(inst);
    EXPECT_EQ(face_count(*inst), 8u * 4u * 2u);
    // A vertical ray through a corner of a subpatch meets the surface there, with the patch's own normal.
    for (int i = 0; i <= 8; i += 3)
        for (int j = 1; j <= 4; j += 2) {
            const double u = i / 8.0, v = j / 4.0;
            const auto hit = inst->nearest({3 * u + 1e-9, 3 * v + 1e-9, 10}, {0, 0, -1}, 0.0, 1e30);
            ASSERT_TRUE(hit) << u << " " << v;
            EXPECT_NEAR(10 - hit->t, height(p, u, v), 1e-6);
            const double e = 1e-6;
            const double zx = (height(p, u + e, v) - height(p, u - e, v)) / (2 * e) / 3.0;
            const double zy = (height(p, u, v + e) - height(p, u, v - e)) / (2 * e) / 3.0;
            const Vec3 exact = normalize(Vec3{-zx, -zy, 1});
            EXPECT_NEAR(std::fabs(dot(hit->normal, exact)), 1.0, 1e-6) << u << " " << v;
        }
}

TEST(BicubicPatch, FlatSubpatchesStopTheSubdivision) {
    // A flat patch is two triangles at any depth; a curved one is too when flatness allows everything.
    scene::BicubicPatch flat = height_patch(4, 4, 0.01);
    for (Vec3& q : flat.points) q.z = 0.25 * q.x - 0.5 * q.y;
    const auto plane = ShapeInstance::create(make_object(flat), 0);
    ASSERT_TRUE(plane);
    EXPECT_EQ(face_count(*plane), 2u);
    const auto coarse = ShapeInstance::create(make_object(height_patch(4, 4, 1e9)), 0);
    ASSERT_TRUE(coarse);
    EXPECT_EQ(face_count(*coarse), 2u);
    const auto fine = ShapeInstance::create(make_object(height_patch(4, 4, 0.01)), 0);
    ASSERT_TRUE(fine);
    EXPECT_GT(face_count(*fine), 2u);
    EXPECT_LE(face_count(*fine), 512u);
}

TEST(BicubicPatch, FlatnessIsMeasuredAfterTheTransforms) {
    // POV-Ray tessellates the transformed control points: a larger patch needs more subpatches to be as flat.
    const std::string points =
        "<0,0,0>,<1,0,1>,<2,0,0.5>,<3,0,0>, <0,1,0.3>,<1,1,2>,<2,1,1>,<3,1,-0.5>,"
        " <0,2,0>,<1,2,1.5>,<2,2,0.2>,<3,2,0.4>, <0,3,-0.2>,<1,3,0.1>,<2,3,0.8>,<3,3,0>";
    auto faces = [&](const std::string& modifiers) {
        parser::ParseOptions options;
        const auto r = parser::parse_string(
            "union { bicubic_patch { type 1 flatness 0.05 u_steps 6 v_steps 6 " + points + " } sphere { 0, 1 } " +
                modifiers + " }",
            "patch.pov", options);
        EXPECT_TRUE(r.ok());
        // A union of one object may come back as that object, its transform carried over.
        const scene::Object& top = r.scene->objects.at(0);
        const auto* csg = std::get_if<scene::Csg>(&top.shape);
        const auto inst = ShapeInstance::create(csg ? csg->children.at(0) : top, 0);
        return inst ? face_count(*inst) : 0u;
    };
    const std::size_t small = faces(""), large = faces("scale 20");
    EXPECT_GT(small, 2u);
    EXPECT_GT(large, small);
    EXPECT_EQ(faces("translate 5 rotate 30*y"), small);
}

// uv_mapping: a hit carries the patch's (u, v), blended from its triangle's corners as POV-Ray's
// intersect_subpatch does, and uv_vectors map it bilinearly to texture coordinates (POV-Ray's Compute_Texture_UV
// of the point (v, u)). On a patch whose x and y are linear in (u, v) the parameters are exactly (x / 3, y / 3).
TEST(BicubicPatch, HitsCarryThePatchParametersAndUvVectorsMapThem) {
    scene::BicubicPatch p = height_patch(3, 3, 0.0);
    const auto inst = ShapeInstance::create(make_object(p), 0);
    ASSERT_TRUE(inst);
    const MeshShape& mesh = std::get<MeshShape>(inst->shape());
    int checked = 0;
    for (double x : {0.4, 1.3, 2.05, 2.9})
        for (double y : {0.2, 1.1, 2.7}) {
            const Vec3 origin{x, y, 10.0}, dir{0.0, 0.0, -1.0};
            for (std::size_t f = 0; f < mesh.faces().size(); ++f) {
                if (!mesh.intersect_face({origin, dir}, f, 0.0, INFINITY)) continue;
                const auto hit = inst->face_hit(origin, dir, f, 0.0, INFINITY);
                ASSERT_TRUE(hit && hit->has_params);
                EXPECT_NEAR(hit->params.x, x / 3.0, 1e-12);
                EXPECT_NEAR(hit->params.y, y / 3.0, 1e-12);
                ++checked;
                break;
            }
        }
    EXPECT_EQ(checked, 12);
    // POV-Ray's default uv_vectors <0,0> <1,0> <1,1> <0,1> give (v, u); others blend bilinearly.
    const Vec3 params{0.25, 0.75, 0.0};
    const Vec3 uv = bicubic_patch_uv(p, params);
    EXPECT_DOUBLE_EQ(uv.x, 0.75);
    EXPECT_DOUBLE_EQ(uv.y, 0.25);
    p.uv_vectors = {{{1.0, 0.0, 0.0}, {3.0, 0.0, 0.0}, {3.0, 4.0, 0.0}, {1.0, 2.0, 0.0}}};
    const Vec3 mapped = bicubic_patch_uv(p, params);
    // (s, t) = (v, u) = (0.75, 0.25): rows (1,0)->(3,0) at s gives (2.5, 0), (1,2)->(3,4) gives (2.5, 3.5).
    EXPECT_DOUBLE_EQ(mapped.x, 2.5);
    EXPECT_DOUBLE_EQ(mapped.y, 0.25 * 3.5);
}

// The parser keeps uv_vectors and reads the patch's other keywords after them.
TEST(BicubicPatch, UvVectorsAreReadWithoutAWarning) {
    parser::ParseOptions options;
    const auto r = parser::parse_string(
        "global_settings { assumed_gamma 1 }\n"
        "bicubic_patch { type 1 uv_vectors <0,0> <2,0> <2,1> <0,1> flatness 0.01 u_steps 2 v_steps 2 "
        "<0,0,0>,<1,0,0>,<2,0,0>,<3,0,0>, <0,1,0>,<1,1,1>,<2,1,1>,<3,1,0>, <0,2,0>,<1,2,1>,<2,2,1>,<3,2,0>, "
        "<0,3,0>,<1,3,0>,<2,3,0>,<3,3,0> uv_mapping pigment { checker } }",
        "patch.pov", options);
    ASSERT_TRUE(r.ok());
    for (const auto& d : r.diagnostics) EXPECT_NE(d.severity, Severity::Warning) << d.message;
    const auto& patch = std::get<scene::BicubicPatch>(r.scene->objects.at(0).shape);
    EXPECT_EQ(patch.uv_vectors[1], (Vec3{2.0, 0.0, 0.0}));
    EXPECT_EQ(patch.uv_vectors[2], (Vec3{2.0, 1.0, 0.0}));
    EXPECT_DOUBLE_EQ(patch.flatness, 0.01);
    EXPECT_EQ(patch.u_steps, 2);
}

}  // namespace
}  // namespace wardray::geometry
