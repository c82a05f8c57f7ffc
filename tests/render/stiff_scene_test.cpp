// Stiff and extreme scenes under direct lighting: scale invariance from 1e-6 to 1e6 (and of fog), degenerate and
// sliver triangles, coincident surfaces, grazing lights, light colours across twelve decades, a camera inside a solid.
// Every render must be finite and match the picture the scene's geometry implies.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "cache/irradiance_cache.h"
#include "geometry/scene_geometry.h"
#include "lighting/integrator.h"
#include "parser/parse.h"
#include "render/film.h"
#include "render/image_metrics.h"
#include "render/renderer.h"

namespace wardray::render {
namespace {

namespace fs = std::filesystem;

constexpr int kWidth = 64;
constexpr int kHeight = 48;

struct Rendered {
    Film film;
    std::uint64_t non_finite = 0;
};

// Parses `text` with `declares`, builds it and renders it (with direct light only unless `radiosity`, then through
// the irradiance cache with its pretrace); fails the test on a scene error.
Rendered render_text(const std::string& text, const std::vector<std::pair<std::string, double>>& declares = {},
                     bool radiosity = false) {
    parser::ParseOptions options;
    options.declares = declares;
    options.image_width = kWidth;
    options.image_height = kHeight;
    const parser::ParseResult parsed = parser::parse_string(text, "stiff.pov", options);
    std::string errors;
    for (const Diagnostic& d : parsed.diagnostics) errors += format_diagnostic(d);
    EXPECT_TRUE(parsed.ok()) << errors;
    if (!parsed.ok()) return {Film(kWidth, kHeight), 0};
    const geometry::SceneGeometry geometry(*parsed.scene);
    lighting::IntegratorOptions integrator_options;
    integrator_options.gi = radiosity ? lighting::GiMode::Cache : lighting::GiMode::Off;
    const lighting::Integrator integrator(*parsed.scene, geometry, integrator_options);
    RenderSettings settings;
    settings.width = kWidth;
    settings.height = kHeight;
    std::optional<cache::IrradianceCache> irradiance_cache;
    if (radiosity && parsed.scene->global.radiosity) irradiance_cache.emplace(*parsed.scene->global.radiosity);
    RenderResult result =
        render_image(*parsed.scene, integrator, settings, nullptr, irradiance_cache ? &*irradiance_cache : nullptr);
    return {std::move(result.film), result.non_finite_pixels};
}

// Writes the image, the reference and their difference beside the test's output when a comparison fails.
void save_on_failure(const std::string& name, const Film& image, const Film& reference) {
    const fs::path dir = fs::path(WARDRAY_TEST_OUTPUT_DIR) / "stiff";
    fs::create_directories(dir);
    write_image(image, dir / (name + ".hdr"), ImageFormat::Hdr);
    write_image(reference, dir / (name + ".reference.hdr"), ImageFormat::Hdr);
    write_image(difference_image(image, reference), dir / (name + ".difference.png"), ImageFormat::Png);
}

double rrmse(const std::string& name, const Film& image, const Film& reference, double limit) {
    const auto c = compare_images(image, reference);
    EXPECT_TRUE(c.has_value());
    if (!c) return 1e30;
    if (c->rrmse > limit) save_on_failure(name, image, reference);
    return c->rrmse;
}

double max_channel(const Film& f) {
    double m = 0.0;
    for (float v : f.data()) m = std::fmax(m, v);
    return m;
}



// The scaled scene of scenes/stiff/`name`, shared with tools/scale_report.py.
std::string scaled_scene(const char* name = "scaled.pov") {
    std::ifstream f(fs::path(WARDRAY_SOURCE_DIR) / "scenes" / "stiff" / name);
    std::stringstream s;
    s << f.rdbuf();
    return s.str();
}

class ScaleInvariance : public ::testing::TestWithParam<double> {};

TEST_P(ScaleInvariance, MatchesScaleOne) {
    static const Rendered reference = render_text(scaled_scene(), {{"S", 1.0}});
    ASSERT_EQ(reference.non_finite, 0u);
    ASSERT_GT(max_channel(reference.film), 0.1);
    const double s = GetParam();
    const Rendered scaled = render_text(scaled_scene(), {{"S", s}});
    EXPECT_EQ(scaled.non_finite, 0u);
    std::ostringstream name;
    name << "scale_" << s;
    EXPECT_LE(rrmse(name.str(), scaled.film, reference.film, 0.01), 0.01) << "S = " << s;
}

// The same with indirect light from the cache: record radii, the behind test, neighbour clamping and gather seeds
// must all be free of absolute lengths.
TEST_P(ScaleInvariance, RadiosityMatchesScaleOne) {
    static const Rendered reference = render_text(scaled_scene("scaled_radiosity.pov"), {{"S", 1.0}}, true);
    ASSERT_EQ(reference.non_finite, 0u);
    ASSERT_GT(max_channel(reference.film), 0.1);
    const double s = GetParam();
    const Rendered scaled = render_text(scaled_scene("scaled_radiosity.pov"), {{"S", s}}, true);
    EXPECT_EQ(scaled.non_finite, 0u);
    std::ostringstream name;
    name << "radiosity_scale_" << s;
    EXPECT_LE(rrmse(name.str(), scaled.film, reference.film, 0.01), 0.01) << "S = " << s;
}

// Fog, ground fog and its turbulence scaled with the scene (scenes/stiff/scaled_fog.pov): within 1 %.
TEST(Stiff, FogScaledWithItsSceneMatchesScaleOne) {
    const Rendered reference = render_text(scaled_scene("scaled_fog.pov"), {{"S", 1.0}});
    ASSERT_EQ(reference.non_finite, 0u);
    ASSERT_GT(max_channel(reference.film), 0.1);
    for (const double s : {1e-4, 1e4}) {
        const Rendered scaled = render_text(scaled_scene("scaled_fog.pov"), {{"S", s}});
        EXPECT_EQ(scaled.non_finite, 0u);
        std::ostringstream name;
        name << "fog_scale_" << s;
        EXPECT_LE(rrmse(name.str(), scaled.film, reference.film, 0.01), 0.01) << "S = " << s;
    }
}

INSTANTIATE_TEST_SUITE_P(Stiff, ScaleInvariance, ::testing::Values(1e-6, 1e-3, 1e3, 1e6),
                         [](const ::testing::TestParamInfo<double>& info) {
                             const int exponent = static_cast<int>(std::lround(std::log10(info.param)));
                             return std::string(exponent < 0 ? "Em" : "E") + std::to_string(std::abs(exponent));
                         });

const char* kSquareHeader = R"(#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0.5, 0.5, -2> look_at <0.5, 0.5, 0> }
light_source { <0.3, 1, -3> color rgb 1 }
background { rgb <0.1, 0.1, 0.2> }
)";

// A unit square as two triangles, against the same square cut into 400 needles fanned from one corner
// plus zero-area, repeated-vertex and collinear triangles: the degenerate ones add nothing, the needles
// leave no holes.
TEST(Stiff, DegenerateAndNeedleTrianglesDrawTheSameSquare) {
    const std::string square = std::string(kSquareHeader) +
                               "mesh { triangle { <0,0,0>, <1,0,0>, <1,1,0> } triangle { <0,0,0>, <1,1,0>, <0,1,0> }"
                               " pigment { rgb <0.9, 0.5, 0.2> } }\n";
    std::ostringstream needles;
    needles << kSquareHeader << "mesh {\n";
    constexpr int k_fan = 200;
    for (int i = 0; i < k_fan; ++i) {
        // From the corner <0,0,0> to consecutive points of the edges x = 1 and y = 1.
        const double a0 = static_cast<double>(i) / k_fan;
        const double a1 = static_cast<double>(i + 1) / k_fan;
        needles << "triangle { <0,0,0>, <1," << a0 << ",0>, <1," << a1 << ",0> }\n";
        needles << "triangle { <0,0,0>, <" << a1 << ",1,0>, <" << a0 << ",1,0> }\n";
    }
    needles << "triangle { <0.2,0.2,0>, <0.2,0.2,0>, <0.2,0.2,0> }\n"     // one point
            << "triangle { <0.1,0.1,0>, <0.9,0.9,0>, <0.1,0.1,0> }\n"     // a repeated vertex
            << "triangle { <0.1,0.1,0>, <0.5,0.5,0>, <0.9,0.9,0> }\n"     // collinear
            << "triangle { <0,0,-0.5>, <1,1,-0.5>, <0.5,0.5,-0.5> }\n"    // collinear, in front of the square
            << "pigment { rgb <0.9, 0.5, 0.2> } }\n";
    const Rendered reference = render_text(square);
    const Rendered image = render_text(needles.str());
    EXPECT_EQ(reference.non_finite, 0u);
    EXPECT_EQ(image.non_finite, 0u);
    EXPECT_LE(rrmse("needles", image.film, reference.film, 0.01), 0.01);
    const auto c = compare_images(image.film, reference.film);
    ASSERT_TRUE(c.has_value());
    EXPECT_LE(c->bad_pixel_fraction, 0.01);
}

// Standalone degenerate triangles (not in a mesh) are skipped, never drawn as NaN.
TEST(Stiff, StandaloneDegenerateTrianglesRenderNothing) {
    const std::string empty = std::string(kSquareHeader) + "sphere { <5, 5, 5>, 0.1 }\n";
    const std::string degenerate =
        empty + "triangle { <0.2,0.2,0>, <0.2,0.2,0>, <0.2,0.2,0> pigment { rgb 1 } }\n"
                "triangle { <0.1,0.1,0>, <0.9,0.9,0>, <0.1,0.1,0> pigment { rgb 1 } }\n"
                "triangle { <0.1,0.1,0>, <0.5,0.5,0>, <0.9,0.9,0> pigment { rgb 1 } }\n"
                "smooth_triangle { <0,0,0>, <0,0,0>, <1,1,0>, <0,0,0>, <1,1,1e-300>, <0,0,0> pigment { rgb 1 } }\n";
    const Rendered reference = render_text(empty);
    const Rendered image = render_text(degenerate);
    EXPECT_EQ(image.non_finite, 0u);
    EXPECT_LE(rrmse("degenerate_standalone", image.film, reference.film, 1e-6), 1e-6);
}

// Two copies of the same sphere in the same place look like one: no shadow acne from the twin surface.
TEST(Stiff, CoincidentSurfacesLookLikeOne) {
    const std::string header = std::string(kSquareHeader) + "plane { y, -1 pigment { rgb 0.8 } }\n";
    const std::string one = header + "sphere { <0.5, 0.5, 0>, 0.6 pigment { rgb <0.2, 0.6, 0.9> } }\n";
    const std::string two = one + "sphere { <0.5, 0.5, 0>, 0.6 pigment { rgb <0.2, 0.6, 0.9> } }\n" +
                            "box { <-0.5, -1, 0.8>, <1.5, -0.5, 1.2> pigment { rgb 0.5 } }\n" +
                            "box { <-0.5, -1, 0.8>, <1.5, -0.5, 1.2> pigment { rgb 0.5 } }\n";
    const std::string one_box = one + "box { <-0.5, -1, 0.8>, <1.5, -0.5, 1.2> pigment { rgb 0.5 } }\n";
    const Rendered reference = render_text(one_box);
    const Rendered image = render_text(two);
    EXPECT_EQ(image.non_finite, 0u);
    EXPECT_LE(rrmse("coincident", image.film, reference.film, 0.01), 0.01);
}

// A light a hair above a plane, far away, lights it at a grazing angle: the cosine law gives almost nothing,
// and a light exactly in the plane gives exactly nothing.
TEST(Stiff, GrazingLightFollowsTheCosineLaw) {
    const std::string header = R"(#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -3> look_at 0 }
plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }
)";
    for (const double height : {1e-6, 0.0}) {
        std::ostringstream scene;
        scene << header << "light_source { <1000, " << height << ", 0> color rgb 1 }\n";
        const Rendered image = render_text(scene.str());
        EXPECT_EQ(image.non_finite, 0u) << height;
        // cos(theta) = height / 1000 at most (points near the origin): < 1e-8 for the raised light.
        EXPECT_LE(max_channel(image.film), 1e-8) << height;
    }
}

// Light colours from 1e-6 to 1e6: radiance is linear in each light's colour, at every magnitude.
TEST(Stiff, LightColoursAcrossTwelveDecadesStayLinear) {
    const std::string header = R"(#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -4> look_at <0, 0.5, 0> }
plane { y, 0 pigment { rgb 0.8 } finish { ambient 0 } }
sphere { <0, 0.7, 0>, 0.7 pigment { rgb <1, 0.3, 0.2> } finish { ambient 0 phong 0.5 } }
)";
    auto scene = [&](double a, double b) {
        std::ostringstream s;
        s << header << "light_source { <3, 5, -4> color rgb " << a << " }\n"
          << "light_source { <-3, 4, -2> color rgb " << b << " }\n";
        return s.str();
    };
    const Rendered unit = render_text(scene(1.0, 0.0));
    for (const double c : {1e-6, 1e6}) {
        const Rendered image = render_text(scene(c, 0.0));
        EXPECT_EQ(image.non_finite, 0u) << c;
        Film scaled_back(kWidth, kHeight);
        for (int y = 0; y < kHeight; ++y)
            for (int x = 0; x < kWidth; ++x) scaled_back.set_pixel(x, y, image.film.pixel(x, y) / c);
        EXPECT_LE(rrmse("colour_" + std::to_string(c), scaled_back, unit.film, 1e-4), 1e-4) << c;
    }
    // Both extremes at once: the faint light vanishes under the bright one, and nothing overflows.
    const Rendered both = render_text(scene(1e6, 1e-6));
    EXPECT_EQ(both.non_finite, 0u);
    EXPECT_NEAR(max_channel(both.film) / (1e6 * max_channel(unit.film)), 1.0, 0.05);
}

// A camera inside a closed sphere sees its inside, lit only by ambient light (the light is outside).
TEST(Stiff, CameraInsideAnObjectSeesItsInside) {
    const std::string scene = R"(#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, 0> look_at <0, 0, 1> }
light_source { <10, 10, -10> color rgb 1 }
sphere { 0, 1 pigment { rgb 0.5 } finish { ambient 0.1 diffuse 0.7 } }
)";
    const Rendered image = render_text(scene);
    EXPECT_EQ(image.non_finite, 0u);
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const Vec3 p = image.film.pixel(x, y);
            ASSERT_NEAR(p.x, 0.05, 1e-4) << x << "," << y;
            ASSERT_NEAR(p.y, 0.05, 1e-4) << x << "," << y;
            ASSERT_NEAR(p.z, 0.05, 1e-4) << x << "," << y;
        }
}

}  // namespace
}  // namespace wardray::render
