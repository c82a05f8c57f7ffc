// Tests of the grammar POV-Ray 3.7 accepts beyond its example scenes: identifiers standing alone where POV-Ray
// takes them, its 3.1-era forms (read with its warnings), and its rules for includes, macros and directives.
#include <string>

#include "tests/parser/test_util.h"

namespace wardray::parser {
namespace {

using test::parse_ok;
using test::TempDir;

bool has_warning(const Scene& s, const std::string& text) {
    for (const Diagnostic& d : s.warnings)
        if (d.message.find(text) != std::string::npos) return true;
    return false;
}

TEST(Grammar, TextureTakesPigmentNormalAndFinishIdentifiers) {
    const Scene s = parse_ok(R"(
        #declare P = pigment { rgb <1, 0, 0> }
        #declare F = finish { ambient 0.3 }
        #declare N = normal { bumps 0.25 }
        sphere { 0, 1 texture { P N F scale 2 } }
        sphere { 0, 1 texture { F finish { diffuse 0.2 } } }
    )");
    ASSERT_EQ(s.objects.size(), 2u);
    const Texture& a = s.objects[0].texture;
    EXPECT_EQ(a.pigment.color.r, 1.0);
    EXPECT_EQ(a.finish.ambient.r, 0.3);
    EXPECT_EQ(a.normal.pattern.type, Pattern::Type::Bumps);
    EXPECT_EQ(a.normal.amount, 0.25);
    // A finish block after a finish identifier modifies that finish in place, as POV-Ray's Parse_Finish does.
    EXPECT_EQ(s.objects[1].texture->finish.diffuse, 0.2);
    EXPECT_EQ(s.objects[1].texture->finish.ambient.r, 0.3);
}

TEST(Grammar, LayeredTextureIdentifierAsALaterLayerBringsAllItsLayers) {
    // A user's `#declare T = texture { pigment { rgbt 1 } } texture { DMFWood6 rotate x*90 }`: DMFWood6 is two
    // layers, and POV-Ray links both over the first, each moved by the transform (it drew the top layer's grain
    // where wardray kept only DMFWood6's first layer). The same in a tiles list and on an object.
    const Scene s = parse_ok(R"(
        #declare W = texture { pigment { rgb <1, 0, 0> } } texture { pigment { rgbt <0, 1, 0, 0.5> } }
        #declare T = texture { pigment { rgbt 1 } } texture { W translate x }
        sphere { 0, 1 texture { T } }
        sphere { 0, 1 texture { tiles { texture { pigment { rgbt 1 } } texture { W translate x } tile2 texture { W } } } }
        sphere { 0, 1 texture { pigment { rgbt 1 } } texture { W translate x } }
    )");
    ASSERT_EQ(s.objects.size(), 3u);
    const Texture& declared = s.objects[0].texture;
    const Texture& tiles = s.objects[1].texture;
    const Texture& listed = s.objects[2].texture;
    ASSERT_EQ(tiles.texture_map.size(), 2u);
    for (const Texture* t : {&declared, &tiles.texture_map[1].texture, &listed}) {
        EXPECT_EQ(t->pigment.color.transmit, 1.0);
        ASSERT_EQ(t->layers.size(), 2u);
        EXPECT_EQ(t->layers[0].pigment.color.r, 1.0);
        EXPECT_EQ(t->layers[1].pigment.color.g, 1.0);
        for (const Texture& layer : t->layers) {
            EXPECT_TRUE(layer.layers.empty());
            EXPECT_EQ(layer.pigment.pattern.transform.point({0, 0, 0}), (Vec3{1, 0, 0}));
        }
    }
}

TEST(Grammar, FinishAfterALayeredTextureModifiesItsTopLayerInPlace) {
    // POV-Ray keeps a layered texture as a list headed by its last (top) layer; a pigment, normal or finish after
    // the identifier, in the texture or on the object, changes that layer only, and a finish block changes the
    // layer's own finish rather than starting from the default (norm_acc.pov's `texture { T_Wood35 finish {..} }`).
    const Scene s = parse_ok(R"(
        #declare T = texture { pigment { rgb <1, 0.5, 0.1> } finish { phong 0.5 } }
                     texture { pigment { rgbt <0.2, 0.2, 1, 0.5> } finish { specular 0.4 } }
        sphere { 0, 1 texture { T finish { diffuse 0 ambient 1 } } }
        sphere { 0, 1 texture { T } finish { ambient 0.5 } }
    )");
    ASSERT_EQ(s.objects.size(), 2u);
    const Texture& a = s.objects[0].texture;
    ASSERT_EQ(a.layers.size(), 1u);
    EXPECT_EQ(a.finish.ambient.r, 0.1);
    EXPECT_EQ(a.finish.phong, 0.5);
    EXPECT_EQ(a.layers[0].finish.ambient.r, 1.0);
    EXPECT_EQ(a.layers[0].finish.diffuse, 0.0);
    EXPECT_EQ(a.layers[0].finish.specular, 0.4);
    const Texture& b = s.objects[1].texture;
    ASSERT_EQ(b.layers.size(), 1u);
    EXPECT_EQ(b.finish.ambient.r, 0.1);
    EXPECT_EQ(b.layers[0].finish.ambient.r, 0.5);
    EXPECT_EQ(b.layers[0].finish.specular, 0.4);
}

TEST(Grammar, PigmentAndNormalAfterATextureIdentifierModifyItsOwn) {
    // POV-Ray's Parse_Pigment and Parse_Tnormal change the texture's pigment and normal in place (ballbox1.pov's
    // `texture { T_Stone1 pigment { octaves 3 rotate 90*z } }` keeps T_Stone1's granite and its colour map).
    const Scene s = parse_ok(R"(
        #declare T = texture { pigment { granite turbulence 0.5 color_map { [0 rgb 0] [1 rgb 1] } } normal { bumps 0.3 } }
        sphere { 0, 1 texture { T pigment { octaves 3 } normal { scale 2 } } }
        sphere { 0, 1 texture { T } pigment { rgb <1, 0, 0> } }
        plane { y, 0 pigment { rgb 1 } translate 5*x normal { bumps 0.5 } }
    )");
    ASSERT_EQ(s.objects.size(), 3u);
    const Texture& a = s.objects[0].texture;
    EXPECT_EQ(a.pigment.pattern.type, Pattern::Type::Granite);
    ASSERT_TRUE(a.pigment.pattern.params->turbulence.has_value());
    EXPECT_EQ(a.pigment.pattern.params->turbulence->octaves, 3);
    EXPECT_EQ(a.pigment.pattern.params->turbulence->amount.x, 0.5);
    EXPECT_EQ(a.pigment.color_map.size(), 2u);
    EXPECT_EQ(a.normal.pattern.type, Pattern::Type::Bumps);
    EXPECT_EQ(a.normal.amount, static_cast<double>(0.3f));  // POV-Ray stores bump_size in single precision
    EXPECT_TRUE(s.objects[1].texture->pigment.is_solid());
    EXPECT_EQ(s.objects[1].texture->pigment.color.r, 1.0);
    // A texture with no normal has none to modify: the new one does not take the object's earlier translate
    // (caustic2.pov's water surface).
    EXPECT_TRUE(s.objects[2].texture->normal.pattern.transform.is_identity());
}

TEST(Grammar, AColourArrayElementStartsAColourExpressionInAPigment) {
    // isocacti.pov: `pigment { Rand_Array_Item(RockColors, RS)*RRand(0.1, 1, RS) }` (arrays.inc).
    const Scene s = parse_ok(R"(
        #declare Colors = array[2] { rgb <1, 0.5, 0.25>, rgb 1 }
        #macro Item(A, I) A[I] #end
        sphere { 0, 1 pigment { Item(Colors, 0) * 0.5 } }
        sphere { 0, 1 pigment { Colors[1] } }
    )");
    ASSERT_EQ(s.objects.size(), 2u);
    EXPECT_EQ(s.objects[0].texture->pigment.color.g, 0.25);
    EXPECT_EQ(s.objects[1].texture->pigment.color.b, 1.0);
}

TEST(Grammar, NormalMapEntryTakesANormalIdentifier) {
    const Scene s = parse_ok(R"(
        #declare N = normal { dents 0.75 }
        sphere { 0, 1 pigment { rgb 1 } normal { gradient x normal_map { [0 N] [1 N scale 2] } } }
    )");
    const Normal& n = s.objects[0].texture->normal;
    ASSERT_EQ(n.normal_map.size(), 2u);
    EXPECT_EQ(n.normal_map[0].normal.amount, 0.75);
    EXPECT_EQ(n.normal_map[1].normal.pattern.type, Pattern::Type::Dents);
}

TEST(Grammar, NoBumpScaleMarksTheNormalAndTheTextureMap) {
    const Scene s = parse_ok(R"(
        sphere { 0, 1 texture { no_bump_scale pigment { rgb 1 } normal { bumps } scale 8 } }
        sphere { 0, 1 normal { dents 0.5 no_bump_scale scale 3 } }
        sphere { 0, 1 texture { gradient x texture_map { [0 normal { bumps }] [1 pigment { rgb 1 }] } no_bump_scale } }
        sphere { 0, 1 normal { bumps scale 2 } }
    )");
    EXPECT_FALSE(has_warning(s, "not rendered"));
    ASSERT_EQ(s.objects.size(), 4u);
    EXPECT_TRUE(s.objects[0].texture->normal.pattern.no_bump_scale);  // the normal read after the flag too
    EXPECT_TRUE(s.objects[1].texture->normal.pattern.no_bump_scale);
    const Texture& mapped = s.objects[2].texture.get();
    EXPECT_TRUE(mapped.map_pattern.no_bump_scale);
    ASSERT_EQ(mapped.texture_map.size(), 2u);
    EXPECT_TRUE(mapped.texture_map[0].texture.normal.pattern.no_bump_scale);
    EXPECT_FALSE(s.objects[3].texture->normal.pattern.no_bump_scale);
}

TEST(Grammar, FinishIorMovesIntoTheInterior) {
    const Scene s = parse_ok(R"(
        #declare Glass = finish { ior 1.5 refraction 1 phong 1 }
        sphere { 0, 1 pigment { rgbf 1 } finish { Glass } }
        union { sphere { 0, 1 } sphere { x, 1 } texture { pigment { rgbf 1 } finish { ior 1.33 } } }
        sphere { 0, 1 pigment { rgbf 1 } }
    )");
    ASSERT_EQ(s.objects.size(), 4u);
    EXPECT_EQ(s.objects[0].interior.ior, 1.5);
    EXPECT_EQ(s.objects[1].interior.ior, 1.33);
    EXPECT_EQ(s.objects[2].interior.ior, 1.33);
    EXPECT_EQ(s.objects[3].interior.ior, 1.0);
    EXPECT_TRUE(has_warning(s, "Index of refraction value should be specified in 'interior{...}' statement."));
    EXPECT_TRUE(has_warning(s, "Refraction value unnecessary to turn on refraction."));
}

TEST(Grammar, FinishCausticsWarnsAndPartialRefractionMovesIntoTheInterior) {
    const Scene s = parse_ok(R"(
        sphere { 0, 1 pigment { rgbf 1 } finish { caustics 1 refraction 0.5 } }
        sphere { 0, 1 pigment { rgbf 1 } interior { refraction 0.5 } }
        union { sphere { 0, 1 } sphere { x, 1 } texture { pigment { rgbf 1 } finish { refraction 0.25 } } }
    )");
    EXPECT_TRUE(has_warning(s, "Caustics value should be specified in 'interior{...}' statement."));
    EXPECT_FALSE(has_warning(s, "not rendered"));
    ASSERT_EQ(s.objects.size(), 4u);
    EXPECT_EQ(s.objects[0].interior.refraction, 0.5);
    // POV-Ray compat (Post_Process, checked with povray 3.7): a plain texture's finish (refraction 1 unless given)
    // overrides the interior's own `refraction`.
    EXPECT_EQ(s.objects[1].interior.refraction, 1.0);
    EXPECT_EQ(s.objects[2].interior.refraction, 0.25);
    EXPECT_EQ(s.objects[3].interior.refraction, 0.25);
}

TEST(Grammar, MacroGivingAPigmentIsAnEntryOfAListPattern) {
    const Scene s = parse_ok(R"(
        #macro Tile(C) pigment { rgb C } #end
        sphere { 0, 1 pigment { hexagon Tile(<1, 0, 0>), Tile(<0, 1, 0>), Tile(<0, 0, 1>) } }
    )");
    const Pigment& p = s.objects[0].texture->pigment;
    ASSERT_EQ(p.pigment_map.size(), 3u);
    EXPECT_EQ(p.pigment_map[1].pigment.color.g, 1.0);
    EXPECT_EQ(p.pigment_map[2].pigment.color.b, 1.0);
}

TEST(Grammar, ColorMapEntryTakesFilterAndTransmitAfterAnExpression) {
    const Scene s = parse_ok(R"(
        #declare Red = <1, 0, 0>;
        sphere { 0, 1 pigment { gradient x color_map { [0 Red filter 0.5] [1 <0, 0, 1> transmit 0.25] } } }
    )");
    const auto& map = s.objects[0].texture->pigment.color_map;
    ASSERT_EQ(map.size(), 2u);
    EXPECT_EQ(map[0].color.r, 1.0);
    EXPECT_EQ(map[0].color.filter, 0.5);
    EXPECT_EQ(map[1].color.b, 1.0);
    EXPECT_EQ(map[1].color.transmit, 0.25);
}

TEST(Grammar, CameraAngleZeroLeavesTheDirection) {
    const Scene s = parse_ok("camera { location 0 direction 2 * z angle 0 }");
    EXPECT_EQ(s.camera.direction.z, 2.0);
    const ParseResult r = test::parse_fail("camera { location 0 angle -1 }");
    EXPECT_NE(test::all_diagnostics(r).find("Negative viewing angle."), std::string::npos);
}

TEST(Grammar, DivisionByZeroWarnsAndGivesAHugeValue) {
    const Scene s = parse_ok(R"(
        #declare Clock = 0;
        #declare A = -1 / Clock;
        #if (A < 1e300) #error "not huge" #end
    )");
    EXPECT_TRUE(has_warning(s, "Divide by zero."));
}

TEST(Grammar, BitwiseFunctionsTruncateToInts) {
    parse_ok(R"(
        #if (bitwise_and(12.7, 10) != 8 | bitwise_or(1, 2, 4) != 7 | bitwise_xor(6, 3) != 5) #error "bits" #end
    )");
}

TEST(Grammar, NowCountsDaysSince2000) {
    // 2024-01-01 is 8766 days after 2000-01-01; a scene read today is later than that.
    parse_ok("#if (now < 8766 | now > 80000) #error \"now is not in days since 2000\" #end");
}

TEST(Grammar, FrontEndIdentifiersCanBeDeclaredAnew) {
    parse_ok(R"(
        #declare image_width = 1920;
        #declare frame_number = 7;
        #if (image_width != 1920 | frame_number != 7) #error "not redeclared" #end
    )");
    const ParseResult r = test::parse_fail("#declare clock = 1;\n");
    EXPECT_NE(test::all_diagnostics(r).find("'clock' is a reserved word"), std::string::npos);
}

TEST(Grammar, UndefOfAnArrayElement) {
    parse_ok(R"(
        #declare A = array[2] { 1, 2 }
        #undef A[1]
        #ifdef (A[1]) #error "still defined" #end
        #declare A[1] = pigment { rgb 1 }
        #ifndef (A[1]) #error "not defined again" #end
    )");
}

TEST(Grammar, DeclaredObjectStandsAloneAsAnObject) {
    const Scene s = parse_ok(R"(
        #declare Ball = sphere { 0, 1 pigment { rgb 1 } }
        #declare Cut = box { -1, 1 }
        Ball
        union { Ball sphere { x, 1 } translate y }
        sphere { 0, 2 clipped_by { Cut scale 0.5 } }
    )");
    ASSERT_EQ(s.objects.size(), 4u);
    EXPECT_EQ(s.objects[2].transform.point({1, 0, 0}), (Vec3{1, 1, 0}));
    ASSERT_EQ(s.objects[3].clipped_by.size(), 1u);
    EXPECT_EQ(s.objects[3].clipped_by[0].transform.point({1, 1, 1}), (Vec3{0.5, 0.5, 0.5}));
}

TEST(Grammar, FloatDeclarationTakesASecondSemicolonEvenAfterItsFile) {
    TempDir dir;
    dir.write("floats.inc", "#declare R = 2;\n");
    dir.write("pigments.inc", "#declare P = pigment { rgb 1 }\n");
    const auto ok = dir.write("ok.pov", "global_settings { assumed_gamma 1 }\n#include \"floats.inc\";\n"
                                        "#declare S = 1;;\nsphere { 0, R + S }\n");
    const ParseResult r = parse_file(ok, test::default_options());
    ASSERT_TRUE(r.ok()) << test::all_diagnostics(r);
    // POV-Ray compat: after another kind of declaration the ';' is an error, as in POV-Ray.
    const auto bad = dir.write("bad.pov", "global_settings { assumed_gamma 1 }\n#include \"pigments.inc\";\n");
    EXPECT_FALSE(parse_file(bad, test::default_options()).ok());
}

TEST(Grammar, DeclareAndIncludeWithoutHashWarn) {
    TempDir dir;
    dir.write("r.inc", "#declare R = 3;\n");
    const auto main = dir.write("s.pov", "global_settings { assumed_gamma 1 }\ninclude \"r.inc\"\n"
                                         "declare Ball = sphere { 0, R }\nobject { Ball }\n");
    const ParseResult r = parse_file(main, test::default_options());
    ASSERT_TRUE(r.ok()) << test::all_diagnostics(r);
    ASSERT_EQ(r.scene->objects.size(), 1u);
    EXPECT_TRUE(has_warning(*r.scene, "Should have '#' before 'declare'."));
    EXPECT_TRUE(has_warning(*r.scene, "Should have '#' before 'include'."));
}

TEST(Grammar, MacroGivesOneOfItsLocalsStandingBeforeItsEnd) {
    parse_ok(R"(
        #macro Name(A) #local R = concat(A, "x"); R #end
        #macro Next(A) #local R = A + 1; R #end
        #macro Pair(A) #local R = array[2] { A, A }; R #end
        #declare R = "outer";
        #declare S = Name("a");
        #declare T = concat(Name("b"), "!");
        #declare N = Next(1);
        #declare P = Pair(3);
        #if (strcmp(S, "ax") != 0 | strcmp(T, "bx!") != 0 | N != 2 | P[1] != 3) #error "macro value" #end
    )");
}

TEST(Grammar, MacroCallTakesACommaAfterItsLastArgument) {
    const Scene s = parse_ok(R"(
        #macro Place(R, X) sphere { X * x, R } #end
        Place(1, 2, )
    )");
    ASSERT_EQ(s.objects.size(), 1u);
}

TEST(Grammar, NestedIncludeIsFoundFromTheSceneFolder) {
    TempDir dir;
    dir.write("scene/parts/a.inc", "#include \"parts/b.inc\"\n#include \"c.inc\"\n");
    dir.write("scene/parts/b.inc", "#declare B = 1;\n");
    dir.write("scene/parts/c.inc", "#declare C = 2;\n");
    dir.write("scene/c.inc", "#declare C = 3;\n");
    const auto main = dir.write("scene/s.pov", "global_settings { assumed_gamma 1 }\n#include \"parts/a.inc\"\n"
                                               "sphere { 0, B + C }\n");
    ParseResult r = parse_file(main, test::default_options());
    ASSERT_TRUE(r.ok()) << test::all_diagnostics(r);
    // POV-Ray finds c.inc in the scene's folder (its current folder), not beside a.inc.
    EXPECT_EQ(std::get<Sphere>(r.scene->objects[0].shape).radius, 4.0);
    // Found only beside the including file, a file is read, with a warning that POV-Ray would not find it.
    std::filesystem::remove(dir.path() / "scene/c.inc");
    r = parse_file(main, test::default_options());
    ASSERT_TRUE(r.ok()) << test::all_diagnostics(r);
    EXPECT_EQ(std::get<Sphere>(r.scene->objects[0].shape).radius, 3.0);
    EXPECT_TRUE(has_warning(*r.scene, "'c.inc' is found only beside the file including it"));
}

TEST(Grammar, AnElementOfAnArrayOfFunctionsIsCalled) {
    // Scenes from the wild keep functions in arrays and call them as F[i](x, y), at parse time and in functions.
    const Scene s = parse_ok(R"(
        #declare F = array[2];
        #declare F[0] = function(x) { x * 2 }
        #declare F[1] = function(x, y) { x + y + 10 }
        #declare G = function(x) { F[0](x) + F[1](x, 1) }
        #declare H = F[0](4) + 1;
        sphere { 0, F[1](5, 0) }
        sphere { 0, G(3) }
        sphere { 0, H }
    )");
    ASSERT_EQ(s.objects.size(), 3u);
    EXPECT_DOUBLE_EQ(std::get<Sphere>(s.objects[2].shape).radius, 9.0);
    EXPECT_DOUBLE_EQ(std::get<Sphere>(s.objects[0].shape).radius, 15.0);
    EXPECT_DOUBLE_EQ(std::get<Sphere>(s.objects[1].shape).radius, 6.0 + 14.0);
}

TEST(Grammar, AnImageNamedWithoutExtensionIsFoundByItsType) {
    // POV-Ray appends the extensions of the type named before the file (png: .png, jpeg: .jpg or .jpeg).
    TempDir dir;
    dir.write("scene/tex.png", "not read: the reader below is a stand-in");
    dir.write("scene/photo.jpeg", "not read either");
    const auto main = dir.write("scene/s.pov", "global_settings { assumed_gamma 1 }\n"
                                               "sphere { 0, 1 pigment { image_map { png \"tex\" } } }\n"
                                               "sphere { 0, 1 pigment { image_map { jpeg \"photo\" } } }\n");
    std::vector<std::string> opened;
    ParseOptions o = test::default_options();
    o.read_image = [&](const std::filesystem::path& file, bool& encoded, std::string&) {
        opened.push_back(file.filename().string());
        encoded = true;
        auto image = std::make_shared<ImageData>();
        image->width = image->height = 1;
        image->rgb = {0.5f, 0.5f, 0.5f};
        return image;
    };
    ParseResult r = parse_file(main, o);
    ASSERT_TRUE(r.ok()) << test::all_diagnostics(r);
    ASSERT_EQ(opened, (std::vector<std::string>{"tex.png", "photo.jpeg"}));
    EXPECT_TRUE(r.scene->objects[0].texture->pigment.image_map.has_value());
    // A type whose extensions do not match is still an error at the file name.
    dir.write("scene/t.pov", "sphere { 0, 1 pigment { image_map { gif \"tex\" } } }\n");
    r = parse_file(dir.path() / "scene/t.pov", o);
    EXPECT_FALSE(r.ok());
    EXPECT_NE(test::all_diagnostics(r).find("cannot open image file 'tex'"), std::string::npos);
}

TEST(Grammar, AUnionRedeclaredAroundItselfKeepsEveryPartInOrder) {
    // `#declare U = union { object { U } ... }` over and over (a scene from the wild does it 1,400 times): each
    // declaration copies U once and appends; the copies placed afterwards are whole and independent.
    const Scene s = parse_ok(R"(
        #declare U = sphere { 0, 1 }
        #for (I, 1, 30)
            #declare U = union { object { U } sphere { <I, 0, 0>, 1 } }
        #end
        object { U translate y }
        object { U pigment { rgb <1, 0, 0> } }
    )");
    ASSERT_EQ(s.objects.size(), 62u);
    for (int i = 0; i <= 30; ++i) {
        const Object& a = s.objects[i];
        const Object& b = s.objects[31 + i];
        EXPECT_EQ(a.transform.point(std::get<Sphere>(a.shape).center).x, double(i));
        EXPECT_EQ(a.transform.point(std::get<Sphere>(a.shape).center).y, 1.0);
        EXPECT_EQ(b.transform.point(std::get<Sphere>(b.shape).center).y, 0.0);
        EXPECT_EQ(b.texture->pigment.color.r, 1.0);
    }
}

TEST(Grammar, APigmentFunctionGivesItsHeightFieldItem) {
    // `.hf` (MegaPOV's item, still compiled by POV-Ray 3.7): red as the high byte, green as the low one, scaled
    // by 0.996093.
    ParseOptions o = test::default_options();
    o.pigment_value = [](const Pigment&, const Vec3& p, int) { return Color{0.5, 0.25 + p.x, 0.9, 0.0, 0.0}; };
    const Scene s = parse_ok(R"(
        #declare P = function { pigment { rgb 1 } }
        #declare F = function { P(x, y, z).hf }
        sphere { 0, F(0, 0, 0) }
        sphere { 0, F(0.5, 0, 0) }
    )", o);
    ASSERT_EQ(s.objects.size(), 2u);
    EXPECT_DOUBLE_EQ(std::get<Sphere>(s.objects[0].shape).radius, (0.5 + 0.25 / 255.0) * 0.996093);
    EXPECT_DOUBLE_EQ(std::get<Sphere>(s.objects[1].shape).radius, (0.5 + 0.75 / 255.0) * 0.996093);
}

TEST(Grammar, AMacroMayStandForAFunctionsWholeBody) {
    // A macro giving `pigment { ... }` is a pigment function's body; one giving an expression stays a float body.
    ParseOptions o = test::default_options();
    o.pigment_value = [](const Pigment& pg, const Vec3&, int) { return pg.color; };
    const Scene s = parse_ok(R"(
        #macro Pig(C) pigment { rgb C } #end
        #macro Half() x / 2 #end
        #declare P = function { Pig(<0.25, 0.5, 0.75>) }
        #declare F = function { Half() }
        sphere { 0, P(0, 0, 0).green }
        sphere { 0, F(3, 0, 0) }
    )", o);
    ASSERT_EQ(s.objects.size(), 2u);
    EXPECT_DOUBLE_EQ(std::get<Sphere>(s.objects[0].shape).radius, 0.5);
    EXPECT_DOUBLE_EQ(std::get<Sphere>(s.objects[1].shape).radius, 1.5);
}

}  // namespace
}  // namespace wardray::parser
