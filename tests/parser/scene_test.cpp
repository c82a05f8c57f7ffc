// Tests of scene statements: camera resolution, lights, objects, textures, unions, global settings, warnings.
#include <cmath>
#include <map>
#include <string>

#include "parser/keywords.h"
#include "tests/parser/test_util.h"

namespace wardray::parser {
namespace {

using test::parse_ok;

void expect_vec(const Vec3& a, const Vec3& b, double tol = 1e-12) {
    EXPECT_NEAR(a.x, b.x, tol);
    EXPECT_NEAR(a.y, b.y, tol);
    EXPECT_NEAR(a.z, b.z, tol);
}

TEST(Camera, DefaultsWithoutCameraStatement) {
    const Scene s = parse_ok("");
    expect_vec(s.camera.location, {0, 0, 0});
    expect_vec(s.camera.direction, {0, 0, 1});
    expect_vec(s.camera.right, {1.33, 0, 0});
    expect_vec(s.camera.up, {0, 1, 0});
}

TEST(Camera, LookAtStraightAhead) {
    const Scene s = parse_ok("camera { location <0, 0, -5> look_at <0, 0, 0> }");
    expect_vec(s.camera.location, {0, 0, -5});
    expect_vec(s.camera.direction, {0, 0, 1});
    expect_vec(s.camera.right, {1.33, 0, 0});
    expect_vec(s.camera.up, {0, 1, 0});
}

TEST(Camera, AngleThenLookAtHandComputed) {
    // angle 90: |direction| = 0.5 * 1.33 / tan(45 deg) = 0.665; look_at turns it toward <1,0,1>.
    const Scene s = parse_ok("camera { location <0, 0, 0> look_at <1, 0, 1> angle 90 }");
    const double a = 1.0 / std::sqrt(2.0);
    expect_vec(s.camera.direction, {0.665 * a, 0, 0.665 * a});
    expect_vec(s.camera.right, {1.33 * a, 0, -1.33 * a});
    expect_vec(s.camera.up, {0, 1, 0});
}

TEST(Camera, LookAtNormalisesAsPovRayDoes) {
    // POV-Ray compat (VNormalize): the look_at direction is scaled by the reciprocal of its length. For <3, 5, 7>
    // that gives a z of 0.7683498199278325 where dividing by the length gives the next double down.
    const Scene s = parse_ok("camera { location <0, 0, 0> direction z look_at <3, 5, 7> }");
    EXPECT_EQ(s.camera.direction.z, 0.7683498199278325);
    EXPECT_NE(s.camera.direction.z, 7.0 / std::sqrt(83.0));
}

TEST(Camera, LookAtFromAboveKeepsLengthsAndSky) {
    const Scene s = parse_ok("camera { location <0, 3, -4> direction 2*z up 0.75*y right x look_at 0 }");
    // d = (0, -3, 4) / 5; right = sky x d normalized = x; up = d x right.
    expect_vec(s.camera.direction, {0, -1.2, 1.6});
    expect_vec(s.camera.right, {1, 0, 0});
    expect_vec(s.camera.up, {0, 0.75 * 0.8, 0.75 * 0.6});
}

TEST(Camera, SkyRollsTheCamera) {
    const Scene s = parse_ok("camera { location <0, 0, -1> sky <1, 0, 0> look_at 0 }");
    // right = sky x d = x cross z = -y; up = d x right = z cross -y = x.
    expect_vec(s.camera.right, {0, -1.33, 0});
    expect_vec(s.camera.up, {1, 0, 0});
}

TEST(Camera, RightHandedRightVectorIsKept) {
    const Scene s = parse_ok("camera { location <0, 0, 10> right <-1.33, 0, 0> look_at <0, 0, 0> }");
    expect_vec(s.camera.direction, {0, 0, -1});
    // (up x direction) . right < 0: the right vector keeps pointing the other way from sky x direction.
    expect_vec(s.camera.right, {1.33, 0, 0});
    expect_vec(s.camera.up, {0, 1, 0});
}

TEST(Camera, ItemOrderDoesNotMatterAndTransformsComeLast) {
    const Scene a = parse_ok("camera { look_at 0 angle 60 location <0, 0, -5> rotate y*90 }");
    const Scene b = parse_ok("camera { location <0, 0, -5> angle 60 look_at 0 rotate y*90 }");
    expect_vec(a.camera.location, {-5, 0, 0});
    expect_vec(a.camera.location, b.camera.location);
    expect_vec(a.camera.direction, b.camera.direction);
    const double len = 0.5 * 1.33 / std::tan(30.0 * std::acos(-1.0) / 180.0);
    expect_vec(a.camera.direction, {len, 0, 0});
    expect_vec(a.camera.right, {0, 0, -1.33});
}

TEST(Camera, Orthographic) {
    Scene s = parse_ok("camera { orthographic location <0, 0, -10> look_at 0 }");
    EXPECT_EQ(s.camera.type, Camera::Type::Orthographic);
    expect_vec(s.camera.right, {13.3, 0, 0});
    expect_vec(s.camera.up, {0, 10, 0});
    s = parse_ok("camera { orthographic location <0, 0, -10> look_at 0 angle 90 }");
    expect_vec(s.camera.right, {20, 0, 0});
    expect_vec(s.camera.up, {0, 20 / 1.33, 0}, 1e-9);
    s = parse_ok("camera { orthographic location <0, 0, -10> right 4*x up 3*y look_at 0 }");
    expect_vec(s.camera.right, {4, 0, 0});
    expect_vec(s.camera.up, {0, 3, 0});
}

TEST(Camera, OrthographicWithoutLookAtIsSizedFromTheDefaultLookAt) {
    // POV-Ray's default look_at is <0, 0, 1>, not one unit ahead of the location: its distance sizes the view.
    Scene s = parse_ok("camera { orthographic location <3, 4, -10> }");
    const double k = std::sqrt(3.0 * 3.0 + 4.0 * 4.0 + 11.0 * 11.0);
    expect_vec(s.camera.right, {1.33 * k, 0, 0}, 1e-9);
    expect_vec(s.camera.up, {0, k, 0}, 1e-9);
    expect_vec(s.camera.direction, {0, 0, 1});
    s = parse_ok("camera { orthographic location <0, 0, 1> }");  // at the default look_at: unscaled
    expect_vec(s.camera.right, {1.33, 0, 0});
}

TEST(Camera, DeclaredCamera) {
    const Scene s = parse_ok("#declare Cam = camera { location <0, 0, -5> }\ncamera { Cam look_at <0, 0, 0> }");
    expect_vec(s.camera.location, {0, 0, -5});
}

TEST(Light, AllFields) {
    const Scene s = parse_ok(R"(
        light_source { <1, 2, 3>, rgb <0.5, 0.6, 0.7> }
        light_source { <0, 10, 0> color rgb 1 spotlight point_at <0, 0, 0> radius 10 falloff 20 tightness 5
                       fade_distance 4 fade_power 2 shadowless translate x }
        light_source { <0, 10, 0>, 1 parallel point_at 0 }
        light_source { 0, 1 cylinder }
    )");
    ASSERT_EQ(s.lights.size(), 4u);
    expect_vec(s.lights[0].position, {1, 2, 3});
    EXPECT_DOUBLE_EQ(s.lights[0].color.g, 0.6);
    EXPECT_EQ(s.lights[0].type, Light::Type::Point);
    const Light& spot = s.lights[1];
    EXPECT_EQ(spot.type, Light::Type::Spot);
    expect_vec(spot.position, {1, 10, 0});
    expect_vec(spot.point_at, {1, 0, 0});
    EXPECT_DOUBLE_EQ(spot.radius, 10);
    EXPECT_DOUBLE_EQ(spot.falloff, 20);
    EXPECT_DOUBLE_EQ(spot.tightness, 5);
    EXPECT_DOUBLE_EQ(spot.fade_distance, 4);
    EXPECT_DOUBLE_EQ(spot.fade_power, 2);
    EXPECT_TRUE(spot.shadowless);
    EXPECT_EQ(s.lights[2].type, Light::Type::Parallel);
    EXPECT_DOUBLE_EQ(s.lights[2].color.transmit, 1.0);  // a bare float colour sets all five components
    EXPECT_EQ(s.lights[3].type, Light::Type::Cylinder);
}

TEST(Light, AreaLightKeepsItsGridAndOptions) {
    const Scene s = parse_ok("light_source { <0, 5, 0> color rgb 1 area_light <1, 0, 0>, <0, 0, 1>, 4, 3.7 "
                             "adaptive 1 jitter circular orient rotate y*90 }");
    ASSERT_EQ(s.lights.size(), 1u);
    EXPECT_TRUE(s.warnings.empty());
    const Light& l = s.lights[0];
    EXPECT_TRUE(l.area);
    EXPECT_EQ(l.area_size1, 4);
    EXPECT_EQ(l.area_size2, 3);  // POV-Ray truncates the sizes
    EXPECT_EQ(l.adaptive, 1);
    EXPECT_TRUE(l.jitter && l.circular && l.orient);
    // The axes turn with the light (left-handed: rotating x by 90° about y gives −z).
    expect_vec(l.area_axis1, {0, 0, -1});
    expect_vec(l.area_axis2, {1, 0, 0});
    EXPECT_EQ(parse_ok("light_source { 0, 1 }").lights[0].adaptive, 100);  // full grid unless told
}

TEST(Light, AreaLightAxesFollowTheTransformsAroundIt) {
    // A declared area light used in an object { } and inside a union: each transform around it turns and scales
    // its square too, not only its position.
    const Scene s = parse_ok(R"(
        #declare L = light_source { 0, 1 area_light <1, 0, 0>, <0, 1, 0>, 2, 2 }
        object { L scale 2 }
        union { object { L } sphere { 0, 1 } rotate y*90 scale 3 }
    )");
    ASSERT_EQ(s.lights.size(), 2u);
    expect_vec(s.lights[0].area_axis1, {2, 0, 0});
    expect_vec(s.lights[0].area_axis2, {0, 2, 0});
    expect_vec(s.lights[1].area_axis1, {0, 0, -3});
    expect_vec(s.lights[1].area_axis2, {0, 3, 0});
}

TEST(Light, AreaLightSizeBelowOneIsAnError) {
    const ParseResult r = test::parse_fail("light_source { 0, 1 area_light x, z, 0, 4 }");
    ASSERT_FALSE(r.diagnostics.empty());
    EXPECT_EQ(r.diagnostics[0].message, "area_light size must be between 1 and 10000");
    EXPECT_EQ(r.diagnostics[0].loc.column, 38u);  // at the size
}

TEST(Objects, ShapesTransformsAndFlags) {
    const Scene s = parse_ok(R"(
        sphere { <1, 2, 3>, 0.5 translate x no_shadow }
        box { <-1, -1, -1>, <1, 1, 1> rotate y*90 scale 2 no_image no_reflection no_radiosity inverse hollow }
        plane { y, -1 matrix <1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 5, 0> }
        sphere { 0, 1 transform { scale 2 translate z inverse } }
    )");
    ASSERT_EQ(s.objects.size(), 4u);
    const Sphere& sp = std::get<Sphere>(s.objects[0].shape);
    expect_vec(sp.center, {1, 2, 3});
    EXPECT_DOUBLE_EQ(sp.radius, 0.5);
    expect_vec(s.objects[0].transform.point({0, 0, 0}), {1, 0, 0});
    EXPECT_TRUE(s.objects[0].no_shadow);
    const Object& box = s.objects[1];
    expect_vec(std::get<Box>(box.shape).corner2, {1, 1, 1});
    expect_vec(box.transform.point({0, 0, 1}), {2, 0, 0});
    EXPECT_TRUE(box.no_image && box.no_reflection && box.no_radiosity && box.inverse);
    EXPECT_FALSE(box.no_shadow);
    const Plane& pl = std::get<Plane>(s.objects[2].shape);
    expect_vec(pl.normal, {0, 1, 0});
    EXPECT_DOUBLE_EQ(pl.distance, -1);
    expect_vec(s.objects[2].transform.point({0, 0, 0}), {0, 5, 0});
    expect_vec(s.objects[3].transform.point({0, 0, 1}), {0, 0, 0});
    EXPECT_EQ(s.objects[0].loc.line, 3u);  // after the global_settings line parse_ok adds
}

TEST(Objects, PigmentFinishTextureAndIdentifiers) {
    const Scene s = parse_ok(R"(
        #declare P = pigment { color rgb <0.1, 0.2, 0.3> }
        #declare F = finish { ambient 0.2 diffuse 0.8 brilliance 2 phong 0.5 phong_size 60 specular 0.3
                              roughness 0.01 emission rgb <1, 0, 0> }
        #declare T = texture { pigment { P } finish { F diffuse 0.7 } }
        sphere { 0, 1 pigment { P } finish { F } }
        sphere { 0, 1 texture { T } }
        sphere { 0, 1 texture { T pigment { rgb 1 } } }
        sphere { 0, 1 pigment { rgb x } finish { diffuse albedo 0.5 } }
    )");
    ASSERT_EQ(s.objects.size(), 4u);
    const Texture& a = s.objects[0].texture;
    EXPECT_DOUBLE_EQ(a.pigment.color.b, 0.3);
    EXPECT_DOUBLE_EQ(a.finish.ambient.g, 0.2);
    EXPECT_DOUBLE_EQ(a.finish.diffuse, 0.8);
    EXPECT_DOUBLE_EQ(a.finish.brilliance, 2);
    EXPECT_DOUBLE_EQ(a.finish.phong, 0.5);
    EXPECT_DOUBLE_EQ(a.finish.phong_size, 60);
    EXPECT_DOUBLE_EQ(a.finish.specular, 0.3);
    EXPECT_DOUBLE_EQ(a.finish.roughness, 0.01);
    EXPECT_DOUBLE_EQ(a.finish.emission.r, 1);
    EXPECT_DOUBLE_EQ(s.objects[1].texture->finish.diffuse, 0.7);
    EXPECT_DOUBLE_EQ(s.objects[1].texture->pigment.color.g, 0.2);
    EXPECT_DOUBLE_EQ(s.objects[2].texture->pigment.color.g, 1.0);
    EXPECT_DOUBLE_EQ(s.objects[2].texture->finish.diffuse, 0.7);
    EXPECT_DOUBLE_EQ(s.objects[3].texture->finish.diffuse, 0.5);
    EXPECT_DOUBLE_EQ(s.objects[3].texture->finish.ambient.r, 0.1);
}

TEST(Objects, DeclaredInteriorIsCopiedAndModified) {
    // The pattern of optics.pov, laser.pov and glass.inc: an interior identifier, alone or followed by items,
    // also passed through a macro parameter (mediasky.pov).
    const Scene s = parse_ok(R"(
        #declare I_Glass = interior { ior 1.5 fade_distance 0.5 fade_power 1001 }
        #declare I_Faded = interior { I_Glass fade_distance 2 }
        #macro Shell(Int) sphere { 0, 1 interior { Int } } #end
        sphere { 0, 1 interior { I_Glass } }
        sphere { 0, 1 interior { I_Faded ior 1.33 } }
        Shell(interior { ior 2 })
    )");
    ASSERT_EQ(s.objects.size(), 3u);
    EXPECT_EQ(s.objects[0].interior.ior, 1.5);
    EXPECT_EQ(s.objects[0].interior.fade_distance, 0.5);
    EXPECT_EQ(s.objects[0].interior.fade_power, 1001);
    EXPECT_EQ(s.objects[1].interior.ior, 1.33);
    EXPECT_EQ(s.objects[1].interior.fade_distance, 2);
    EXPECT_EQ(s.objects[1].interior.fade_power, 1001);
    EXPECT_EQ(s.objects[2].interior.ior, 2);
    const ParseResult r = test::parse_fail("#declare F = finish { ambient 0 }\nsphere { 0, 1 interior { F } }\n");
    ASSERT_EQ(test::count_errors(r), 1u) << test::all_diagnostics(r);
    EXPECT_EQ(r.diagnostics[0].message, "'F' is a finish, not an interior");
}

TEST(Objects, MetallicTakesAnOptionalAmountOrBoolean) {
    // diffract.pov writes `metallic on`; POV-Ray reads the amount as any float, 1 when it is left out.
    const Scene s = parse_ok(R"(
        sphere { 0, 1 finish { metallic on reflection { 0.5 metallic off } } }
        sphere { 0, 1 finish { metallic off } }
        sphere { 0, 1 finish { metallic phong 1 } }
        sphere { 0, 1 finish { metallic 0.25 } }
    )");
    ASSERT_EQ(s.objects.size(), 4u);
    EXPECT_EQ(s.objects[0].texture->finish.metallic, 1);
    EXPECT_EQ(s.objects[0].texture->finish.reflection_metallic, 0);
    EXPECT_EQ(s.objects[1].texture->finish.metallic, 0);
    EXPECT_EQ(s.objects[2].texture->finish.metallic, 1);
    EXPECT_EQ(s.objects[2].texture->finish.phong, 1);
    EXPECT_EQ(s.objects[3].texture->finish.metallic, 0.25);
}

TEST(Objects, DefaultTextureIsBlackWithDefaultFinish) {
    const Scene s = parse_ok("sphere { 0, 1 }");
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_DOUBLE_EQ(s.objects[0].texture->pigment.color.r, 0);
    EXPECT_DOUBLE_EQ(s.objects[0].texture->finish.diffuse, 0.6);
    EXPECT_DOUBLE_EQ(s.objects[0].texture->finish.ambient.r, 0.1);
}

TEST(Objects, UnionIsFlattened) {
    const Scene s = parse_ok(R"(
        #declare Inner = union {
            sphere { 0, 1 }
            sphere { x, 1 pigment { rgb <0, 0, 1> } }
            pigment { rgb <1, 0, 0> }
        }
        union {
            object { Inner }
            box { 0, 1 }
            light_source { <0, 1, 0> rgb 1 }
            translate <0, 10, 0>
            pigment { rgb <0, 1, 0> }
            no_shadow
        }
        object { Inner scale 2 }
    )");
    ASSERT_EQ(s.objects.size(), 5u);
    // Children with their own texture keep it; the inner union's texture beats the outer one's.
    EXPECT_DOUBLE_EQ(s.objects[0].texture->pigment.color.r, 1);
    EXPECT_DOUBLE_EQ(s.objects[1].texture->pigment.color.b, 1);
    EXPECT_DOUBLE_EQ(s.objects[2].texture->pigment.color.g, 1);
    for (int i = 0; i < 3; ++i) {
        EXPECT_TRUE(s.objects[i].no_shadow);
        expect_vec(s.objects[i].transform.point({0, 0, 0}), {0, 10, 0});
    }
    ASSERT_EQ(s.lights.size(), 1u);
    expect_vec(s.lights[0].position, {0, 11, 0});
    expect_vec(s.objects[4].transform.point({1, 0, 0}), {2, 0, 0});
    EXPECT_DOUBLE_EQ(s.objects[4].texture->pigment.color.b, 1);
    EXPECT_FALSE(s.objects[3].no_shadow);
}

TEST(Objects, TransformOrderIsKeywordOrder) {
    const Scene s = parse_ok("sphere { 0, 1 translate x rotate y*90 }\nsphere { 0, 1 rotate y*90 translate x }");
    expect_vec(s.objects[0].transform.point({0, 0, 0}), {0, 0, -1});
    expect_vec(s.objects[1].transform.point({0, 0, 0}), {1, 0, 0});
}

TEST(Objects, ZeroScaleIsChangedToOne) {
    const Scene s = parse_ok("sphere { 0, 1 scale <2, 0, 1> }");
    expect_vec(s.objects[0].transform.point({1, 1, 1}), {2, 1, 1});
    ASSERT_FALSE(s.warnings.empty());
    EXPECT_EQ(s.warnings[0].message, "scale by 0 changed to 1");
}

TEST(Unsupported, OneWarningPerFeatureAndTheRestRenders) {
    // Features chosen among those far from being rendered, so the test outlives the work on shapes and textures.
    const Scene s = parse_ok(R"(
        sphere { 0, 1 finish { subsurface { translucency 0.5 } } }
        sphere { 0, 2 finish { subsurface { translucency 0.5 } } }
        #declare Thing = sphere { 0, 1 texture { uv_mapping pigment { checker } } }
        object { Thing }
        object { Thing }
        box { 0, 1 }
    )");
    ASSERT_EQ(s.objects.size(), 5u);
    std::vector<std::string> messages;
    for (const auto& w : s.warnings) messages.push_back(w.message);
    const std::vector<std::string> expected = {"subsurface is not rendered yet",
                                               "uv_mapping on sphere is not rendered yet"};
    EXPECT_EQ(messages, expected);
    EXPECT_EQ(s.warnings[0].loc.line, 3u);
    EXPECT_EQ(s.warnings[0].loc.column, 32u);
}

TEST(Objects, OptionalCommasAndRelationsOnlyInParentheses) {
    const Scene s = parse_ok(R"(
        box { <-1, -1, -1> <1, 1, 1> }
        sphere { <0 1 2> 3 }
        plane { y 0 }
        light_source { <0, 5, 0> rgb 1 area_light <1, 0, 0> <0, 0, 1> 2 2 }
        #declare Flag = (2 > 1) & (1 < 2);
        sphere { 0, Flag }
    )");
    ASSERT_EQ(s.objects.size(), 4u);
    expect_vec(std::get<Box>(s.objects[0].shape).corner2, {1, 1, 1});
    expect_vec(std::get<Sphere>(s.objects[1].shape).center, {0, 1, 2});
    EXPECT_DOUBLE_EQ(std::get<Sphere>(s.objects[1].shape).radius, 3);
    EXPECT_DOUBLE_EQ(std::get<Sphere>(s.objects[3].shape).radius, 1);
}

TEST(Objects, MacrosProduceObjectsAndItems) {
    const Scene s = parse_ok(R"(
        #macro Ball(R) sphere { 0, R } #end
        #macro Red() pigment { rgb <1, 0, 0> } #end
        #macro Shiny() finish { phong 1 } #end
        object { Ball(2) Red() Shiny() translate x }
        union { Ball(3) Ball(4) split_union off }
    )");
    ASSERT_EQ(s.objects.size(), 3u);
    EXPECT_DOUBLE_EQ(std::get<Sphere>(s.objects[0].shape).radius, 2);
    EXPECT_DOUBLE_EQ(s.objects[0].texture->pigment.color.r, 1);
    EXPECT_DOUBLE_EQ(s.objects[0].texture->finish.phong, 1);
    EXPECT_DOUBLE_EQ(std::get<Sphere>(s.objects[2].shape).radius, 4);
}

TEST(Objects, LayeredTexturesKeepEveryLayer) {
    // POV-Ray compat: the last texture listed is the top layer, in a declaration as on an object.
    const Scene s = parse_ok(R"(
        #declare T = texture { pigment { rgb x } } texture { pigment { rgbt <0, 1, 0, 0.5> } }
        sphere { 0, 1 texture { T } }
        sphere { 0, 1 texture { pigment { rgb z } } texture { pigment { rgb y } } }
        default { finish { diffuse 0.3 } }
        sphere { 0, 1 }
    )");
    ASSERT_EQ(s.objects.size(), 3u);
    EXPECT_DOUBLE_EQ(s.objects[0].texture->pigment.color.r, 1);
    ASSERT_EQ(s.objects[0].texture->layers.size(), 1u);
    EXPECT_DOUBLE_EQ(s.objects[0].texture->layers[0].pigment.color.g, 1);
    EXPECT_DOUBLE_EQ(s.objects[0].texture->layers[0].pigment.color.transmit, 0.5);
    EXPECT_DOUBLE_EQ(s.objects[1].texture->pigment.color.b, 1);
    ASSERT_EQ(s.objects[1].texture->layers.size(), 1u);
    EXPECT_DOUBLE_EQ(s.objects[1].texture->layers[0].pigment.color.g, 1);
    EXPECT_DOUBLE_EQ(s.objects[2].texture->finish.diffuse, 0.3);
    EXPECT_TRUE(s.warnings.empty());
}

TEST(GlobalSettings, AllItems) {
    const ParseResult r = parse_string(R"(
        global_settings {
            assumed_gamma 1.0 ambient_light rgb <0.1, 0.2, 0.3> max_trace_level 7 adc_bailout 0.001
            radiosity {
                count 50, 2000 nearest_count 8, 3 error_bound 0.5 low_error_factor 0.4 minimum_reuse 0.01
                maximum_reuse 0.1 recursion_limit 3 pretrace_start 0.16 pretrace_end 0.02 brightness 1.5
                gray_threshold 0.2 adc_bailout 0.005 always_sample on normal on media off
            }
        }
        background { color rgb <0.1, 0.2, 0.3> }
    )", "g.pov", test::default_options());
    ASSERT_TRUE(r.ok()) << test::all_diagnostics(r);
    EXPECT_TRUE(r.diagnostics.empty()) << test::all_diagnostics(r);
    const GlobalSettings& g = r.scene->global;
    EXPECT_TRUE(g.assumed_gamma_given);
    EXPECT_DOUBLE_EQ(g.ambient_light.b, 0.3);
    EXPECT_EQ(g.max_trace_level, 7);
    EXPECT_DOUBLE_EQ(g.adc_bailout, 0.001);
    ASSERT_TRUE(g.radiosity.has_value());
    const RadiositySettings& rad = *g.radiosity;
    EXPECT_EQ(rad.count, 50);
    EXPECT_EQ(rad.count_directions, 2000);
    EXPECT_EQ(rad.nearest_count, 8);
    EXPECT_EQ(rad.nearest_count_pretrace, 3);
    EXPECT_DOUBLE_EQ(rad.error_bound, 0.5);
    EXPECT_DOUBLE_EQ(rad.low_error_factor, 0.4);
    EXPECT_DOUBLE_EQ(rad.minimum_reuse, 0.01);
    EXPECT_DOUBLE_EQ(rad.maximum_reuse, 0.1);
    EXPECT_EQ(rad.recursion_limit, 3);
    EXPECT_DOUBLE_EQ(rad.pretrace_start, 0.16);
    EXPECT_DOUBLE_EQ(rad.pretrace_end, 0.02);
    EXPECT_DOUBLE_EQ(rad.brightness, 1.5);
    EXPECT_DOUBLE_EQ(rad.gray_threshold, 0.2);
    EXPECT_DOUBLE_EQ(rad.adc_bailout, 0.005);
    EXPECT_TRUE(rad.always_sample);
    EXPECT_TRUE(rad.normal);
    EXPECT_FALSE(rad.media);
    EXPECT_EQ(rad.loc.line, 4u);
    EXPECT_DOUBLE_EQ(r.scene->background.g, 0.2);
}

TEST(GlobalSettings, RadiosityDefaultsAndMissingGammaWarning) {
    const ParseResult r = parse_string("global_settings { radiosity { } }", "g.pov", test::default_options());
    ASSERT_TRUE(r.ok());
    const RadiositySettings& rad = *r.scene->global.radiosity;
    EXPECT_EQ(rad.count, 35);
    EXPECT_DOUBLE_EQ(rad.error_bound, 1.8);
    EXPECT_FALSE(r.scene->global.assumed_gamma_given);
    ASSERT_EQ(r.scene->warnings.size(), 1u);
    EXPECT_NE(r.scene->warnings[0].message.find("assumed_gamma"), std::string::npos);
}

TEST(Scene, CrandIsReadIntoTheFinishWithoutAWarning) {
    // POV-Ray 3.7 renders crand (lighting/graininess.h); the finish keeps its amount, and a declared finish too.
    const Scene s = test::parse_ok("#declare F = finish { crand 0.02 }\n"
                                   "sphere { 0, 1 finish { crand 0.03 } }\nsphere { 0, 1 finish { F } }\n");
    EXPECT_TRUE(s.warnings.empty());
    ASSERT_EQ(s.objects.size(), 2u);
    EXPECT_DOUBLE_EQ(s.objects[0].texture->finish.crand, 0.03);
    EXPECT_DOUBLE_EQ(s.objects[1].texture->finish.crand, 0.02);
}

TEST(Objects, MeshBlockCopiesADeclaredMesh) {
    // meshcam_persp_demo.pov: `mesh { camera_mesh translate ... }` places a declared mesh again.
    const Scene s = test::parse_ok("#declare M = mesh { triangle { 0, x, y } triangle { 0, y, z } }\n"
                                   "mesh { M translate 2 * x }\n");
    ASSERT_EQ(s.objects.size(), 1u);
    ASSERT_TRUE(std::holds_alternative<Mesh>(s.objects[0].shape));
    EXPECT_EQ(std::get<Mesh>(s.objects[0].shape).faces.size(), 2u);
    EXPECT_EQ(s.objects[0].transform.point({0, 0, 0}), (Vec3{2, 0, 0}));
}

TEST(Objects, MacroInsideATransformBlock) {
    // transforms.inc's macros return `transform { ... }` and stand inside transform blocks (meshcam_macros.inc).
    const Scene s = test::parse_ok("#macro Shift(V) transform { translate V } #end\n"
                                   "sphere { 0, 1 transform { Shift(<1, 2, 3>) scale 2 } }\n");
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_EQ(s.objects[0].transform.point({0, 0, 0}), (Vec3{2, 4, 6}));
}

TEST(Objects, DeclaredNormalsReadAsWrittenInPlace) {
    const Scene s = test::parse_ok("#declare N = normal { bumps 0.5 scale 0.2 }\n"
                                   "#declare A = array[2] { normal { dents 0.3 }, N }\n"
                                   "sphere { 0, 1 normal { bumps 0.5 scale 0.2 } }\n"
                                   "sphere { 0, 1 normal { N } }\n"
                                   "sphere { 0, 1 normal { A[1] } }\n"
                                   "sphere { 0, 1 texture { normal { A[0] } } }\n");
    ASSERT_EQ(s.objects.size(), 4u);
    EXPECT_TRUE(s.warnings.empty()) << format_diagnostic(s.warnings.front());
    auto normal = [&](std::size_t i) {
        Normal n = s.objects[i].texture->normal;
        n.loc = {};
        return n;
    };
    EXPECT_EQ(normal(0).pattern.type, Pattern::Type::Bumps);
    EXPECT_TRUE(normal(1) == normal(0));
    EXPECT_TRUE(normal(2) == normal(0));
    EXPECT_EQ(normal(3).pattern.type, Pattern::Type::Dents);
    const ParseResult r = test::parse_fail("#declare A = array[1] { 1 }\nsphere { 0, 1 normal { A[0] } }\n");
    EXPECT_NE(test::all_diagnostics(r).find("expected a normal but found a number"), std::string::npos)
        << test::all_diagnostics(r);
}

// The pattern list is consistent: each keyword of WARDRAY_PATTERNS is reserved, is no "not rendered yet" pattern,
// and parses to its pattern type in a pigment, a normal and a texture map.
TEST(PatternList, EveryKeywordParsesToItsTypeAndIsReserved) {
    for (const auto& [keyword, type] : k_pattern_keywords) {
        SCOPED_TRACE(std::string(keyword));
        EXPECT_TRUE(is_keyword(keyword));
        EXPECT_FALSE(is_pattern_keyword(keyword));
        // The patterns that need parameters get a sample of them.
        static const std::map<std::string_view, const char*> parameters = {
            {"gradient", " y"},        {"mandel", " 20"},  {"julia", " <0.3, 0.2>, 20"}, {"magnet", " 1 mandel 20"},
            {"spiral1", " 3"},         {"spiral2", " 3"},  {"pigment_pattern", " { bozo }"}, {"function", " { x + y }"},
            {"density_file", " df3 \"/usr/share/povray-3.7/include/spiral.df3\""}, {"object", " { sphere { 0, 1 } }"},
            {"slope", " { y, 0, 1 altitude x }"}, {"tiling", " 5"}, {"image_pattern", " { png \"/usr/share/povray-3.7/include/Mount1.png\" }"}};
        const auto sample = parameters.find(keyword);
        const std::string pattern = std::string(keyword) + (sample != parameters.end() ? sample->second : "");
        if (keyword == "facets") {
            // POV-Ray compat: facets is a normal pattern only.
            EXPECT_EQ(parse_ok("sphere { 0, 1 normal { facets } }").objects[0].texture->normal.pattern.type, type);
            continue;
        }
        // image_pattern reads its file through the renderer's reader: a one-texel stand-in.
        ParseOptions options = test::default_options();
        options.read_image = [](const std::filesystem::path&, bool&, std::string&) {
            auto image = std::make_shared<ImageData>();
            image->width = image->height = 1;
            image->rgb = {0.5f, 0.5f, 0.5f};
            return image;
        };
        const Scene s = parse_ok("sphere { 0, 1 pigment { " + pattern + " } normal { " + pattern +
                                     " } }\nsphere { 0, 1 texture { " + pattern +
                                     " texture_map { [0 pigment { rgb 0 }] [1 pigment { rgb 1 }] } } }",
                                 options);
        ASSERT_EQ(s.objects.size(), 2u);
        EXPECT_EQ(s.objects[0].texture->pigment.pattern.type, type);
        EXPECT_EQ(s.objects[0].texture->normal.pattern.type, type);
        EXPECT_EQ(s.objects[1].texture->map_pattern.type, type);
    }
}

// The camera list is consistent: each keyword of WARDRAY_CAMERAS is reserved and sets its projection.
TEST(CameraList, EveryKeywordSetsItsTypeAndIsReserved) {
    for (const auto& [keyword, type] : k_camera_keywords) {
        SCOPED_TRACE(std::string(keyword));
        EXPECT_TRUE(is_keyword(keyword));
        EXPECT_EQ(camera_type_name(type), keyword);
        // The cylinder camera's keyword takes its projection's number.
        std::string item = std::string(keyword) + (keyword == "cylinder" ? " 2" : "");
        if (keyword == "mesh_camera") item += " { 1 0 mesh { triangle { 0, x, y } } }";
        const Scene s = parse_ok("camera { " + item + " location -5*z look_at 0 }");
        EXPECT_EQ(s.camera.type, type);
    }
}

// Every object holds a Shape, a variant as large as its largest kind: kinds with large fixed arrays (a bicubic
// patch's 16 points, a quartic's 35 coefficients) keep them on the heap, so a scene of 20,000 spheres does not
// carry 20,000 patches' worth of bytes (the variant was 712 bytes, the object 1224).
TEST(SceneMemory, AnObjectDoesNotCarryTheLargestShapeInline) {
    EXPECT_LE(sizeof(scene::Shape), 320u);
    EXPECT_LE(sizeof(scene::Object), 832u);
    const auto patch = parse_ok(
        "bicubic_patch { type 1 flatness 0.1 u_steps 2 v_steps 2 <0,0,0>,<1,0,0>,<2,0,0>,<3,0,0>, <0,1,0>,<1,1,1>,"
        "<2,1,1>,<3,1,0>, <0,2,0>,<1,2,1>,<2,2,1>,<3,2,0>, <0,3,0>,<1,3,0>,<2,3,0>,<3,3,2> }");
    const auto& bp = std::get<scene::BicubicPatch>(patch.objects.at(0).shape);
    ASSERT_EQ(bp.points.size(), 16u);
    EXPECT_EQ(bp.points[15].z, 2.0);
    EXPECT_EQ(bp.uv_vectors.size(), 4u);
    const auto quartic = parse_ok("quartic { <1,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,-1> }");
    const auto& q = std::get<scene::Quartic>(quartic.objects.at(0).shape);
    ASSERT_EQ(q.coefficients.size(), 35u);
    EXPECT_EQ(q.coefficients[34], -1.0);
}

}  // namespace
}  // namespace wardray::parser
