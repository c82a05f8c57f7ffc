// Renderer: tiles over TBB workers, POV-Ray's block-wise antialiasing, per-tile counters summed in tile order.
#include "render/renderer.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <mutex>

#include "render/camera.h"

namespace wardray::render {

namespace {

/// What one tile adds to the totals.
struct TileCounters {
    lighting::RayCounters rays;
    std::uint64_t non_finite = 0;
    std::uint64_t supersampled = 0;
};

/// Traces and shades one image position, keeping NaN and infinity out of the picture.
class Sampler {
public:
    Sampler(const CameraModel& camera, const lighting::Integrator& integrator, TileCounters& counters)
        : m_camera(camera), m_integrator(integrator), m_counters(counters) {}

    Vec3 operator()(double px, double py) const {
        Vec3 c = m_integrator.trace_camera_ray(m_camera.ray(px, py), m_counters.rays);
        if (!is_finite(c)) {
            ++m_counters.non_finite;
            c = Vec3{};
        }
        return c;
    }

private:
    const CameraModel& m_camera;
    const lighting::Integrator& m_integrator;
    TileCounters& m_counters;
};

// A jitter offset in [-0.5, 0.5) from a sample position: the same position always jitters the same way,
// so antialiased images are repeatable (POV-Ray's jitter is a fixed function of position too).
Vec3 jitter_at(double x, double y) {
    auto hash = [](std::uint64_t v) {
        v ^= v >> 33;
        v *= 0xFF51AFD7ED558CCDull;
        v ^= v >> 33;
        v *= 0xC4CEB9FE1A85EC53ull;
        return v ^ (v >> 33);
    };
    const std::uint64_t h = hash(std::bit_cast<std::uint64_t>(x) ^ hash(std::bit_cast<std::uint64_t>(y)));
    return {static_cast<double>(h >> 40) / double(1 << 24) - 0.5,
            static_cast<double>((h >> 16) & 0xFFFFFF) / double(1 << 24) - 0.5, 0.0};
}

// POV-Ray's antialiasing distance: summed absolute difference of gamma-encoded channels.
double encoded_distance(const Vec3& a, const Vec3& b, double gamma) {
    double d = 0.0;
    for (int c = 0; c < 3; ++c)
        d += std::fabs(std::pow(std::max(a[c], 0.0), 1.0 / gamma) - std::pow(std::max(b[c], 0.0), 1.0 / gamma));
    return d;
}

// Averages a depth x depth grid of (jittered) samples over pixel (x, y) with its centre sample `centre`:
// (centre + Σ samples) / (depth² + 1), as POV-Ray's method 1 does.
Vec3 supersample(const Sampler& sample, int x, int y, const Vec3& centre, const AntialiasSettings& aa) {
    const double step = 1.0 / aa.depth;
    const double range = 0.5 - 0.5 * step;
    const double jitter_scale = aa.jitter / aa.depth;
    Vec3 sum = centre;
    for (int j = 0; j < aa.depth; ++j) {
        for (int i = 0; i < aa.depth; ++i) {
            const double sx = x + 0.5 - range + i * step;
            const double sy = y + 0.5 - range + j * step;
            const Vec3 jit = jitter_scale > 0.0 ? jitter_at(sx, sy) * jitter_scale : Vec3{};
            sum += sample(sx + jit.x, sy + jit.y);
        }
    }
    return sum / (aa.depth * aa.depth + 1.0);
}

// Renders one block with POV-Ray's method 1: a pixel is supersampled when its gamma-encoded colour differs
// from its left or top neighbour by the threshold, and so is that neighbour if it was not already. The row
// above and the column left of the block are traced afresh and never supersampled, so a block depends on
// nothing outside it and the image is the same whatever order blocks finish in.
void render_block_antialiased(const Sampler& sample, Film& film, int x0, int y0, int x1, int y1,
                              const AntialiasSettings& aa, TileCounters& counters) {
    const int w = x1 - x0 + 1;  // one extra column on the left
    const int h = y1 - y0 + 1;  // one extra row on top
    std::vector<Vec3> colour(static_cast<std::size_t>(w) * h);
    std::vector<char> done(colour.size(), 0);
    auto at = [&](int x, int y) { return static_cast<std::size_t>(y - y0 + 1) * w + (x - x0 + 1); };
    for (int x = x0 - 1; x < x1; ++x) {
        colour[at(x, y0 - 1)] = sample(x + 0.5, y0 - 0.5);
        done[at(x, y0 - 1)] = 1;
    }
    for (int y = y0; y < y1; ++y) {
        colour[at(x0 - 1, y)] = sample(x0 - 0.5, y + 0.5);
        done[at(x0 - 1, y)] = 1;
        for (int x = x0; x < x1; ++x) {
            const std::size_t cur = at(x, y), left = at(x - 1, y), top = at(x, y - 1);
            colour[cur] = sample(x + 0.5, y + 0.5);
            const bool left_differs = encoded_distance(colour[left], colour[cur], aa.gamma) >= aa.threshold;
            const bool top_differs = encoded_distance(colour[top], colour[cur], aa.gamma) >= aa.threshold;
            if (left_differs && !done[left]) {
                colour[left] = supersample(sample, x - 1, y, colour[left], aa);
                done[left] = 1;
                ++counters.supersampled;
            }
            if (top_differs && !done[top]) {
                colour[top] = supersample(sample, x, y - 1, colour[top], aa);
                done[top] = 1;
                ++counters.supersampled;
            }
            if (left_differs || top_differs) {
                colour[cur] = supersample(sample, x, y, colour[cur], aa);
                done[cur] = 1;
                ++counters.supersampled;
            }
        }
    }
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) film.set_pixel(x, y, colour[at(x, y)]);
}

}  // namespace

RenderResult render_image(const parser::Scene& scene, const lighting::Integrator& integrator,
                          const RenderSettings& settings, const ProgressFn& progress) {
    RenderResult result{Film(settings.width, settings.height), {}};
    const CameraModel camera(scene.camera, settings.width, settings.height);
    const int tiles_x = (settings.width + settings.tile_size - 1) / settings.tile_size;
    const int tiles_y = (settings.height + settings.tile_size - 1) / settings.tile_size;
    const int tile_count = tiles_x * tiles_y;
    std::vector<TileCounters> tile_counters(tile_count);
    std::atomic<int> tiles_done{0};
    std::mutex progress_mutex;

    tbb::parallel_for(tbb::blocked_range<int>(0, tile_count, 1), [&](const tbb::blocked_range<int>& range) {
        for (int tile = range.begin(); tile != range.end(); ++tile) {
            const int x0 = (tile % tiles_x) * settings.tile_size;
            const int y0 = (tile / tiles_x) * settings.tile_size;
            const int x1 = std::min(x0 + settings.tile_size, settings.width);
            const int y1 = std::min(y0 + settings.tile_size, settings.height);
            const Sampler sample(camera, integrator, tile_counters[tile]);
            if (settings.antialias.enabled) {
                render_block_antialiased(sample, result.film, x0, y0, x1, y1, settings.antialias,
                                         tile_counters[tile]);
            } else {
                for (int y = y0; y < y1; ++y)
                    for (int x = x0; x < x1; ++x) result.film.set_pixel(x, y, sample(x + 0.5, y + 0.5));
            }
            const int done = ++tiles_done;
            if (progress) {
                std::lock_guard<std::mutex> lock(progress_mutex);
                progress(static_cast<double>(done) / tile_count);
            }
        }
    });
    for (const TileCounters& t : tile_counters) {
        result.rays += t.rays;
        result.non_finite_pixels += t.non_finite;
        result.supersampled_pixels += t.supersampled;
    }
    return result;
}

}  // namespace wardray::render
