// The steps of rendering one scene: resolve the job, load, build, render, write; each reports its own failures.
#pragma once

#include <tbb/global_control.h>

#include <chrono>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "app/animation.h"
#include "app/options.h"
#include "cache/irradiance_cache.h"
#include "geometry/scene_geometry.h"
#include "lighting/integrator.h"
#include "render/renderer.h"
#include "scene/scene.h"

namespace wardray::app {

/// The clock every phase is timed with.
using Clock = std::chrono::steady_clock;

/// Seconds from `start` until now.
double seconds_since(Clock::time_point start);

/// One run's options with their defaults resolved: the scene file, the output file and its format.
struct Job {
    Options options;
    std::filesystem::path output;  ///< POV-Ray's default: the scene's name with the format's extension
    render::ImageFormat format = render::ImageFormat::Png;
    std::vector<Frame> frames;     ///< one for a still; an animation's frames, each with its own output
    std::optional<render::PixelRegion> region;  ///< a partial render's pixels; empty: the whole image
};

/// Fills in the bundled default scene, the output file, the frames and the partial render's region; empty (with
/// a message) when there is no default scene or the animation or region options name no frame or pixel.
std::optional<Job> resolve_job(Options options, const std::string& argv0);

/// The exit status when the job must not start: its output is the scene file, or its image cannot fit in memory.
std::optional<int> refuse_job(const Job& job);

/// Readies the process for the job: the worker thread limit (held by the result, so keep it for the whole run),
/// a partial image removed on a signal, and the heap bounded by the machine's memory.
std::unique_ptr<tbb::global_control> prepare_process(const Options& options);

/// A parsed scene, how long parsing took and the process's peak resident bytes when it ended.
struct LoadedScene {
    scene::Scene scene;
    double seconds = 0.0;
    std::size_t peak_bytes = 0;
};

/// Parses the scene file with the options' include folders, declares and guard rails and the frame's clock values;
/// prints every diagnostic and is empty when the scene has errors.
std::optional<LoadedScene> load_scene(const Options& options, const parser::ParseOptions::FrameClock& clock = {});

/// The scene's geometry (one Embree scene), how long building it took and the peak resident bytes after it.
struct BuiltGeometry {
    std::unique_ptr<geometry::SceneGeometry> geometry;
    double seconds = 0.0;
    std::size_t peak_bytes = 0;
};

/// Builds the geometry; empty (with a message) when it cannot be built.
std::optional<BuiltGeometry> build_geometry(const scene::Scene& scene);

/// What lights the scene: the integrator and, when the scene's radiosity uses it, the irradiance cache.
struct Illumination {
    lighting::IntegratorOptions settings;
    std::unique_ptr<lighting::Integrator> integrator;
    std::unique_ptr<cache::IrradianceCache> cache;  ///< null unless the integrator uses a cache
    std::filesystem::path cache_file;               ///< +RF<file>, or the scene's name with .rca
};

/// Builds the integrator and the cache (started from the radiosity file with +RFI); prints their warnings.
Illumination build_illumination(const scene::Scene& scene, const geometry::SceneGeometry& geometry,
                                const Options& options);

/// A rendered frame, and how long rendering took (pretrace passes included).
struct RenderedFrame {
    render::RenderResult result;
    double seconds = 0.0;
};

/// Renders the image (only `region`'s pixels when there is one), with a progress line when stderr is a terminal.
/// With `communicator`, the render is shared among its processes (rank 0's result holds the whole image).
RenderedFrame render_frame(const scene::Scene& scene, const Illumination& illumination, const Options& options,
                           const std::optional<render::PixelRegion>& region = std::nullopt,
                           render::Communicator* communicator = nullptr);

/// Writes the image, the --aov images and the radiosity file (+RFO); false (with a message) when one fails.
bool write_outputs(const Job& job, const scene::Scene& scene, const Illumination& illumination,
                   const render::RenderResult& result);

}  // namespace wardray::app
