// Renderer: tiles over TBB workers; per-tile ray counters summed in tile order.
#include "render/renderer.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <mutex>

#include "render/camera.h"

namespace wardray::render {

RenderResult render_image(const parser::Scene& scene, const lighting::Integrator& integrator,
                          const RenderSettings& settings, const ProgressFn& progress) {
    RenderResult result{Film(settings.width, settings.height), {}};
    const CameraModel camera(scene.camera, settings.width, settings.height);
    const int tiles_x = (settings.width + settings.tile_size - 1) / settings.tile_size;
    const int tiles_y = (settings.height + settings.tile_size - 1) / settings.tile_size;
    const int tile_count = tiles_x * tiles_y;
    std::vector<lighting::RayCounters> tile_rays(tile_count);
    std::vector<std::uint64_t> tile_non_finite(tile_count, 0);
    std::atomic<int> tiles_done{0};
    std::mutex progress_mutex;

    tbb::parallel_for(tbb::blocked_range<int>(0, tile_count, 1), [&](const tbb::blocked_range<int>& range) {
        for (int tile = range.begin(); tile != range.end(); ++tile) {
            const int x0 = (tile % tiles_x) * settings.tile_size;
            const int y0 = (tile / tiles_x) * settings.tile_size;
            const int x1 = std::min(x0 + settings.tile_size, settings.width);
            const int y1 = std::min(y0 + settings.tile_size, settings.height);
            lighting::RayCounters& rays = tile_rays[tile];
            for (int y = y0; y < y1; ++y) {
                for (int x = x0; x < x1; ++x) {
                    Vec3 c = integrator.trace_camera_ray(camera.ray(x + 0.5, y + 0.5), rays);
                    // A non-finite value never reaches a pixel; it would poison every later average.
                    if (!is_finite(c)) {
                        c = Vec3{};
                        ++tile_non_finite[tile];
                    }
                    result.film.set_pixel(x, y, c);
                }
            }
            const int done = ++tiles_done;
            if (progress) {
                std::lock_guard<std::mutex> lock(progress_mutex);
                progress(static_cast<double>(done) / tile_count);
            }
        }
    });
    for (int tile = 0; tile < tile_count; ++tile) {
        result.rays += tile_rays[tile];
        result.non_finite_pixels += tile_non_finite[tile];
    }
    return result;
}

}  // namespace wardray::render
