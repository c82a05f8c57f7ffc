// Renderer: traces the image in tiles on a thread pool, deterministically for any thread count.
#pragma once

#include <cstdint>
#include <functional>

#include "geometry/scene_geometry.h"
#include "lighting/direct_lighting.h"
#include "parser/scene.h"
#include "render/film.h"

namespace wardray::render {

struct RenderSettings {
    int width = 320;
    int height = 240;
    int tile_size = 32;
};

/// Called as tiles complete with the fraction done (0..1); called from worker threads, one at a time.
using ProgressFn = std::function<void(double fraction)>;

/// The finished image and the rays it took.
struct RenderResult {
    Film film;
    lighting::RayCounters rays;
    std::uint64_t non_finite_pixels = 0;  ///< pixels whose radiance was NaN or infinite (written as black)
};

/// Renders every pixel. Each pixel depends only on its own rays, so tiles may finish in any order
/// and the image is the same for any number of threads.
RenderResult render_image(const parser::Scene& scene, const lighting::Integrator& integrator,
                          const RenderSettings& settings, const ProgressFn& progress);

}  // namespace wardray::render
