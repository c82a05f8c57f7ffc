// Deep structure: 20,000 nested unions (made by a loop that redeclares, and written out as nested blocks) parse,
// build and render without overflowing the stack, and give the picture of the same spheres in one flat union;
// nested intersections and merges become one node whose picture is the nested tree's, byte for byte.
#include <gtest/gtest.h>

#include <cstdint>
#include <set>
#include <string>
#include <variant>
#include <vector>

#include "geometry/scene_geometry.h"
#include "lighting/integrator.h"
#include "parser/parse.h"
#include "render/film.h"
#include "render/renderer.h"

namespace wardray::render {
namespace {

constexpr int kWidth = 40;
constexpr int kHeight = 30;
constexpr int kLevels = 20000;

const char* const kHeader = "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n"
                            "camera { location <0, 0, -6> look_at 0 }\nlight_source { <10, 10, -10> rgb 1 }\n";

// The i-th small sphere, with the loop's expressions for its place and colour (so the values are the same bits).
std::string small_sphere(int i) {
    const std::string k = std::to_string(i % 400);
    return "sphere { <mod(" + k + ", 20) * 0.2 - 1.9, div(" + k + ", 20) * 0.2 - 1.9, -1.6>, 0.08 pigment { rgb <" +
           std::to_string(i % 7) + " / 7, 0.6, 0.3> } }";
}

const char* const kFirst = "sphere { 0, 1.5 pigment { rgb 0.8 } }";

std::string redeclared() {
    return std::string(kHeader) + "#declare U = " + kFirst + "\n#for (I, 0, " + std::to_string(kLevels - 1) +
           ")\n  #declare K = mod(I, 400);\n"
           "  #declare U = union { object { U } sphere { <mod(K, 20) * 0.2 - 1.9, div(K, 20) * 0.2 - 1.9, -1.6>, "
           "0.08 pigment { rgb <mod(I, 7) / 7, 0.6, 0.3> } } }\n#end\nobject { U }\n";
}

std::string nested() {
    std::string s = kHeader;
    for (int i = 0; i < kLevels; ++i) s += "union {\n";
    s += std::string(kFirst) + "\n";
    for (int i = 0; i < kLevels; ++i) s += small_sphere(i) + " }\n";
    return s;
}

std::string shallow() {
    std::string s = std::string(kHeader) + "union {\n" + kFirst + "\n";
    for (int i = 0; i < kLevels; ++i) s += small_sphere(i) + "\n";
    return s + "}\n";
}

struct Rendered {
    bool ok = false;
    std::size_t objects = 0;
    Film film{kWidth, kHeight};
};

parser::ParseResult parse_text(const std::string& text) {
    parser::ParseOptions options;
    options.image_width = kWidth;
    options.image_height = kHeight;
    parser::ParseResult parsed = parser::parse_string(text, "deep.pov", options);
    std::string errors;
    for (const Diagnostic& d : parsed.diagnostics) errors += format_diagnostic(d);
    EXPECT_TRUE(parsed.ok()) << errors;
    return parsed;
}

Rendered render_scene(const scene::Scene& scene) {
    Rendered r;
    const geometry::SceneGeometry geometry(scene);
    const lighting::Integrator integrator(scene, geometry, lighting::IntegratorOptions{});
    RenderSettings settings;
    settings.width = kWidth;
    settings.height = kHeight;
    RenderResult result = render_image(scene, integrator, settings, nullptr, nullptr);
    r.ok = result.non_finite_pixels == 0;
    r.objects = scene.objects.size();
    r.film = std::move(result.film);
    return r;
}

Rendered render_text(const std::string& text) {
    const parser::ParseResult parsed = parse_text(text);
    if (!parsed.ok()) return {};
    return render_scene(*parsed.scene);
}

TEST(DeepCsg, TwentyThousandNestedUnionsRenderAsTheFlatUnion) {
    const Rendered flat = render_text(shallow());
    ASSERT_TRUE(flat.ok);
    ASSERT_EQ(flat.objects, static_cast<std::size_t>(kLevels + 1));
    for (const auto& [name, text] : {std::pair{"redeclared", redeclared()}, std::pair{"nested", nested()}}) {
        const Rendered deep = render_text(text);
        ASSERT_TRUE(deep.ok) << name;
        EXPECT_EQ(deep.objects, flat.objects) << name;
        EXPECT_TRUE(deep.film.data() == flat.film.data()) << name << ": not the flat union's pixels";
    }
}

constexpr int kCsgLevels = 40;

// The i-th sphere of a nested intersection or merge: each a little off centre and coloured, so the picture shows
// which child's crossing each pixel kept.
std::string offset_sphere(int i) {
    return "sphere { <0.3 * sin(" + std::to_string(i) + "), 0.3 * cos(" + std::to_string(i) + "), 0>, 1.6 + 0.002 * " +
           std::to_string(i) + " pigment { rgb <mod(" + std::to_string(i) + ", 7) / 7, 0.6, 0.3> } }";
}

// kCsgLevels levels of `op { A_i <level i - 1> B_i }`, the first sphere innermost: the nested node stands between
// two siblings, so it is neither its parent's first child nor its last.
std::string nested_between(const std::string& op) {
    std::string s = kHeader;
    for (int i = kCsgLevels - 1; i >= 0; --i) s += op + " {\n" + offset_sphere(2 * i + 1) + "\n";
    s += std::string(kFirst) + "\n";
    for (int i = 0; i < kCsgLevels; ++i) s += offset_sphere(2 * i + 2) + " }\n";
    return s;
}

// The nested tree nested_between wrote, built again from the flat node's children (A_{n-1} .. A_0, first, B_0 ..
// B_{n-1}) without the parser, so it renders as a tree of kCsgLevels nodes.
scene::Object unflattened(const scene::Object& flat) {
    const auto& kids = std::get<scene::Csg>(flat.shape).children;
    const auto op = std::get<scene::Csg>(flat.shape).op;
    const std::size_t n = kCsgLevels;
    scene::Object level = kids[n];
    for (std::size_t i = 0; i < n; ++i) {
        scene::Csg csg;
        csg.op = op;
        csg.children = {kids[n - 1 - i], std::move(level), kids[n + 1 + i]};
        scene::Object node = i + 1 == n ? flat : scene::Object{};
        node.shape = std::move(csg);
        level = std::move(node);
    }
    return level;
}

TEST(DeepCsg, NestedIntersectionsAndMergesAtAnyPositionAreOneNodeWithTheTreesPixels) {
    for (const std::string op : {"intersection", "merge"}) {
        parser::ParseResult parsed = parse_text(nested_between(op));
        ASSERT_TRUE(parsed.ok()) << op;
        ASSERT_EQ(parsed.scene->objects.size(), 1u) << op;
        const scene::Object& flat = parsed.scene->objects.front();
        const auto* csg = std::get_if<scene::Csg>(&flat.shape);
        ASSERT_NE(csg, nullptr) << op;
        ASSERT_EQ(csg->children.size(), static_cast<std::size_t>(2 * kCsgLevels + 1)) << op << ": not one node";
        for (const scene::Object& child : csg->children)
            ASSERT_FALSE(std::holds_alternative<scene::Csg>(child.shape)) << op << ": a nested node was left";
        const Rendered one_node = render_scene(*parsed.scene);
        scene::Scene tree = *parsed.scene;
        tree.objects.front() = unflattened(flat);
        const Rendered nested = render_scene(tree);
        ASSERT_TRUE(one_node.ok && nested.ok) << op;
        EXPECT_TRUE(one_node.film.data() == nested.film.data()) << op << ": not the nested tree's pixels";
        // Not a blank picture: the kept crossings belong to several children.
        std::set<float> values(one_node.film.data().begin(), one_node.film.data().end());
        EXPECT_GT(values.size(), 8u) << op;
    }
}

TEST(DeepCsg, ADifferenceSplicesOnlyAsTheFirstChild) {
    // (A - B) - C is A - B - C; A - (B - C) keeps its inner node.
    const std::string first_child = std::string(kHeader) +
        "difference { difference { sphere { 0, 1 } sphere { x, 0.5 } } sphere { -x, 0.5 } }\n";
    const std::string second_child = std::string(kHeader) +
        "difference { sphere { 0, 1 } difference { sphere { x, 0.5 } sphere { x, 0.2 } } }\n";
    const parser::ParseResult a = parse_text(first_child);
    const parser::ParseResult b = parse_text(second_child);
    ASSERT_TRUE(a.ok() && b.ok());
    EXPECT_EQ(std::get<scene::Csg>(a.scene->objects.front().shape).children.size(), 3u);
    const auto& kept = std::get<scene::Csg>(b.scene->objects.front().shape).children;
    ASSERT_EQ(kept.size(), 2u);
    EXPECT_TRUE(std::holds_alternative<scene::Csg>(kept[1].shape));
}

TEST(DeepCsg, ATreeTooDeepToFlattenIsLeftOutNotAStackOverflow) {
    // 5,000 levels of `difference { A <level i - 1> }`: not flattened (A - (B - C) is not A - B - C), so the geometry
    // refuses the object past 1,000 levels instead of recursing off the stack (SIGSEGV before).
    constexpr int levels = 5000;
    std::string text = kHeader;
    for (int i = levels - 1; i >= 0; --i) text += "difference {\nsphere { 0, " + std::to_string(1.5 + 0.001 * i) + " }\n";
    text += std::string(kFirst) + "\n";
    for (int i = 0; i < levels; ++i) text += "}\n";
    text += "sphere { <1, 1, 0>, 0.5 pigment { rgb 1 } }\n";
    const parser::ParseResult parsed = parse_text(text);
    ASSERT_TRUE(parsed.ok());
    ASSERT_EQ(parsed.scene->objects.size(), 2u);
    const geometry::SceneGeometry geometry(*parsed.scene);
    ASSERT_EQ(geometry.skipped_objects(), std::vector<std::uint32_t>{0});
    // The reason names the depth and where level 1001 is written: two lines a level below the statement.
    ASSERT_EQ(geometry.skip_reasons().size(), 1u);
    const geometry::SkipReason& why = geometry.skip_reasons().front();
    EXPECT_TRUE(why.too_deep);
    EXPECT_EQ(why.where.line, parsed.scene->objects.front().loc.line + 2 * geometry::max_csg_depth());
    EXPECT_TRUE(render_scene(*parsed.scene).ok);
}

}  // namespace
}  // namespace wardray::render
