// Deep structure: 20,000 nested unions (made by a loop that redeclares, and written out as nested blocks) parse,
// build and render without overflowing the stack, and give the picture of the same spheres in one flat union.
#include <gtest/gtest.h>

#include <string>

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

Rendered render_text(const std::string& text) {
    parser::ParseOptions options;
    options.image_width = kWidth;
    options.image_height = kHeight;
    const parser::ParseResult parsed = parser::parse_string(text, "deep.pov", options);
    std::string errors;
    for (const Diagnostic& d : parsed.diagnostics) errors += format_diagnostic(d);
    EXPECT_TRUE(parsed.ok()) << errors;
    Rendered r;
    if (!parsed.ok()) return r;
    const geometry::SceneGeometry geometry(*parsed.scene);
    const lighting::Integrator integrator(*parsed.scene, geometry, lighting::IntegratorOptions{});
    RenderSettings settings;
    settings.width = kWidth;
    settings.height = kHeight;
    RenderResult result = render_image(*parsed.scene, integrator, settings, nullptr, nullptr);
    r.ok = result.non_finite_pixels == 0;
    r.objects = parsed.scene->objects.size();
    r.film = std::move(result.film);
    return r;
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

}  // namespace
}  // namespace wardray::render
