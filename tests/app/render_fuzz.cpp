// libFuzzer entry point for the whole pipeline: parses arbitrary bytes as a scene, builds its geometry and renders
// an 8x6 image (radiosity and its cache included when the scene asks), then checks every pixel is finite.
//
// Built (by tests/fuzz/CMakeLists.txt) with -DWARDRAY_FUZZ=ON under clang (tools/fuzz.sh 600 render), and without libFuzzer into
// render_fuzz_regression_tests, which replays tests/fuzz/render_regressions/ and the seed scenes through it.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string_view>

#include "cache/irradiance_cache.h"
#include "geometry/object_query.h"
#include "geometry/scene_geometry.h"
#include "lighting/integrator.h"
#include "parser/parse.h"
#include "render/renderer.h"
#include "texture/noise.h"
#include "texture/pattern.h"
#include "texture/pigment.h"

namespace {

using namespace wardray;

constexpr const char* k_system_includes = "/usr/share/povray-3.7/include";

// The parser's small guard rails (as parser_fuzz), with the hooks the app gives it, minus image reading: the
// scene's folder does not exist, so no file but the system include files is read and none is written.
parser::ParseOptions fuzz_options() {
    parser::ParseOptions o;
    o.file_writes = parser::ParseOptions::FileWrites::Refuse;
    o.max_loop_iterations = 20'000;
    o.max_macro_depth = 40;
    o.max_include_depth = 8;
    o.max_array_elements = 100'000;
    o.max_string_length = 100'000;
    o.max_objects = 20'000;
    o.max_memory_bytes = std::size_t{512} << 20;
    // The system include folder, so seeds from the example scenes get past `#include "colors.inc"` to the
    // renderer (declarations there are read only when used, so an input pays for what it names).
    if (std::error_code ec; std::filesystem::is_directory(k_system_includes, ec)) o.library_paths = {k_system_includes};
    o.image_width = 8;
    o.image_height = 6;
    static const geometry::ObjectQuery query;
    o.query = &query;
    o.vector_turbulence = [](const Vec3& p, int octaves, double omega, double lambda) {
        return texture::dturbulence(p, texture::TurbulenceParams{octaves, omega, lambda});
    };
    o.pattern_value = [](const scene::Pattern& pattern, const Vec3& p, int noise_generator) {
        return texture::pattern_value(pattern, texture::warp_point(pattern, p), noise_generator);
    };
    o.pigment_value = [](const scene::Pigment& pigment, const Vec3& p, int noise_generator) {
        return texture::evaluate_pigment(pigment, p, noise_generator);
    };
    return o;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const parser::ParseOptions options = fuzz_options();
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    parser::ParseResult parsed = parser::parse_string(text, "/nonexistent/wardray-fuzz/scene.pov", options);
    if (!parsed.ok()) return 0;
    const scene::Scene& scene = *parsed.scene;
    std::unique_ptr<geometry::SceneGeometry> geometry;
    try {
        geometry = std::make_unique<geometry::SceneGeometry>(scene);
    } catch (const std::exception&) {
        return 0;  // reported as an error by the app
    }
    lighting::IntegratorOptions settings;
    settings.gi = scene.global.radiosity ? lighting::GiMode::Cache : lighting::GiMode::Off;
    const lighting::Integrator integrator(scene, *geometry, settings);
    std::unique_ptr<cache::IrradianceCache> cache;
    if (integrator.uses_cache()) cache = std::make_unique<cache::IrradianceCache>(*scene.global.radiosity);
    render::RenderSettings render_settings;
    render_settings.width = 8;
    render_settings.height = 6;
    render_settings.antialias.enabled = true;
    const render::RenderResult result = render::render_image(scene, integrator, render_settings, {}, cache.get());
    // Render-time guard: whatever the scene computes, the image holds finite values only.
    for (const float v : result.film.data())
        if (!std::isfinite(v)) std::abort();
    return 0;
}
