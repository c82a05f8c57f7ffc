// Renderer: traces the image in tiles on a thread pool, deterministically for any thread count.
#pragma once

#include <cstdint>
#include <functional>

#include "geometry/scene_geometry.h"
#include "lighting/direct_lighting.h"
#include "parser/scene.h"
#include "render/film.h"

namespace wardray::render {

/// POV-Ray's adaptive non-recursive supersampling (+A, sampling method 1) and its parameters.
struct AntialiasSettings {
    bool enabled = false;
    double threshold = 0.3;  ///< +A0.3: summed RGB difference of gamma-encoded neighbours that triggers it
    int depth = 3;           ///< +R3: a supersampled pixel gets depth x depth extra samples
    double jitter = 1.0;     ///< +J1.0; 0 turns jitter off
    double gamma = 2.5;      ///< +AG2.5: neighbours are compared as pow(c, 1/gamma)
};

struct RenderSettings {
    int width = 320;
    int height = 240;
    int tile_size = 32;  ///< POV-Ray's render block size; antialiasing decisions are made per block
    AntialiasSettings antialias;
};

/// Called as tiles complete with the fraction done (0..1); called from worker threads, one at a time.
using ProgressFn = std::function<void(double fraction)>;

/// The finished image and the rays it took.
struct RenderResult {
    Film film;
    lighting::RayCounters rays;
    std::uint64_t non_finite_pixels = 0;  ///< pixels whose radiance was NaN or infinite (written as black)
    std::uint64_t supersampled_pixels = 0;
};

/// Renders every pixel. Each pixel depends only on its own rays, so tiles may finish in any order
/// and the image is the same for any number of threads.
RenderResult render_image(const parser::Scene& scene, const lighting::Integrator& integrator,
                          const RenderSettings& settings, const ProgressFn& progress);

}  // namespace wardray::render
