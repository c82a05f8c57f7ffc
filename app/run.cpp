// The steps of rendering one scene: resolve the job, load, build, render, write.
#include "app/run.h"

#include <tbb/parallel_for.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <vector>

#include "app/app.h"
#include "app/partial_render.h"
#include "app/photon_file_io.h"
#include "app/process_limits.h"
#include "app/read_policy.h"
#include "app/whole_file.h"
#include "cache/interpolation.h"
#include "camera/camera.h"
#include "geometry/object_query.h"
#include "parser/parse.h"
#include "parser/read_access.h"
#include "parser/trace_sensitivity.h"
#include "render/film.h"
#include "render/gif_reader.h"
#include "render/height_image.h"
#include "render/image_header.h"
#include "render/output_gamma.h"
#include "render/png_palette.h"
#include "texture/noise.h"
#include "texture/pattern.h"
#include "texture/pigment.h"

#ifndef WARDRAY_SOURCE_DIR
#define WARDRAY_SOURCE_DIR ""
#endif

namespace wardray::app {

namespace {

namespace fs = std::filesystem;

constexpr const char* kPovrayIncludeDir = "/usr/share/povray-3.7/include";

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

// --max-memory's default, in MB.
constexpr std::uint64_t kDefaultMaxMemoryMb = 1024;

// POV-Ray compat: a GIF is a colour-mapped image to POV-Ray 3.7, its graphic control extension's transparent entry
// of alpha 0 (an image map's transmit 1 there) and every other entry opaque, each texel keeping its entry's colour.
// Read here for a GIF whose one image covers its screen; `image` is what read_image gave (its colours, transparent
// texels black as OpenImageIO gives them) and becomes indexed, with the palette's alpha when it names a transparent
// entry. Other files, and GIFs placed on a larger screen, are left as they are.
void add_gif_palette(const fs::path& file, scene::ImageData& image) {
    std::string error;
    const std::optional<render::GifIndices> gif = render::read_gif_indices(file, error);
    if (!gif || gif->left != 0 || gif->top != 0 || gif->width != image.width || gif->height != image.height ||
        gif->screen_width != image.width || gif->screen_height != image.height || gif->palette.size() < 3)
        return;
    const int entries = static_cast<int>(gif->palette.size() / 3);
    image.index = gif->index;
    image.palette_size = entries;
    image.alpha.clear();
    image.palette_alpha.clear();
    image.has_alpha = gif->transparent >= 0 && gif->transparent < entries;
    if (!image.has_alpha) return;
    image.palette_alpha.assign(static_cast<std::size_t>(entries), 1.0f);
    image.palette_alpha[static_cast<std::size_t>(gif->transparent)] = 0.0f;
    const auto t = static_cast<std::size_t>(gif->transparent);
    for (std::size_t at = 0; at < image.index.size(); ++at)
        if (image.index[at] == gif->transparent)
            for (std::size_t c = 0; c < 3; ++c) image.rgb[at * 3 + c] = static_cast<float>(gif->palette[t * 3 + c]) / 255.0f;
}

// What the parser is told: include folders, declares, file access, guard rails, and the hooks it calls back.
parser::ParseOptions parse_options_for(const Options& options, const parser::ParseOptions::FrameClock& clock) {
    parser::ParseOptions parse_options;
    parse_options.animation = clock;
    parse_options.library_paths.push_back(kPovrayIncludeDir);
    for (const fs::path& p : options.library_paths) parse_options.library_paths.push_back(p);
    parse_options.declares = options.declares;
    parse_options.image_width = options.width;
    parse_options.image_height = options.height;
    parse_options.read_paths = options.read_paths;
    if (!options.strict_reads) {
        std::error_code ec;
        const char* home = std::getenv("HOME");
        parse_options.permitted_reads = povray_permitted_reads(home ? home : "", fs::current_path(ec));
    }
    parse_options.write_paths = options.write_paths;
    // image_map files through the render layer's reader (OpenImageIO, loaded only when a scene has one).
    // An image file counts against the parse's memory budget: one whose header claims more pixels than fit in it
    // (about 16 bytes each while it is read) is refused before anything is allocated.
    const std::uint64_t max_pixels = (options.max_memory.value_or(kDefaultMaxMemoryMb) << 20) / 16;
    parse_options.read_image = [max_pixels](const fs::path& file, bool& encoded, std::string& error)
        -> std::shared_ptr<scene::ImageData> {
        bool alpha = false;
        std::vector<float> alpha_values;
        std::optional<render::Film> film =
            render::read_image(file, error, &encoded, &alpha, nullptr, nullptr, &alpha_values, max_pixels);
        if (!film) return nullptr;
        auto image = std::make_shared<scene::ImageData>();
        image->has_alpha = alpha;
        image->alpha = std::move(alpha_values);
        image->width = film->width();
        image->height = film->height();
        image->rgb = film->take_data();  // moved, not copied: an image map's samples are held once
        if (const auto png = render::png_colour_info(file)) {
            image->table_grey8 = png->colour_type == 0 && png->bit_depth <= 8;
            image->declared_srgb = png->srgb;
            image->declared_file_gamma = png->file_gamma;
        }
        // A palette PNG's indices too (bump_map use_index, material_map, image_map filter N).
        int w = 0, h = 0;
        std::vector<std::uint8_t> index;
        std::vector<float> entry_rgb, entry_alpha;
        if (render::read_png_palette_indices(file, w, h, index, image->palette_size, &entry_rgb, &entry_alpha) &&
            w == image->width && h == image->height) {
            // A palette image's alpha is its palette's.
            image->alpha.clear();
            if (!entry_alpha.empty() && encoded) {
                // With a tRNS chunk the colours come from the palette as stored and each entry's alpha is kept.
                for (std::size_t at = 0; at < index.size(); ++at)
                    if (index[at] < image->palette_size)
                        for (int c = 0; c < 3; ++c) image->rgb[at * 3 + c] = entry_rgb[index[at] * 3u + c];
                image->palette_alpha = std::move(entry_alpha);
            }
            image->index = std::move(index);
        } else if (image->has_alpha && image->alpha.empty() && encoded) {
            add_gif_palette(file, *image);
        }
        return image;
    };
    parse_options.read_height_grid = [max_pixels](const fs::path& file, std::string& error, std::string& unsupported) {
        return render::read_height_grid(file, error, unsupported, max_pixels);
    };
    if (options.allow_file_writes) parse_options.file_writes = parser::ParseOptions::FileWrites::Allow;
    if (options.max_loop_iterations) parse_options.max_loop_iterations = *options.max_loop_iterations;
    if (options.max_macro_depth) parse_options.max_macro_depth = *options.max_macro_depth;
    if (options.max_include_depth) parse_options.max_include_depth = *options.max_include_depth;
    if (options.max_array_size) parse_options.max_array_elements = *options.max_array_size;
    if (options.max_string_length) parse_options.max_string_length = *options.max_string_length;
    if (options.max_memory_file) parse_options.max_memory_file_bytes = *options.max_memory_file;
    // The command line's budgets: an object costs about 3.7 KB while parsing, so an endless object-making loop stops
    // within a second or two and under 1 GB; the switches raise them for scenes that really are that large. A
    // user's city of 4,000 domed towers holds 92,000 objects (108,000 counted with its CSG children).
    parse_options.max_objects = options.max_objects.value_or(250'000);
    parse_options.max_memory_bytes = static_cast<std::size_t>(options.max_memory.value_or(kDefaultMaxMemoryMb)) << 20;
    // --check evaluates every declaration, so it also reports mistakes in declarations nothing uses.
    parse_options.defer_library_declarations = !options.check_only;
    static const geometry::ObjectQuery object_query;  // trace(), inside(), min_extent(), max_extent() while parsing
    parse_options.query = &object_query;
    parse_options.vector_turbulence = [](const Vec3& p, int octaves, double omega, double lambda) {
        return texture::dturbulence(p, texture::TurbulenceParams{octaves, omega, lambda});
    };
    parse_options.pattern_value = [](const scene::Pattern& pattern, const Vec3& p, int noise_generator) {
        return texture::pattern_value(pattern, texture::warp_point(pattern, p), noise_generator);
    };
    parse_options.set_number_of_waves = [](int count) { texture::set_number_of_waves(count); };
    parse_options.pigment_value = [](const scene::Pigment& pigment, const Vec3& p, int noise_generator) {
        return texture::evaluate_pigment(pigment, p, noise_generator);
    };
    parse_options.debug_output = [](const std::string& text) { std::cerr << text << std::flush; };
    return parse_options;
}

// The irradiance cache for +RFI: the records of the radiosity file, or (with a warning) an empty cache.
void load_cache_file(cache::IrradianceCache& irradiance_cache, const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) {
        std::cerr << "wardray: warning: cannot read radiosity file '" << file.string()
                  << "'; starting with an empty cache\n";
        return;
    }
    try {
        irradiance_cache.load(in);
    } catch (const cache::CacheFileError& e) {
        std::cerr << "wardray: warning: radiosity file '" << file.string() << "' not used: " << e.what() << "\n";
    }
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

// A diagnostic image (--aov), in the format its name says; false (with a message) when it cannot be written.
bool write_aov(const fs::path& path, const render::Film& film) {
    const auto error =
        render::write_image(film, path, render::format_from_extension(path).value_or(render::ImageFormat::Png));
    if (error) std::cerr << "wardray: error: " << *error << "\n";
    return !error;
}

// --aov records: the image with a red dot where each first-bounce cache record projects.
render::Film mark_records(const render::Film& film, const scene::Scene& scene,
                          const cache::IrradianceCache* irradiance_cache, int width, int height) {
    render::Film marked = film;
    if (!irradiance_cache) return marked;
    const camera::CameraModel camera(scene.camera, width, height);
    for (const cache::IrradianceRecord& r : irradiance_cache->records(0)) {
        double px = 0.0, py = 0.0;
        if (!camera.project(r.position, px, py)) continue;
        const int x = static_cast<int>(std::floor(px)), y = static_cast<int>(std::floor(py));
        if (x >= 0 && y >= 0 && x < width && y < height) marked.set_pixel(x, y, {1.0, 0.0, 0.0});
    }
    return marked;
}

// +RFO: every record of the cache into the radiosity file, whole or not at all.
bool save_cache_file(const cache::IrradianceCache& irradiance_cache, const fs::path& file) {
    return write_whole_file(file, "radiosity file", [&](std::ostream& out) { irradiance_cache.save(out); });
}

}  // namespace

double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

std::optional<Job> resolve_job(Options options, const std::string& argv0) {
    if (options.scene.empty()) {
        const auto scene = find_default_scene(argv0);
        if (!scene) {
            std::cerr << "wardray: error: the bundled default scene (scenes/default.pov) was not found\n";
            return std::nullopt;
        }
        options.scene = *scene;
    }
    // The output file: POV-Ray's default is the scene's name with the format's extension, in the current folder.
    Job job;
    job.format = options.format.value_or(
        options.output ? render::format_from_extension(*options.output).value_or(render::ImageFormat::Png)
                       : render::ImageFormat::Png);
    job.output = options.output.value_or(options.scene.stem().string() + render::extension_of(job.format));
    if (job.output.extension().empty()) job.output += render::extension_of(job.format);
    auto frames = plan_frames(options.animation, job.output);
    if (const std::string* why = std::get_if<std::string>(&frames)) {
        std::cerr << "wardray: error: animation: " << *why << "\n";
        return std::nullopt;
    }
    job.frames = std::move(std::get<std::vector<Frame>>(frames));
    auto region = resolve_region(options.region, options.width, options.height);
    if (const std::string* why = std::get_if<std::string>(&region)) {
        std::cerr << "wardray: error: partial render: " << *why << "\n";
        return std::nullopt;
    }
    job.region = std::get<std::optional<render::PixelRegion>>(region);
    job.options = std::move(options);
    return job;
}

std::optional<int> refuse_job(const Job& job) {
    const Options& options = job.options;
    std::error_code ec;
    if (options.write_output && !options.check_only && fs::exists(job.output, ec) &&
        fs::equivalent(job.output, options.scene, ec)) {
        std::cerr << "wardray: the output '" << job.output.string()
                  << "' is the scene file itself; choose another\n";
        return kExitUsage;
    }
    // +RFI reads a file the user named: confined like the scene's own reads, plus the current folder, where +RFO
    // writes a relative name (the default name, beside the output as +RFO writes it, is wardray's own file).
    if (options.radiosity_load && options.radiosity_file) {
        const parser::ParseOptions reads = parse_options_for(options, {});
        std::vector<parser::ReadRoot> roots = parser::readable_roots(reads, options.scene);
        roots.push_back({fs::current_path(ec), true});
        if (!parser::is_readable(*options.radiosity_file, roots)) {
            std::cerr << "wardray: error: " << parser::read_refusal(*options.radiosity_file, "+RFI radiosity file")
                      << "\n";
            return kExitScene;
        }
    }
    if (!options.check_only) {
        if (const auto error = image_too_large(options.width, options.height)) {
            std::cerr << "wardray: error: " << *error << "\n";
            return kExitScene;
        }
    }
    return std::nullopt;
}

std::unique_ptr<tbb::global_control> prepare_process(const Options& options) {
    std::unique_ptr<tbb::global_control> thread_limit;
    if (options.threads > 0)
        thread_limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                             static_cast<std::size_t>(options.threads));
    render::remove_partial_output_on_signal();
    limit_heap_to_machine_memory();
    return thread_limit;
}

std::optional<LoadedScene> load_scene(const Options& options, const parser::ParseOptions::FrameClock& clock) {
    const auto start = Clock::now();
    // A scene that calls trace() is parsed twice, to warn when its objects hang on trace()'s rounding.
    parser::ParseResult parse = parser::parse_file_checking_trace(options.scene, parse_options_for(options, clock));
    const double seconds = seconds_since(start);
    for (const Diagnostic& d : parse.diagnostics) std::cerr << format_diagnostic(d);
    if (!parse.ok()) return std::nullopt;
    // --gi-pretrace-bound: with the record passes and the gradients, wardray's pretrace bound for the block's
    // low_error_factor (--gi-gradients=off stays POV-Ray 3.7's cache).
    if (auto& radiosity = parse.scene->global.radiosity;
        radiosity && options.gi_record_pass && options.gi_gradients && !options.gi_pov_pretrace_bound)
        radiosity->low_error_factor = cache::pretrace_low_error_factor(radiosity->low_error_factor);
    return LoadedScene{std::move(*parse.scene), seconds, peak_resident_bytes()};
}

std::optional<BuiltGeometry> build_geometry(const scene::Scene& scene) {
    const auto start = Clock::now();
    BuiltGeometry built;
    try {
        built.geometry = std::make_unique<geometry::SceneGeometry>(scene);
    } catch (const std::exception& e) {
        std::cerr << "wardray: error: cannot build the scene's geometry: " << e.what() << "\n";
        return std::nullopt;
    }
    built.seconds = seconds_since(start);
    built.peak_bytes = peak_resident_bytes();
    return built;
}

Illumination build_illumination(const scene::Scene& scene, const geometry::SceneGeometry& geometry,
                                const Options& options) {
    Illumination illumination;
    lighting::IntegratorOptions& settings = illumination.settings;
    settings.gi = options.gi.value_or(scene.global.radiosity ? lighting::GiMode::Cache : lighting::GiMode::Off);
    settings.reference_rays = options.gi_rays;
    settings.gather_light_picks = options.gi_light_picks;
    settings.guide_paths = options.gi_guide;
    settings.seed = options.seed;
    settings.path_seed = options.gi_path_seed;
    settings.fine_area_lights = options.gi_fine_area_lights;
    settings.gradients = options.gi_gradients;
    settings.gradient_cap = options.gi_gradient_cap;
    settings.hessian_spacing = options.gi_hessian_spacing;
    settings.adaptive_gather = options.gi_adaptive;
    settings.lookup_sampling = options.gi_lookup_sampling;
    settings.geometry_floor = options.gi_geometry_floor;
    settings.output_alpha = options.output_alpha;
    settings.quality = options.quality;
    // Up to +Q5 surfaces show their pigments' quick_color (the integrator); the sky's pigments keep theirs.
    if (options.quality <= 5 && scene.sky_sphere)
        for (const scene::Pigment& p : scene.sky_sphere->pigments)
            if (p.quick_color)
                std::cerr << p.loc.path << ":" << p.loc.line << ":" << p.loc.column
                          << ": warning: a sky_sphere pigment's quick_color is not rendered yet (at +Q"
                          << options.quality << " POV-Ray shows it)\n";
    if (scene.camera.type == scene::Camera::Type::Perspective && length(scene.camera.direction) > 0.0)
        settings.footprint = length(scene.camera.right) / (options.width * length(scene.camera.direction));
    // POV-Ray compat: a mesh_camera's rays start on its mesh, and the objects they start inside are those around
    // the first ray's origin (the first pixel, in reading order, that has a ray: the first POV-Ray traces).
    if (scene.camera.type == scene::Camera::Type::MeshCamera) {
        const camera::CameraModel model(scene.camera, options.width, options.height, scene.global.noise_generator);
        for (int i = 0; i < options.width * options.height && !settings.camera_origin; ++i)
            if (const auto first = model.ray(i % options.width + 0.5, i / options.width + 0.5))
                settings.camera_origin = first->origin;
    }
    // The photon pass runs here, in the integrator's construction, when the scene has a photons block; a
    // load_file replaces it with the photons of an earlier render, a save_file keeps them for write_outputs.
    if (scene.global.photons && !scene.global.photons->file.empty()) {
        if (scene.global.photons->load) settings.photons_from_file = load_photon_file(scene.global.photons->file);
        else settings.keep_shot_photons = true;
    }
    illumination.integrator = std::make_unique<lighting::Integrator>(scene, geometry, settings);
    for (const std::string& limitation : illumination.integrator->limitations())
        std::cerr << options.scene.string() << ": warning: " << limitation << "\n";
    // The reference's guide learns from a pilot pass through a fixed grid of image positions, one row a task and
    // the rows' samples joined in order, so it depends on the scene, the seed, the size and the paths only.
    if (illumination.integrator->wants_guide()) {
        const camera::CameraModel model(scene.camera, options.width, options.height, scene.global.noise_generator);
        const int grid = lighting::Integrator::kPilotGrid;
        const int paths = lighting::Integrator::pilot_paths(
            static_cast<long long>(options.width) * options.height, options.gi_rays);
        std::vector<std::vector<lighting::GuideSample>> rows(grid);
        tbb::parallel_for(0, grid, [&](int j) {
            for (int i = 0; i < grid; ++i)
                if (const auto ray = model.ray((i + 0.5) * options.width / grid, (j + 0.5) * options.height / grid))
                    illumination.integrator->pilot(*ray, paths, rows[j]);
        });
        // Joined row by row, each row freed once copied: the pilot's vertices are about 60 bytes a path.
        std::size_t total = 0;
        for (const auto& row : rows) total += row.size();
        std::vector<lighting::GuideSample> samples;
        samples.reserve(total);
        for (auto& row : rows) {
            samples.insert(samples.end(), row.begin(), row.end());
            std::vector<lighting::GuideSample>().swap(row);
        }
        illumination.integrator->learn_guide(samples);
    }
    // The irradiance cache, only when the scene asks for radiosity and --gi is cache; +RFI starts it from a file.
    illumination.cache_file = options.radiosity_file.value_or(options.scene.stem().string() + ".rca");
    if (illumination.integrator->uses_cache()) {
        illumination.cache = std::make_unique<cache::IrradianceCache>(*scene.global.radiosity);
        illumination.cache->set_neighbour_clamp(options.gi_neighbour_clamp);
        illumination.cache->set_ambient_grids(options.gi_lookup_sampling > 1);
        if (options.radiosity_load) load_cache_file(*illumination.cache, illumination.cache_file);
    }
    return illumination;
}

RenderedFrame render_frame(const scene::Scene& scene, const Illumination& illumination, const Options& options,
                           const std::optional<render::PixelRegion>& region, render::Communicator* communicator) {
    ProgressLine progress(isatty(STDERR_FILENO) != 0 && (!communicator || communicator->rank() == 0));
    const auto start = Clock::now();
    render::RenderSettings settings;
    settings.width = options.width;
    settings.height = options.height;
    settings.tile_size = options.render_block_size;
    settings.region = region;
    // POV-Ray compat: antialiasing compares colours after decoding the working gamma (not when gamma is off).
    const double antialias_gamma =
        scene.global.gamma_handling
            ? render::antialias_gamma_on_working_values(options.antialias_gamma, scene.global.assumed_gamma)
            : options.antialias_gamma;
    settings.antialias = {options.antialias, options.antialias_threshold, options.antialias_depth, options.jitter,
                          antialias_gamma, options.sampling_method};
    settings.pretrace = options.pretrace;
    settings.record_pass = options.gi_record_pass;
    settings.seed = options.seed;
    settings.irradiance_aov = options.aov_irradiance.has_value();
    settings.alpha = options.output_alpha;
    settings.communicator = communicator;
    RenderedFrame frame{render::render_image(
        scene, *illumination.integrator, settings, [&](double f) { progress.update("render", f); },
        illumination.cache.get())};
    progress.finish();
    frame.seconds = seconds_since(start);
    return frame;
}

bool write_outputs(const Job& job, const scene::Scene& scene, const Illumination& illumination,
                   const render::RenderResult& result) {
    const Options& options = job.options;
    if (options.write_output) {
        const render::OutputGamma gamma = render::output_gamma(scene.global, options.file_gamma, options.display_gamma);
        if (auto error = render::write_image(result.film, job.output, job.format, gamma,
                                             result.alpha ? &*result.alpha : nullptr)) {
            std::cerr << "wardray: error: " << *error << "\n";
            return false;
        }
    }
    if (options.aov_irradiance && result.irradiance && !write_aov(*options.aov_irradiance, *result.irradiance))
        return false;
    if (options.aov_records &&
        !write_aov(*options.aov_records,
                   mark_records(result.film, scene, illumination.cache.get(), options.width, options.height)))
        return false;
    if (illumination.cache && options.radiosity_save && !save_cache_file(*illumination.cache, illumination.cache_file))
        return false;
    if (const photons::ShotPhotons* shot = illumination.integrator->shot_photons();
        shot && !save_photon_file(*shot, scene.global.photons->file))
        return false;
    return true;
}

}  // namespace wardray::app
