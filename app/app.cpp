// The wardray command: parse, build, render, write, with POV-Ray's exit conventions and a progress line.
#include "app/app.h"

#include <sys/resource.h>
#include <tbb/global_control.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "cache/irradiance_cache.h"
#include "geometry/object_query.h"
#include "geometry/scene_geometry.h"
#include "lighting/direct_lighting.h"
#include "texture/noise.h"
#include "parser/parse.h"
#include "camera/camera.h"
#include "app/diff_command.h"
#include "app/options.h"
#include "render/renderer.h"

#ifndef WARDRAY_SOURCE_DIR
#define WARDRAY_SOURCE_DIR ""
#endif

#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define WARDRAY_HAS_ASAN 1
#endif
#endif
#ifndef WARDRAY_HAS_ASAN
#define WARDRAY_HAS_ASAN 0
#endif

namespace wardray::app {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

constexpr const char* kPovrayIncludeDir = "/usr/share/povray-3.7/include";

double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

// The bundled default scene: beside the executable's build folder, else in the source tree it was built from.
std::optional<fs::path> find_default_scene(const std::string& argv0) {
    std::error_code ec;
    fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (ec) exe = fs::absolute(argv0, ec);
    const std::vector<fs::path> candidates = {exe.parent_path() / "scenes" / "default.pov",
                                              exe.parent_path().parent_path() / "scenes" / "default.pov",
                                              fs::path(WARDRAY_SOURCE_DIR) / "scenes" / "default.pov"};
    for (const fs::path& p : candidates)
        if (fs::is_regular_file(p, ec)) return p;
    return std::nullopt;
}

const char* gi_name(lighting::GiMode mode) {
    switch (mode) {
        case lighting::GiMode::Off: return "off";
        case lighting::GiMode::Cache: return "cache";
        case lighting::GiMode::Reference: return "reference";
    }
    return "off";
}

const char* shape_name(const scene::Shape& shape) { return scene::shape_keyword(shape); }

const char* light_name(scene::Light::Type type) {
    switch (type) {
        case scene::Light::Type::Point: return "point";
        case scene::Light::Type::Spot: return "spotlight";
        case scene::Light::Type::Parallel: return "parallel";
        case scene::Light::Type::Cylinder: return "cylinder";
    }
    return "point";
}

std::string vec_text(const Vec3& v) {
    std::ostringstream s;
    s << '<' << v.x << ", " << v.y << ", " << v.z << '>';
    return s.str();
}

// --check: what the scene holds, in a form a person can read.
void describe_scene(const scene::Scene& scene, std::ostream& out) {
    out << "scene: " << scene.path << "\n";
    out << "version: " << scene.version << "\n";
    out << "camera: "
        << (scene.camera.type == scene::Camera::Type::Orthographic ? "orthographic" : "perspective")
        << " at " << vec_text(scene.camera.location) << " looking along " << vec_text(scene.camera.direction)
        << "\n";
    // "objects: 3 (box 1, sphere 2)": a total, then the count of each kind in name order.
    auto counts = [&out](const char* label, std::size_t total, const std::map<std::string, int>& by_kind) {
        out << label << ": " << total;
        const char* separator = " (";
        for (const auto& [name, n] : by_kind) {
            out << separator << name << ' ' << n;
            separator = ", ";
        }
        out << (by_kind.empty() ? "" : ")") << "\n";
    };
    std::map<std::string, int> objects;
    for (const scene::Object& o : scene.objects) ++objects[shape_name(o.shape)];
    counts("objects", scene.objects.size(), objects);
    std::map<std::string, int> lights;
    for (const scene::Light& l : scene.lights) ++lights[light_name(l.type)];
    counts("lights", scene.lights.size(), lights);
    out << "radiosity: " << (scene.global.radiosity ? "on" : "off") << "\n";
    out << "warnings: " << scene.warnings.size() << "\n";
    for (const Diagnostic& w : scene.warnings) out << "  " << w.loc.path << ':' << w.loc.line << ':'
                                                            << w.loc.column << ": " << w.message << "\n";
}

// A one-line progress display on a terminal: phase, percent, elapsed, remaining.
class ProgressLine {
public:
    explicit ProgressLine(bool enabled) : m_enabled(enabled) {}
    void update(const char* phase, double fraction) {
        if (!m_enabled) return;
        const auto now = Clock::now();
        if (fraction < 1.0 && now - m_last < std::chrono::milliseconds(100)) return;
        m_last = now;
        const double elapsed = seconds_since(m_start);
        const double remaining = fraction > 0.0 ? elapsed * (1.0 - fraction) / fraction : 0.0;
        std::fprintf(stderr, "\r%-8s %5.1f%%  elapsed %6.1fs  remaining %6.1fs", phase, 100.0 * fraction, elapsed,
                     remaining);
        std::fflush(stderr);
    }
    void finish() {
        if (m_enabled) std::fprintf(stderr, "\n");
    }

private:
    bool m_enabled;
    Clock::time_point m_start = Clock::now();
    Clock::time_point m_last{};
};

// Refuses an image whose pixels alone would not fit in this machine's memory, before anything is parsed or
// allocated (a film of floats, the antialiasing buffers and the writer's copy: about 32 bytes a pixel).
std::optional<std::string> image_too_large(int width, int height) {
    constexpr double k_bytes_per_pixel = 32.0;
    const double needed = static_cast<double>(width) * height * k_bytes_per_pixel;
    const long pages = sysconf(_SC_PHYS_PAGES);
    const long page_size = sysconf(_SC_PAGESIZE);
    if (pages <= 0 || page_size <= 0) return std::nullopt;
    const double memory = static_cast<double>(pages) * static_cast<double>(page_size);
    if (needed <= memory) return std::nullopt;
    constexpr double k_gib = 1024.0 * 1024.0 * 1024.0;
    std::ostringstream s;
    s.precision(3);
    s << "a " << width << "x" << height << " image needs about " << needed / k_gib
      << " GiB for its pixels, more than this machine's " << memory / k_gib << " GiB of memory";
    return s.str();
}

// Bounds the heap by the machine's memory, so a scene that grows without end (a loop of objects) fails with
// bad_alloc, reported at its location, instead of waking the kernel's OOM killer, which may pick another process.
void limit_heap_to_machine_memory() {
#if defined(__SANITIZE_ADDRESS__) || WARDRAY_HAS_ASAN
    // AddressSanitizer's shadow memory counts as data: under any such limit every later allocation fails.
    return;
#endif
    const long pages = sysconf(_SC_PHYS_PAGES);
    const long page_size = sysconf(_SC_PAGESIZE);
    rlimit limit{};
    if (pages <= 0 || page_size <= 0 || getrlimit(RLIMIT_DATA, &limit) != 0) return;
    const auto memory = static_cast<rlim_t>(pages) * static_cast<rlim_t>(page_size);
    if (limit.rlim_cur != RLIM_INFINITY && limit.rlim_cur <= memory) return;
    limit.rlim_cur = limit.rlim_max == RLIM_INFINITY ? memory : std::min(memory, limit.rlim_max);
    setrlimit(RLIMIT_DATA, &limit);
}

}  // namespace

int run(const std::vector<std::string>& args, const std::string& argv0) {
    const auto start = Clock::now();
    if (!args.empty() && args[0] == "diff")
        return run_diff_command(std::vector<std::string>(args.begin() + 1, args.end()));
    auto parsed = parse_command_line(args);
    if (auto* error = std::get_if<UsageError>(&parsed)) {
        std::cerr << "wardray: " << error->message << "\n" << usage_text();
        return kExitUsage;
    }
    Options options = std::get<Options>(parsed);
    if (options.show_help) {
        std::cout << usage_text();
        return kExitOk;
    }
    if (options.show_version) {
        std::cout << "wardray " << WARDRAY_VERSION << "\n";
        return kExitOk;
    }

    if (options.scene.empty()) {
        const auto scene = find_default_scene(argv0);
        if (!scene) {
            std::cerr << "wardray: error: the bundled default scene (scenes/default.pov) was not found\n";
            return kExitScene;
        }
        options.scene = *scene;
    }

    // The output file: POV-Ray's default is the scene's name with the format's extension, in the current folder.
    render::ImageFormat format = options.format.value_or(
        options.output ? render::format_from_extension(*options.output).value_or(render::ImageFormat::Png)
                       : render::ImageFormat::Png);
    fs::path output = options.output.value_or(options.scene.stem().string() + render::extension_of(format));
    if (output.extension().empty()) output += render::extension_of(format);
    std::error_code ec;
    if (options.write_output && !options.check_only && fs::exists(output, ec) &&
        fs::equivalent(output, options.scene, ec)) {
        std::cerr << "wardray: the output '" << output.string() << "' is the scene file itself; choose another\n";
        return kExitUsage;
    }

    std::unique_ptr<tbb::global_control> thread_limit;
    if (options.threads > 0)
        thread_limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                             static_cast<std::size_t>(options.threads));

    if (!options.check_only) {
        if (const auto error = image_too_large(options.width, options.height)) {
            std::cerr << "wardray: error: " << *error << "\n";
            return kExitScene;
        }
    }

    render::remove_partial_output_on_signal();
    limit_heap_to_machine_memory();

    // Parse.
    parser::ParseOptions parse_options;
    parse_options.library_paths.push_back(kPovrayIncludeDir);
    for (const fs::path& p : options.library_paths) parse_options.library_paths.push_back(p);
    parse_options.declares = options.declares;
    parse_options.image_width = options.width;
    parse_options.image_height = options.height;
    parse_options.read_paths = options.read_paths;
    parse_options.write_paths = options.write_paths;
    if (options.allow_file_writes) parse_options.file_writes = parser::ParseOptions::FileWrites::Allow;
    if (options.max_loop_iterations) parse_options.max_loop_iterations = *options.max_loop_iterations;
    if (options.max_macro_depth) parse_options.max_macro_depth = *options.max_macro_depth;
    if (options.max_include_depth) parse_options.max_include_depth = *options.max_include_depth;
    if (options.max_array_size) parse_options.max_array_elements = *options.max_array_size;
    if (options.max_string_length) parse_options.max_string_length = *options.max_string_length;
    if (options.max_memory_file) parse_options.max_memory_file_bytes = *options.max_memory_file;
    // --check evaluates every declaration, so it also reports mistakes in declarations nothing uses.
    parse_options.defer_library_declarations = !options.check_only;
    const geometry::ObjectQuery object_query;  // trace(), inside(), min_extent(), max_extent() while parsing
    parse_options.query = &object_query;
    parse_options.vector_turbulence = [](const Vec3& p, int octaves, double omega, double lambda) {
        return texture::dturbulence(p, texture::TurbulenceParams{octaves, omega, lambda});
    };
    parse_options.debug_output = [](const std::string& text) { std::cerr << text << std::flush; };
    auto phase_start = Clock::now();
    parser::ParseResult parse = parser::parse_file(options.scene, parse_options);
    const double parse_seconds = seconds_since(phase_start);
    for (const Diagnostic& d : parse.diagnostics) std::cerr << format_diagnostic(d);
    if (!parse.ok()) return kExitScene;
    const scene::Scene& scene = *parse.scene;

    if (options.check_only) {
        describe_scene(scene, std::cout);
        return kExitOk;
    }

    // Build.
    phase_start = Clock::now();
    std::unique_ptr<geometry::SceneGeometry> geometry;
    try {
        geometry = std::make_unique<geometry::SceneGeometry>(scene);
    } catch (const std::exception& e) {
        std::cerr << "wardray: error: cannot build the scene's geometry: " << e.what() << "\n";
        return kExitScene;
    }
    const double build_seconds = seconds_since(phase_start);
    for (const std::uint32_t index : geometry->skipped_objects()) {
        Diagnostic d;
        d.severity = Severity::Warning;
        d.loc = scene.objects[index].loc;
        d.message = std::string(shape_name(scene.objects[index].shape)) +
                    " is degenerate (zero size, singular transform or non-finite numbers) and is not rendered";
        std::cerr << format_diagnostic(d);
    }

    lighting::IntegratorOptions integrator_options;
    integrator_options.gi =
        options.gi.value_or(scene.global.radiosity ? lighting::GiMode::Cache : lighting::GiMode::Off);
    integrator_options.reference_rays = options.gi_rays;
    integrator_options.gradients = options.gi_gradients;
    if (scene.camera.type == scene::Camera::Type::Perspective && length(scene.camera.direction) > 0.0)
        integrator_options.footprint = length(scene.camera.right) / (options.width * length(scene.camera.direction));
    const lighting::Integrator integrator(scene, *geometry, integrator_options);
    for (const std::string& limitation : integrator.limitations())
        std::cerr << options.scene.string() << ": warning: " << limitation << "\n";

    // The irradiance cache, only when the scene asks for radiosity and --gi is cache; +RFI starts it from a file.
    std::unique_ptr<cache::IrradianceCache> irradiance_cache;
    const fs::path cache_file = options.radiosity_file.value_or(options.scene.stem().string() + ".rca");
    if (integrator.uses_cache()) {
        irradiance_cache = std::make_unique<cache::IrradianceCache>(*scene.global.radiosity);
        if (options.radiosity_load) {
            std::ifstream in(cache_file, std::ios::binary);
            if (!in) {
                std::cerr << "wardray: warning: cannot read radiosity file '" << cache_file.string()
                          << "'; starting with an empty cache\n";
            } else {
                try {
                    irradiance_cache->load(in);
                } catch (const cache::CacheFileError& e) {
                    std::cerr << "wardray: warning: radiosity file '" << cache_file.string() << "' not used: "
                              << e.what() << "\n";
                }
            }
        }
    }

    // Render.
    ProgressLine progress(isatty(STDERR_FILENO) != 0);
    phase_start = Clock::now();
    render::RenderSettings settings;
    settings.width = options.width;
    settings.height = options.height;
    settings.antialias = {options.antialias, options.antialias_threshold, options.antialias_depth, options.jitter,
                          options.antialias_gamma};
    settings.pretrace = options.pretrace;
    settings.irradiance_aov = options.aov_irradiance.has_value();
    const render::RenderResult result = render::render_image(
        scene, integrator, settings, [&](double f) { progress.update("render", f); }, irradiance_cache.get());
    progress.finish();
    const double render_seconds = seconds_since(phase_start);

    // Write.
    phase_start = Clock::now();
    if (options.write_output) {
        if (auto error = render::write_image(result.film, output, format)) {
            std::cerr << "wardray: error: " << *error << "\n";
            return kExitScene;
        }
    }
    // The diagnostic images (--aov), in the format their names say.
    auto write_aov = [&](const fs::path& path, const render::Film& film) {
        const auto error =
            render::write_image(film, path, render::format_from_extension(path).value_or(render::ImageFormat::Png));
        if (error) std::cerr << "wardray: error: " << *error << "\n";
        return !error;
    };
    if (options.aov_irradiance && result.irradiance && !write_aov(*options.aov_irradiance, *result.irradiance))
        return kExitScene;
    if (options.aov_records) {
        render::Film marked = result.film;
        if (irradiance_cache) {
            const camera::CameraModel camera(scene.camera, options.width, options.height);
            for (const cache::IrradianceRecord& r : irradiance_cache->records(0)) {
                double px = 0.0, py = 0.0;
                if (!camera.project(r.position, px, py)) continue;
                const int x = static_cast<int>(std::floor(px)), y = static_cast<int>(std::floor(py));
                if (x >= 0 && y >= 0 && x < options.width && y < options.height) marked.set_pixel(x, y, {1.0, 0.0, 0.0});
            }
        }
        if (!write_aov(*options.aov_records, marked)) return kExitScene;
    }
    if (irradiance_cache && options.radiosity_save) {
        auto write_cache = [&](const fs::path& tmp) -> std::optional<std::string> {
            std::ofstream f(tmp, std::ios::binary);
            irradiance_cache->save(f);
            f.close();
            if (!f) return std::string("write failed");
            return std::nullopt;
        };
        const auto error = render::write_atomically(cache_file, write_cache);
        if (error) {
            std::cerr << "wardray: error: radiosity file: " << *error << "\n";
            return kExitScene;
        }
    }
    const double write_seconds = seconds_since(phase_start);

    if (options.stats) {
        nlohmann::json stats;
        stats["scene"] = options.scene.string();
        stats["output"] = options.write_output ? output.string() : "";
        stats["width"] = options.width;
        stats["height"] = options.height;
        stats["threads"] = options.threads > 0 ? options.threads
                                               : static_cast<int>(std::thread::hardware_concurrency());
        stats["gi"] = gi_name(integrator_options.gi);
        stats["radiosity_block"] = scene.global.radiosity.has_value();
        double pretrace_seconds = 0.0;
        nlohmann::json passes = nlohmann::json::array();
        for (const render::PassTiming& pass : result.passes) {
            if (pass.kind == "pretrace") pretrace_seconds += pass.seconds;
            passes.push_back({{"kind", pass.kind}, {"block_size", pass.block_size}, {"seconds", pass.seconds}});
        }
        stats["phases"] = {{"parse", parse_seconds}, {"build", build_seconds}, {"pretrace", pretrace_seconds},
                           {"render", render_seconds - pretrace_seconds}, {"write", write_seconds}};
        stats["passes"] = passes;
        stats["total_seconds"] = seconds_since(start);
        stats["rays"] = {{"camera", result.rays.camera},
                         {"shadow", result.rays.shadow},
                         {"secondary", result.rays.secondary},
                         {"gather", result.rays.gather}};
        stats["gathers"] = result.rays.gathers;
        stats["non_finite_pixels"] = result.non_finite_pixels;
        stats["supersampled_pixels"] = result.supersampled_pixels;
        stats["cache"] = nullptr;
        if (irradiance_cache) {
            const cache::CacheStatistics cs = irradiance_cache->statistics();
            nlohmann::json per_pass = nlohmann::json::array();
            for (const auto& depths : cs.records) per_pass.push_back(depths);
            stats["cache"] = {{"records_per_pass_and_depth", per_pass},
                              {"records", cs.total_records},
                              {"lookups", cs.lookups},
                              {"hits", cs.hits},
                              {"hit_rate", cs.hit_rate()},
                              {"mean_radius", cs.mean_radius},
                              {"rays_per_record", result.rays.gathers > 0 ? static_cast<double>(result.rays.gather) /
                                                                                static_cast<double>(result.rays.gathers)
                                                                          : 0.0}};
        }
        auto write_stats = [&](const fs::path& tmp) -> std::optional<std::string> {
            std::ofstream f(tmp);
            f << stats.dump(2) << "\n";
            f.close();
            if (!f) return std::string("write failed");
            return std::nullopt;
        };
        const auto error = render::write_atomically(*options.stats, write_stats);
        if (error) {
            std::cerr << "wardray: error: statistics: " << *error << "\n";
            return kExitScene;
        }
    }
    if (options.verbose)
        std::cerr << "wardray: wrote " << output.string() << " (" << options.width << "x" << options.height
                  << ") in " << seconds_since(start) << " s\n";
    return kExitOk;
}

}  // namespace wardray::app
