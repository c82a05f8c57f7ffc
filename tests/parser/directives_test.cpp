// Tests of the directive layer: #declare/#local scopes, #if, loops, #switch, #macro, #include, #version.
#include "tests/parser/test_util.h"

namespace wardray::parser {
namespace {

using test::parse_ok;
using test::TempDir;

double radius(const Scene& s, std::size_t i) { return std::get<Sphere>(s.objects.at(i).shape).radius; }

TEST(Directives, DeclareAndIf) {
    const Scene s = parse_ok(R"(
        #declare A = 2;
        #if (A > 1) sphere { 0, 1 } #else sphere { 0, 2 } #end
        #if (A < 1) sphere { 0, 3 } #elseif (A = 2) sphere { 0, 4 } #elseif (1) sphere { 0, 5 } #else sphere { 0, 6 } #end
        #ifdef (A) sphere { 0, 7 } #end
        #ifndef (B) sphere { 0, 8 } #end
        #undef A
        #ifdef (A) sphere { 0, 9 } #end
        #if (0) #if (1) sphere { 0, 10 } #end #else sphere { 0, 11 } #end
    )");
    ASSERT_EQ(s.objects.size(), 5u);
    EXPECT_EQ(radius(s, 0), 1);
    EXPECT_EQ(radius(s, 1), 4);
    EXPECT_EQ(radius(s, 2), 7);
    EXPECT_EQ(radius(s, 3), 8);
    EXPECT_EQ(radius(s, 4), 11);
}

TEST(Directives, WhileAndFor) {
    const Scene s = parse_ok(R"(
        #declare I = 0;
        #while (I < 3) sphere { 0, I + 1 } #declare I = I + 1; #end
        #for (J, 10, 4, -3) sphere { 0, J } #end
        #for (K, 1, 0) sphere { 0, 99 } #end
    )");
    ASSERT_EQ(s.objects.size(), 6u);
    EXPECT_EQ(radius(s, 0), 1);
    EXPECT_EQ(radius(s, 2), 3);
    EXPECT_EQ(radius(s, 3), 10);
    EXPECT_EQ(radius(s, 4), 7);
    EXPECT_EQ(radius(s, 5), 4);
}

// POV-Ray widens a #for loop's end by 1e-10: 2.6 + 5 * 0.4 rounds to 4.6000000000000005 and still runs (as in
// POV-Ray 3.7, counted with #debug), and so does a descending loop whose sum rounds just below its end.
TEST(Directives, ForLoopEndHasPovRaysTolerance) {
    const Scene s = parse_ok(R"(
        #for (Y, 2.6, 4.6, 0.4) sphere { 0, Y } #end
        #for (Z, 0.7, 0.1, -0.2) sphere { 0, Z } #end
        #for (W, 1, 1 - 1e-11) sphere { 0, 50 } #end
        #for (V, 0, 1, 0.6) sphere { 0, 60 + V } #end
    )");
    ASSERT_EQ(s.objects.size(), 6u + 4u + 1u + 2u);
    EXPECT_NEAR(radius(s, 5), 4.6, 1e-12);
    EXPECT_NEAR(radius(s, 9), 0.1, 1e-12);
    EXPECT_EQ(radius(s, 10), 50);
    EXPECT_NEAR(radius(s, 12), 60.6, 1e-12);
}

// POV-Ray 3.7 decides what a lone float, vector or colour identifier argument refers to after reading the next
// token, so with no comma before another identifier the argument becomes that one: M(1, P Q R, 5) binds B, C and
// D to Q, R and R (measured with #debug in POV-Ray 3.7, also for parameters passed on inside a macro).
TEST(Directives, MacroArgumentBeforeAnIdentifierWithoutACommaTakesThatIdentifier) {
    const Scene s = parse_ok(R"(
        #macro M(A, B C D, E) sphere { 0, A } sphere { 0, B } sphere { 0, C } sphere { 0, D } sphere { 0, E } #end
        #declare P = 10; #declare Q = 20; #declare R = 30;
        M(1, P Q R, 5)
        #macro W(A, B
          C
          D, E) M(A, B
          C
          D, E) #end
        W(1, 2, 3, 4, 5)
        M(1, P, Q, R, 5)
        M(1 2 3 4 5)
    )");
    ASSERT_EQ(s.objects.size(), 20u);
    const double expected[20] = {1, 20, 30, 30, 5, 1, 3, 4, 4, 5, 1, 10, 20, 30, 5, 1, 2, 3, 4, 5};
    for (std::size_t i = 0; i < 20; ++i) EXPECT_EQ(radius(s, i), expected[i]) << "sphere " << i;
}

TEST(Directives, BreakLeavesLoop) {
    const Scene s = parse_ok(R"(
        #declare I = 0;
        #while (1)
          #declare I = I + 1;
          #if (I = 3) #break #end
          sphere { 0, I }
        #end
        sphere { 0, 100 }
    )");
    ASSERT_EQ(s.objects.size(), 3u);
    EXPECT_EQ(radius(s, 2), 100);
}

TEST(Directives, Switch) {
    const Scene s = parse_ok(R"(
        #declare V = 2;
        #switch (V)
          #case (1) sphere { 0, 1 } #break
          #range (2, 3) sphere { 0, 2 }
          #case (4) sphere { 0, 4 } #break
          #else sphere { 0, 5 }
        #end
        #switch (7) #case (1) sphere { 0, 6 } #break #else sphere { 0, 7 } #end
    )");
    ASSERT_EQ(s.objects.size(), 3u);
    EXPECT_EQ(radius(s, 0), 2);
    EXPECT_EQ(radius(s, 1), 4);  // no #break: falls through
    EXPECT_EQ(radius(s, 2), 7);
}

TEST(Directives, MacrosReturnValuesAndObjects) {
    const Scene s = parse_ok(R"(
        #macro Twice(A) (2 * A) #end
        #macro Ball(R, optional C) sphere { 0, R } #end
        #macro Fact(N) #if (N <= 1) 1 #else N * Fact(N - 1) #end #end
        sphere { 0, Twice(3) + 1 }
        Ball(5)
        sphere { 0, Fact(4) }
        #macro Sum3(A, B, C) #local T = A + B; T + C #end
        sphere { 0, Sum3(1, 2, 3) }
    )");
    ASSERT_EQ(s.objects.size(), 4u);
    EXPECT_EQ(radius(s, 0), 7);
    EXPECT_EQ(radius(s, 1), 5);
    EXPECT_EQ(radius(s, 2), 24);
    EXPECT_EQ(radius(s, 3), 6);
}

TEST(Directives, MacroParametersByReference) {
    const Scene s = parse_ok(R"(
        #macro Inc(V) #declare V = V + 1; #end
        #macro Turn(Stuff, Degrees) #declare Stuff = object { Stuff rotate y * Degrees } #end
        #declare Value = 5;
        Inc(Value)
        Inc(Value + 0)
        #declare Thing = sphere { <0, 0, 1>, Value }
        Turn(Thing, 90)
        object { Thing }
    )");
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_EQ(radius(s, 0), 6);  // an expression argument is passed by value
    const Vec3 c = s.objects[0].transform.point(std::get<Sphere>(s.objects[0].shape).center);
    EXPECT_NEAR(c.x, 1.0, 1e-12);
}

// povray 3.7 on macro4.pov's pattern prints 5, 5, 6 and then 7 through a macro passing its parameter on.
TEST(Directives, LocalOnReferenceParameterWritesCaller) {
    const Scene s = parse_ok(R"(
        #macro Inc(V) #local V = V + 1; #end
        #macro IncTwice(W) Inc(W) #end
        #declare Value = 5;
        Inc(Value + 0) sphere { 0, Value }
        Inc(+Value) sphere { 0, Value }
        Inc(Value) sphere { 0, Value }
        IncTwice(Value) sphere { 0, Value }
    )");
    ASSERT_EQ(s.objects.size(), 4u);
    EXPECT_EQ(radius(s, 0), 5);
    EXPECT_EQ(radius(s, 1), 5);
    EXPECT_EQ(radius(s, 2), 6);
    EXPECT_EQ(radius(s, 3), 7);
}

// Values checked with povray 3.7: directives inside a macro body run when the call is an operand of an object's
// expression or stands in parentheses; at the top level of a #declare POV-Ray stops at the directive.
TEST(Directives, MacroBodyWithConditionalsInsideArithmetic) {
    const Scene s = parse_ok(R"(
        #macro M(A) #if (A) 1 #else 2 #end #end
        #macro N(A) #if (A) 1 #elseif (A + 1) 3 #else 2 #end + 5 #end
        #macro S(A) #switch (A) #case (0) 7 #break #else 8 #end #end
        sphere { 0, M(0) + 10 }
        sphere { 0, M(1) * 3 + 10 }
        #declare V = (M(0)) + 10;
        sphere { 0, V }
        #declare W = <M(0), M(1) + 1, 3>;
        sphere { W, 1 }
        #declare P = (N(0) + 10) + (N(-1) * 2) + 100 * (S(0) + S(1) * 10);
        sphere { 0, P }
    )");
    ASSERT_EQ(s.objects.size(), 5u);
    EXPECT_EQ(radius(s, 0), 12);
    EXPECT_EQ(radius(s, 1), 13);
    EXPECT_EQ(radius(s, 2), 12);
    const Vec3 w = std::get<Sphere>(s.objects[3].shape).center;
    EXPECT_EQ(w.x, 2);
    EXPECT_EQ(w.y, 2);
    EXPECT_EQ(radius(s, 4), 8729);

    const ParseResult r = test::parse_fail("#macro M(A) #if (A) 1 #else 2 #end #end\n#declare V = M(0) + 10;\n");
    ASSERT_FALSE(r.diagnostics.empty());
    EXPECT_EQ(r.diagnostics[0].loc.line, 1u);
    EXPECT_EQ(r.diagnostics[0].loc.column, 31u);  // the #end of the #if, where the value stopped
    EXPECT_NE(r.diagnostics[0].message.find("put the macro call in parentheses"), std::string::npos);
}

// woods.inc declares textures without ';' and layers later ones on earlier ones, array1.pov an array: the next
// #declare must not run while the layers of the previous one, or its array sizes, are looked for.
TEST(Directives, DeclarationEndsAtTheNextDirective) {
    const Scene s = parse_ok(R"(
        #declare T1 = texture { pigment { rgb 1 } }
        #declare T2 = texture { T1 } texture { pigment { rgbt <0, 0, 1, 0.5> } }
        #declare T3 = texture { T2 }
        sphere { 0, 1 texture { T3 } }
        #declare A = array[2]
        #declare A[1] = 3;
        sphere { 0, A[1] }
    )");
    ASSERT_EQ(s.objects.size(), 2u);
    EXPECT_EQ(s.objects[0].texture->layers.size(), 1u);
    EXPECT_EQ(radius(s, 1), 3);
}

// povray 3.7: `M(1 2)` passes two arguments, `M(P -1)` one (P - 1), then misses the second.
TEST(Directives, MacroArgumentCommasAreOptional) {
    const Scene s = parse_ok(R"(
        #macro M(A, B) A * 10 + B #end
        #macro Place(O, V) object { O translate V } #end
        sphere { 0, M(1 2) }
        Place(sphere { 0, 1 } -y)
    )");
    ASSERT_EQ(s.objects.size(), 2u);
    EXPECT_EQ(radius(s, 0), 12);
    EXPECT_EQ(s.objects[1].transform.point({0, 0, 0}).y, -1);
    const ParseResult r = test::parse_fail("#declare P = 1;\n#macro M(A, B) A #end\nsphere { 0, M(P -1) }\n");
    EXPECT_NE(test::all_diagnostics(r).find("missing parameter 'B'"), std::string::npos) << test::all_diagnostics(r);
}

// tracevines.pov: a macro's value ends with ';' inside its #if, so the #local that called it completes while the
// macro is still being read; povray 3.7 binds the name where the #local stands (prints n=1,2,3).
TEST(Directives, LocalFromMacroValueBindsInTheCallersScope) {
    const Scene s = parse_ok(R"(
        #macro F(A) #local Q = A; #if (1) Q; #else <0, 0, 0>; #end #end
        #macro G() #local N = F(<1, 2, 3>) sphere { N, 1 } #end
        G()
    )");
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_EQ(std::get<Sphere>(s.objects[0].shape).center.z, 3);
}

TEST(Directives, LocalIsScopedToIncludeFile) {
    TempDir dir;
    dir.write("inc.inc", "#local L = 5;\n#declare G = L + 1;\n#declare A = 10;\n");
    const auto main = dir.write("scene.pov",
                                "global_settings { assumed_gamma 1 }\n#declare A = 1; #local L = 2;\n"
                                "#include \"inc.inc\"\nsphere { 0, G } sphere { 0, L } sphere { 0, A }\n");
    const ParseResult r = parse_file(main, test::default_options());
    ASSERT_TRUE(r.ok()) << test::all_diagnostics(r);
    EXPECT_EQ(radius(*r.scene, 0), 6);
    EXPECT_EQ(radius(*r.scene, 1), 2);  // the include's #local L did not leak
    EXPECT_EQ(radius(*r.scene, 2), 10);  // #declare in the include wrote the global
}

TEST(Directives, DeclareInsideMacroWritesGlobal) {
    const Scene s = parse_ok(R"(
        #declare C = 1;
        #macro Bump() #declare C = C + 1; #local C = 100; #end
        Bump()
        sphere { 0, C }
    )");
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_EQ(radius(s, 0), 2);
}

TEST(Directives, IncludeSearchOrder) {
    TempDir dir;
    dir.write("lib1/a.inc", "#declare Which = 1;");
    dir.write("lib2/a.inc", "#declare Which = 2;");
    dir.write("lib2/b.inc", "#declare Other = 3;");
    dir.write("scenes/a.inc", "#declare Which = 0;");
    dir.write("scenes/sub/nested.inc", "#include \"sibling.inc\"");
    dir.write("scenes/sub/sibling.inc", "#declare Sib = 4;");
    const auto main = dir.write("scenes/s.pov",
                                "global_settings { assumed_gamma 1 }\n#include \"a.inc\"\n#include \"b\"\n"
                                "#include \"sub/nested.inc\"\nsphere { <Which, Other, Sib>, 1 }\n");
    ParseOptions o;
    o.library_paths = {dir.path() / "lib1", dir.path() / "lib2"};
    ParseResult r = parse_file(main, o);
    ASSERT_TRUE(r.ok()) << test::all_diagnostics(r);
    EXPECT_EQ(std::get<Sphere>(r.scene->objects[0].shape).center, (Vec3{0, 3, 4}));
    // Without the scene's own copy the library paths are searched in order.
    std::filesystem::remove(dir.path() / "scenes/a.inc");
    r = parse_file(main, o);
    ASSERT_TRUE(r.ok()) << test::all_diagnostics(r);
    EXPECT_EQ(std::get<Sphere>(r.scene->objects[0].shape).center.x, 1);
}

TEST(Directives, IncludeChainNotes) {
    TempDir dir;
    dir.write("outer.inc", "// outer\n#include \"inner.inc\"\n");
    dir.write("inner.inc", "#declare X = 1;\n#declare Y = Gren;\n");
    const auto main = dir.write("s.pov", "#declare Green = 1;\n\n#include \"outer.inc\"\n");
    const ParseResult r = parse_file(main, test::default_options());
    ASSERT_FALSE(r.ok());
    ASSERT_GE(r.diagnostics.size(), 1u);
    const Diagnostic& d = r.diagnostics[0];
    EXPECT_EQ(d.loc.path, (dir.path() / "inner.inc").string());
    EXPECT_EQ(d.loc.line, 2u);
    ASSERT_EQ(d.notes.size(), 3u);
    EXPECT_EQ(d.notes[0], "did you mean 'Green'?");
    EXPECT_EQ(d.notes[1], "included from " + (dir.path() / "outer.inc").string() + ":2");
    EXPECT_EQ(d.notes[2], "included from " + main.string() + ":3");
}

TEST(Directives, MissingIncludeIsAnError) {
    const ParseResult r = test::parse_fail("#include \"no_such_file.inc\"\n");
    ASSERT_EQ(test::count_errors(r), 1u);
    EXPECT_EQ(r.diagnostics[0].message, "cannot open include file 'no_such_file.inc': No such file or directory");
}

TEST(Directives, RecursiveIncludeStopsAtDepthLimit) {
    TempDir dir;
    const auto main = dir.write("loop.pov", "#include \"loop.pov\"\n");
    const ParseResult r = parse_file(main, test::default_options());
    ASSERT_FALSE(r.ok());
    EXPECT_NE(test::all_diagnostics(r).find("limit of 64"), std::string::npos) << test::all_diagnostics(r);
}

TEST(Directives, EndlessLoopAndRecursionAreBounded) {
    ParseResult r = test::parse_fail("#while (1) #end\n");
    EXPECT_NE(test::all_diagnostics(r).find("10000000"), std::string::npos);
    r = test::parse_fail("#macro M() M() #end\nsphere { 0, M() }\n");
    EXPECT_NE(test::all_diagnostics(r).find("limit"), std::string::npos);
}

TEST(Directives, VersionSaveRestoreAndDefault) {
    Scene s = parse_ok("sphere { 0, version }");
    EXPECT_DOUBLE_EQ(s.version, 3.7);
    s = parse_ok("#version 3.6;\n#local Ver = version;\n#version 3.5;\nsphere { 0, version }\n#version Ver;\n");
    EXPECT_DOUBLE_EQ(radius(s, 0), 3.5);
    EXPECT_DOUBLE_EQ(s.version, 3.6);
}

TEST(Directives, CommandLineDeclares) {
    ParseOptions o = test::default_options();
    o.declares = {{"Size", 2.5}};
    const Scene s = parse_ok("sphere { 0, Size }", o);
    EXPECT_DOUBLE_EQ(radius(s, 0), 2.5);
}

TEST(Directives, WarningDebugAndError) {
    Scene s = parse_ok("#debug \"hello\\n\"\n#warning concat(\"careful \", \"now\")\n");
    ASSERT_FALSE(s.warnings.empty());
    EXPECT_EQ(s.warnings[0].message, "careful now");
    EXPECT_EQ(s.warnings[0].loc.line, 3u);
    const ParseResult r = test::parse_fail("#error \"stop here\"\nsphere { 0, Undeclared }\n");
    ASSERT_EQ(test::count_errors(r), 1u);  // #error ends the parse
    EXPECT_EQ(r.diagnostics[0].message, "stop here");
}

TEST(Directives, DefaultTexture) {
    const Scene s = parse_ok(R"(
        sphere { 0, 1 }
        #default { finish { ambient 0 diffuse 0.9 } pigment { rgb <1, 0, 0> } }
        sphere { 0, 2 }
        sphere { 0, 3 finish { phong 1 } }
    )");
    ASSERT_EQ(s.objects.size(), 3u);
    EXPECT_DOUBLE_EQ(s.objects[0].texture->finish.diffuse, 0.6);
    EXPECT_DOUBLE_EQ(s.objects[1].texture->finish.diffuse, 0.9);
    EXPECT_DOUBLE_EQ(s.objects[1].texture->pigment.color.r, 1.0);
    EXPECT_DOUBLE_EQ(s.objects[2].texture->finish.diffuse, 0.9);  // a finish block starts from the default
    EXPECT_DOUBLE_EQ(s.objects[2].texture->finish.ambient.r, 0.0);
    EXPECT_DOUBLE_EQ(s.objects[2].texture->finish.phong, 1.0);
}

TEST(Directives, Arrays) {
    const Scene s = parse_ok(R"(
        #declare A = array[3] { 1, 2, 3 };
        #declare M = array[2][2] { { 1, 2 } { 3, 4 } };
        #declare P = array[2];
        #declare P[1] = pigment { rgb <0, 0, 1> };
        #declare S = array[2] { "ab" "cde" };
        #declare B = A;
        #declare B[0] = 100;
        sphere { 0, A[0] + A[2] * 10 }
        sphere { 0, M[1][0] + dimensions(M) * 10 + dimension_size(A, 1) * 100 }
        sphere { 0, 1 pigment { P[1] } }
        sphere { 0, strlen(S[1]) + defined(P[0]) + 10 * defined(P[1]) }
        sphere { 0, A[0] }
    )");
    ASSERT_EQ(s.objects.size(), 5u);
    EXPECT_EQ(radius(s, 0), 31);
    EXPECT_EQ(radius(s, 1), 323);
    EXPECT_EQ(s.objects[2].texture->pigment.color.b, 1);
    EXPECT_EQ(radius(s, 3), 13);
    EXPECT_EQ(radius(s, 4), 1);  // B is a copy
    ParseResult r = test::parse_fail("#declare A = array[2];\nsphere { 0, A[2] }\n");
    EXPECT_NE(r.diagnostics[0].message.find("out of range"), std::string::npos);
    r = test::parse_fail("#declare A = array[2];\nsphere { 0, A[1] }\n");
    EXPECT_NE(r.diagnostics[0].message.find("before it was assigned"), std::string::npos);
}

TEST(Directives, StringComparisonAndRand) {
    const Scene s = parse_ok(R"(
        #declare F = "";
        #if (F != "") sphere { 0, 1 } #else sphere { 0, 2 } #end
        #declare R1 = seed(42);
        #declare R2 = seed(42);
        #declare V1 = rand(R1);
        #declare V2 = rand(R2);
        #declare V3 = rand(R1);
        sphere { <V1, V2, V3>, 1 }
    )");
    ASSERT_EQ(s.objects.size(), 2u);
    EXPECT_EQ(radius(s, 0), 2);
    const Vec3 v = std::get<Sphere>(s.objects[1].shape).center;
    EXPECT_EQ(v.x, v.y);  // same seed, same sequence
    EXPECT_NE(v.x, v.z);
    // POV-Ray 3.7's own values, printed by `povray +W16 +H12 -D` for
    // `#declare S = seed(42); #debug concat(str(rand(S), 0, 6), " ", str(rand(S), 0, 6))` and for seed(0).
    EXPECT_NEAR(v.x, 0.723583, 5e-7);
    EXPECT_NEAR(v.z, 0.329979, 5e-7);
    const Scene zero = parse_ok("#declare S = seed(0);\nsphere { 0, rand(S) }\n");
    EXPECT_NEAR(radius(zero, 0), 0.000003, 5e-7);
}

TEST(Directives, UnusedDeclarationsDoNotWarn) {
    Scene s = parse_ok("#declare C = finish { subsurface { translucency 0.5 } }\n"
                       "#declare P = texture { pigment { rgb 1 } no_bump_scale }\nsphere { 0, 1 }\n");
    EXPECT_TRUE(s.warnings.empty());
    s = parse_ok("#declare F = finish { subsurface { translucency 0.5 } }\n#declare G = finish { F }\n"
                 "sphere { 0, 1 finish { G } }\n");
    ASSERT_EQ(s.warnings.size(), 1u);
    EXPECT_EQ(s.warnings[0].message, "subsurface is not rendered yet");
    EXPECT_EQ(s.warnings[0].loc.line, 2u);  // where the feature is written
}

TEST(Directives, StandardIncludesParse) {
    for (const char* inc : {"colors.inc", "textures.inc", "metals.inc", "golds.inc", "finish.inc", "stones.inc",
                            "woods.inc", "glass.inc", "shapes.inc", "math.inc", "transforms.inc", "skies.inc"}) {
        const ParseResult r = parse_string(std::string("#include \"") + inc + "\"\n", "inc.pov",
                                           test::default_options());
        if (std::string(inc) == "colors.inc") {
            EXPECT_TRUE(r.ok()) << inc << "\n" << test::all_diagnostics(r);
            for (const auto& d : r.diagnostics) EXPECT_NE(d.severity, Severity::Error) << format_diagnostic(d);
        }
        // Whatever is unsupported must come with a location, never a crash.
        for (const auto& d : r.diagnostics) {
            if (d.message.rfind("assumed_gamma", 0) == 0) continue;
            EXPECT_GT(d.loc.line, 0u) << inc << ": " << format_diagnostic(d);
        }
    }
}

TEST(Directives, ColorsIncColours) {
    const Scene s = parse_ok("#include \"colors.inc\"\nbackground { color Gold }\n"
                             "sphere { 0, 1 pigment { Red } } sphere { 0, 1 pigment { color MediumForestGreen } }");
    EXPECT_NEAR(s.background.r, 0.8, 1e-12);
    EXPECT_NEAR(s.background.g, 0.498039, 1e-12);
    ASSERT_EQ(s.objects.size(), 2u);
    EXPECT_EQ(s.objects[0].texture->pigment.color.r, 1.0);
    EXPECT_NEAR(s.objects[1].texture->pigment.color.g, 0.556863, 1e-12);
}

TEST(Directives, DeclareRebindsTheInnermostExistingName) {
    // shapes.inc's HF macros count with `#local K = 0; ... #declare K = K + 1;`: the macro's K must change.
    const Scene s = parse_ok(R"(
        #declare K = 100;
        #macro Count()
            #local K = 0;
            #while (K < 3) #declare K = K + 1; #end
            sphere { 0, K }
        #end
        Count()
        sphere { 0, K }
    )");
    ASSERT_EQ(s.objects.size(), 2u);
    EXPECT_EQ(radius(s, 0), 3);
    EXPECT_EQ(radius(s, 1), 100);  // the global is untouched
}

TEST(Directives, StrayHashIsAWarning) {
    const Scene s = parse_ok("sphere { 0, 1 # }\n");
    ASSERT_EQ(s.warnings.size(), 1u);
    EXPECT_EQ(s.warnings[0].message, "'#' without a directive name is ignored");
}

}  // namespace
}  // namespace wardray::parser
