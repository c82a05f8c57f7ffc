// Materials, interior textures, double_illuminate and light groups as the parser reads them.
#include <string>
#include <vector>

#include "tests/parser/test_util.h"

namespace wardray::parser {
namespace {

using test::parse_ok;

TEST(Objects, LightGroupStandsWhereObjectsDoAndLightsOnlyItsObjects) {
    // abyss.pov puts light groups inside a union; POV-Ray takes them wherever an object may stand.
    const ParseResult r = parse_string(R"(global_settings { assumed_gamma 1 }
        light_source { <0, 20, 0> rgb 1 }
        union {
          light_group { sphere { 0, 1 } light_source { <0, 10, 0> rgb 1 } global_lights on }
          sphere { x, 2 }
          translate y
        }
        light_group { sphere { 0, 3 } light_source { <0, 10, 0> rgb 1 } })",
                                       "test.pov", test::default_options());
    ASSERT_TRUE(r.ok()) << test::all_diagnostics(r);
    const Scene& s = *r.scene;
    EXPECT_TRUE(s.warnings.empty()) << test::all_diagnostics(r);
    ASSERT_EQ(s.objects.size(), 3u);
    ASSERT_EQ(s.lights.size(), 3u);
    EXPECT_EQ(s.lights[0].group, 0);
    EXPECT_NE(s.lights[1].group, 0);
    EXPECT_NE(s.lights[2].group, 0);
    EXPECT_NE(s.lights[1].group, s.lights[2].group);
    EXPECT_EQ(s.lights[1].position, (Vec3{0, 11, 0}));  // the union's translate moves its group's light
    // The first group's sphere: its group's light and, with global_lights on, the global one.
    EXPECT_EQ(s.objects[0].light_groups, std::vector<int>{s.lights[1].group});
    EXPECT_FALSE(s.objects[0].no_global_lights);
    // The union's other sphere is in no group.
    EXPECT_TRUE(s.objects[1].light_groups.empty());
    EXPECT_FALSE(s.objects[1].no_global_lights);
    // The second group, without global_lights: only its own light.
    EXPECT_EQ(s.objects[2].light_groups, std::vector<int>{s.lights[2].group});
    EXPECT_TRUE(s.objects[2].no_global_lights);
}

TEST(Objects, ADeclaredLightGroupPlacedTwiceIsTwoGroups) {
    const Scene s = parse_ok(R"(
        #declare G = light_group { sphere { 0, 1 } light_source { <0, 10, 0> rgb 1 } }
        object { G translate -2*x }
        object { G translate 2*x }
    )");
    ASSERT_EQ(s.objects.size(), 2u);
    ASSERT_EQ(s.lights.size(), 2u);
    EXPECT_NE(s.lights[0].group, s.lights[1].group);
    EXPECT_EQ(s.objects[0].light_groups, std::vector<int>{s.lights[0].group});
    EXPECT_EQ(s.objects[1].light_groups, std::vector<int>{s.lights[1].group});
}

TEST(Objects, MaterialGivesTextureInteriorTextureAndInterior) {
    const Scene s = parse_ok(R"(
        #declare M = material {
          texture { pigment { rgb <1, 0, 0> } }
          texture { pigment { rgbt <0, 1, 0, 0.5> } }
          interior_texture { pigment { rgb <0, 0, 1> } }
          interior { ior 1.5 }
          translate x
        }
        sphere { 0, 1 material { M } }
        sphere { 0, 1 pigment { rgb 1 } material { M scale 2 } }
        box { 0, 1 texture { pigment { rgb 0.5 } } interior_texture { pigment { rgb 0.25 } } double_illuminate }
    )");
    ASSERT_EQ(s.objects.size(), 3u);
    EXPECT_TRUE(s.warnings.empty());
    const Object& a = s.objects[0];
    EXPECT_EQ(a.texture->pigment.color.r, 1.0);
    ASSERT_EQ(a.texture->layers.size(), 1u);
    EXPECT_EQ(a.texture->layers[0].pigment.color.g, 1.0);
    ASSERT_EQ(a.interior_texture.size(), 1u);
    EXPECT_EQ(a.interior_texture[0].pigment.color.b, 1.0);
    EXPECT_EQ(a.interior.ior, 1.5);
    EXPECT_FALSE(a.double_illuminate);
    // A transform inside the material moves its textures only.
    EXPECT_EQ(a.texture->pigment.pattern.transform.point(Vec3{}), (Vec3{1, 0, 0}));
    const Object& b = s.objects[1];
    EXPECT_EQ(b.interior.ior, 1.5);
    ASSERT_EQ(b.interior_texture.size(), 1u);
    const Object& c = s.objects[2];
    ASSERT_EQ(c.interior_texture.size(), 1u);
    EXPECT_EQ(c.interior_texture[0].pigment.color.r, 0.25);
    EXPECT_EQ(c.texture->pigment.color.r, 0.5);
    EXPECT_TRUE(c.double_illuminate);
}

TEST(Objects, MaterialFromAnArrayElement) {
    // sample.inc (incdemo/glasses): `material { MArr[I] }`.
    const Scene s = parse_ok(R"(
        #declare MArr = array[2] { material { texture { pigment { rgb x } } },
                                   material { texture { pigment { rgb y } } interior { ior 1.3 } } }
        sphere { 0, 1 material { MArr[1] } }
    )");
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_EQ(s.objects[0].texture->pigment.color.g, 1.0);
    EXPECT_EQ(s.objects[0].interior.ior, 1.3);
}

/// The CSG children of `o` (a merge or other CSG node).
const std::vector<Object>& children(const Object& o) { return std::get<Csg>(o.shape).children; }

TEST(Objects, CsgChildrenKeepTheirOwnInteriorAndShareTheInheritedOne) {
    // POV-Ray's Post_Process: a child without an interior shares its CSG's; one with its own keeps it (wineglass.pov
    // merges glass parts that each have their own), in a merge and in a union alike; `hollow` on the CSG reaches
    // the children that did not say it themselves.
    const Scene s = parse_ok(R"(
        #declare I = interior { ior 1.45 fade_distance 2 fade_power 1 }
        merge {
          cylinder { 0, y, 1 interior { I } }
          sphere { 0, 1 hollow off }
          sphere { x, 1 }
          interior { ior 1.3 }
          hollow
        }
        union {
          cylinder { 0, y, 1 interior { ior 1.9 } }
          sphere { 0, 1 }
          sphere { x, 1 }
          interior { ior 1.2 }
        }
        sphere { 0, 1 interior { ior 1.5 fade_distance 3 } interior { ior 1.7 } }
        union { sphere { 0, 1 } sphere { x, 1 } }
    )");
    ASSERT_EQ(s.objects.size(), 7u);
    const std::vector<Object>& merged = children(s.objects[0]);
    ASSERT_EQ(merged.size(), 3u);
    EXPECT_EQ(merged[0].interior.ior, 1.45);
    EXPECT_EQ(merged[0].interior.fade_distance, 2.0);
    EXPECT_EQ(merged[1].interior.ior, 1.3);
    EXPECT_EQ(merged[2].interior.ior, 1.3);
    EXPECT_FALSE(same_interior(merged[0], merged[1]));
    EXPECT_TRUE(same_interior(merged[1], merged[2]));
    EXPECT_TRUE(same_interior(merged[1], s.objects[0]));
    EXPECT_TRUE(merged[0].interior.hollow);
    EXPECT_FALSE(merged[1].interior.hollow);
    EXPECT_TRUE(merged[2].interior.hollow);
    // The union's parts: its interior goes only to those without one, and they share it.
    EXPECT_EQ(s.objects[1].interior.ior, 1.9);
    EXPECT_EQ(s.objects[2].interior.ior, 1.2);
    EXPECT_EQ(s.objects[3].interior.ior, 1.2);
    EXPECT_FALSE(same_interior(s.objects[1], s.objects[2]));
    EXPECT_TRUE(same_interior(s.objects[2], s.objects[3]));
    EXPECT_FALSE(same_interior(s.objects[0], s.objects[2]));
    // A second interior statement changes the object's interior in place (POV-Ray's Parse_Interior).
    EXPECT_EQ(s.objects[4].interior.ior, 1.7);
    EXPECT_EQ(s.objects[4].interior.fade_distance, 3.0);
    // A union without an interior: its parts share the new one POV-Ray gives it.
    EXPECT_TRUE(same_interior(s.objects[5], s.objects[6]));
    EXPECT_FALSE(same_interior(s.objects[4], s.objects[5]));
}

TEST(Objects, CopiesOfADeclaredObjectHaveInteriorsOfTheirOwn) {
    // POV-Ray's Copy_Object copies the interior: two copies of one glass union are two interiors.
    const Scene s = parse_ok(R"(
        #declare U = union { sphere { 0, 1 } sphere { x, 1 } interior { ior 1.5 } }
        union { object { U } object { U translate y } }
    )");
    ASSERT_EQ(s.objects.size(), 4u);
    EXPECT_TRUE(same_interior(s.objects[0], s.objects[1]));
    EXPECT_TRUE(same_interior(s.objects[2], s.objects[3]));
    EXPECT_FALSE(same_interior(s.objects[0], s.objects[2]));
    EXPECT_EQ(s.objects[3].interior.ior, 1.5);
}

TEST(Objects, TextureLayersOverTheObjectsOwnTexture) {
    // POV-Ray's Link_Textures: glasschess.pov's blocks say pigment { rgbf 0.9 } and then texture { Glass }, which
    // goes on top; so does a texture given to a copy of a textured object. Without a texture of its own the
    // statement is the object's texture.
    const Scene s = parse_ok(R"(
        #declare Glass = texture { pigment { rgbf <1, 1, 1, 1> } finish { specular 1 } }
        #declare Red = sphere { 0, 1 texture { pigment { rgb x } } }
        sphere { 0, 1 pigment { rgbf 0.9 } texture { Glass } }
        object { Red texture { Glass } }
        sphere { 0, 1 texture { Glass } }
        union { sphere { 0, 1 } texture { pigment { rgb y } } }
    )");
    ASSERT_EQ(s.objects.size(), 4u);
    ASSERT_EQ(s.objects[0].texture->layers.size(), 1u);
    EXPECT_EQ(s.objects[0].texture->pigment.color.filter, 0.9);
    EXPECT_EQ(s.objects[0].texture->layers[0].finish.specular, 1.0);
    ASSERT_EQ(s.objects[1].texture->layers.size(), 1u);
    EXPECT_EQ(s.objects[1].texture->pigment.color.r, 1.0);
    EXPECT_EQ(s.objects[1].texture->layers[0].pigment.color.filter, 1.0);
    EXPECT_TRUE(s.objects[2].texture->layers.empty());
    EXPECT_TRUE(s.objects[3].texture->layers.empty());
    EXPECT_EQ(s.objects[3].texture->pigment.color.g, 1.0);
}

TEST(Objects, MaterialRejectsWhatIsNotAMaterial) {
    const ParseResult r = parse_string("global_settings { assumed_gamma 1 }\n#declare P = pigment { rgb 1 }\n"
                                       "sphere { 0, 1 material { P } }\n",
                                       "test.pov", test::default_options());
    ASSERT_FALSE(r.ok());
    EXPECT_NE(test::all_diagnostics(r).find("not a material"), std::string::npos);
}

TEST(Objects, InteriorDispersionAndItsSamples) {
    // POV-Ray's defaults: dispersion 1 (none) over 7 bands; fewer than 2 samples is POV-Ray's error.
    const Scene s = parse_ok("sphere { 0, 1 interior { ior 1.5 dispersion 1.1 dispersion_samples 12 } }\n"
                             "sphere { 0, 1 interior { ior 1.5 } }\n");
    ASSERT_EQ(s.objects.size(), 2u);
    EXPECT_TRUE(s.warnings.empty());
    EXPECT_EQ(s.objects[0].interior.dispersion, 1.1);
    EXPECT_EQ(s.objects[0].interior.dispersion_samples, 12);
    EXPECT_EQ(s.objects[1].interior.dispersion, 1.0);
    EXPECT_EQ(s.objects[1].interior.dispersion_samples, 7);
    const ParseResult r = parse_string("global_settings { assumed_gamma 1 }\n"
                                       "sphere { 0, 1 interior { dispersion_samples 1 } }\n",
                                       "test.pov", test::default_options());
    ASSERT_FALSE(r.ok());
    EXPECT_NE(test::all_diagnostics(r).find("Dispersion samples minimum is 2."), std::string::npos);
    // POV-Ray truncates first: 1.9 is 1, too few.
    EXPECT_FALSE(parse_string("sphere { 0, 1 interior { dispersion_samples 1.9 } }\n", "test.pov",
                              test::default_options()).ok());
    const Scene many = parse_ok("sphere { 0, 1 interior { dispersion_samples 1e12 } }\n");
    EXPECT_EQ(many.objects[0].interior.dispersion_samples, 1000);
    const Scene zero = parse_ok("sphere { 0, 1 interior { dispersion 0 } }\n");
    EXPECT_EQ(zero.objects[0].interior.dispersion, 1.0);
    ASSERT_EQ(zero.warnings.size(), 1u);
}

}  // namespace
}  // namespace wardray::parser
