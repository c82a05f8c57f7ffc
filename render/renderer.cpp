// Renderer: tiles over TBB workers, POV-Ray's block-wise antialiasing, per-tile counters summed in tile order.
#include "render/renderer.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <chrono>
#include <cmath>
#include <mutex>

#include "cache/irradiance_cache.h"
#include "camera/camera.h"
#include "camera/focal_blur.h"
#include "core/render_seed.h"
#include "render/sampler.h"

namespace wardray::render {

namespace {

// Averages a depth x depth grid of (jittered) samples over pixel (x, y) with its centre sample `centre`:
// (centre + Σ samples) / (depth² + 1), as POV-Ray's method 1 does.
Rgbt supersample(const Sampler& sample, int x, int y, const Rgbt& centre, const AntialiasSettings& aa,
                 std::uint64_t seed) {
    const double step = 1.0 / aa.depth;
    const double range = 0.5 - 0.5 * step;
    const double jitter_scale = aa.jitter / aa.depth;
    Rgbt sum = centre;
    for (int j = 0; j < aa.depth; ++j) {
        for (int i = 0; i < aa.depth; ++i) {
            const double sx = x + 0.5 - range + i * step;
            const double sy = y + 0.5 - range + j * step;
            const Vec3 jit = jitter_scale > 0.0 ? jitter_at(sx, sy, seed) * jitter_scale : Vec3{};
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
                              const AntialiasSettings& aa, std::uint64_t seed, TileCounters& counters) {
    const int w = x1 - x0 + 1;  // one extra column on the left
    const int h = y1 - y0 + 1;  // one extra row on top
    std::vector<Rgbt> colour(static_cast<std::size_t>(w) * h);
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
            colour[cur] = sample.centre(x, y);
            const bool left_differs = encoded_distance(colour[left], colour[cur], aa.gamma) >= aa.threshold;
            const bool top_differs = encoded_distance(colour[top], colour[cur], aa.gamma) >= aa.threshold;
            if (left_differs && !done[left]) {
                colour[left] = supersample(sample, x - 1, y, colour[left], aa, seed);
                done[left] = 1;
                ++counters.supersampled;
            }
            if (top_differs && !done[top]) {
                colour[top] = supersample(sample, x, y - 1, colour[top], aa, seed);
                done[top] = 1;
                ++counters.supersampled;
            }
            if (left_differs || top_differs) {
                colour[cur] = supersample(sample, x, y, colour[cur], aa, seed);
                done[cur] = 1;
                ++counters.supersampled;
            }
        }
    }
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) sample.store(film, x, y, colour[at(x, y)]);
}


/// Runs `body(tile, x0, y0, x1, y1)` on the thread pool for each tile `next()` hands out until it returns -1;
/// `done()` is called as each finishes. Every worker draws its next tile when it is free.
template <typename Next, typename Body, typename Done>
void for_each_tile(const RenderSettings& settings, const Next& next, const Body& body, const Done& done) {
    const int tiles_x = (settings.width + settings.tile_size - 1) / settings.tile_size;
    const int workers = std::max(tbb::this_task_arena::max_concurrency(), 1);
    tbb::parallel_for(0, workers, [&](int) {
        for (int tile = next(); tile >= 0; tile = next()) {
            const int x0 = (tile % tiles_x) * settings.tile_size;
            const int y0 = (tile / tiles_x) * settings.tile_size;
            body(tile, x0, y0, std::min(x0 + settings.tile_size, settings.width),
                 std::min(y0 + settings.tile_size, settings.height));
            done();
        }
    });
}

/// The tiles in waves of `first`, 2 × first, 4 × first, ... taken coarse to fine (every 2^k-th tile across and down
/// first), so that the first waves spread over the whole image and later waves reuse what they cached. A remainder
/// smaller than the wave before it joins that wave: a wave of the one or two tiles left over would keep all but one
/// or two processes waiting, and those tiles gain little from the records of the wave before.
std::vector<std::vector<int>> tile_waves(int tiles_x, int tiles_y, std::size_t first) {
    std::vector<int> order;
    std::vector<char> taken(static_cast<std::size_t>(tiles_x) * tiles_y, 0);
    int step = 1;
    while (step < std::max(tiles_x, tiles_y)) step *= 2;
    for (; step >= 1; step /= 2) {
        for (int ty = 0; ty < tiles_y; ty += step) {
            for (int tx = 0; tx < tiles_x; tx += step) {
                const int t = ty * tiles_x + tx;
                if (taken[t]) continue;
                taken[t] = 1;
                order.push_back(t);
            }
        }
    }
    std::vector<std::vector<int>> waves;
    std::size_t begin = 0;
    for (std::size_t size = std::max<std::size_t>(first, 1); begin < order.size(); size *= 2) {
        std::size_t end = std::min(order.size(), begin + size);
        if (order.size() - end < size) end = order.size();
        waves.emplace_back(order.begin() + begin, order.begin() + end);
        begin = end;
    }
    return waves;
}

/// Keeps, in each wave, only the tiles that overlap `region` (a partial render); empty waves go.
void keep_region_tiles(std::vector<std::vector<int>>& waves, const PixelRegion& region, int tiles_x, int tile_size) {
    auto overlaps = [&](int tile) {
        const int x0 = (tile % tiles_x) * tile_size, y0 = (tile / tiles_x) * tile_size;
        return x0 < region.x1 && x0 + tile_size > region.x0 && y0 < region.y1 && y0 + tile_size > region.y0;
    };
    for (std::vector<int>& wave : waves) std::erase_if(wave, [&](int tile) { return !overlaps(tile); });
    std::erase_if(waves, [](const std::vector<int>& wave) { return wave.empty(); });
}

/// The record passes (RenderSettings::record_pass): first a ray through every this many pixels' centres in each
/// direction, then through every pixel's when the first says the final pass would make more than this share of the
/// cache's records.
constexpr double kSparseRecordStep = 4.0;
constexpr double kRecordPassShare = 0.01;
/// The first wave's tiles in the passes after the first (the first pass's first wave is one tile).
constexpr std::size_t kLaterFirstWave = 8;

/// A uniform number in [0, 1) from a pretrace position, pass and the render seed, so pretrace jitter is the same on
/// every run.
double pretrace_jitter(int pass, double x, double y, int axis, std::uint64_t seed) {
    const Vec3 j = jitter_at(x + 0.25 * axis, y + 1024.0 * pass, seed);
    return j[axis] + 0.5;
}

}  // namespace

std::vector<double> pretrace_sizes(const scene::RadiositySettings& rs, int width, int height) {
    // POV-Ray compat (view.cpp): block sizes from pretrace_start to pretrace_end of the larger image side,
    // halving each step, the end at least one pixel.
    const double side = std::max(width, height);
    const double start = side * rs.pretrace_start;
    const double end = std::max(1.0, side * rs.pretrace_end);
    std::vector<double> sizes;
    if (!(start >= end)) return {end};
    const int steps = static_cast<int>(std::floor(std::log2(start / end) + (1.0 - 1e-10))) + 1;
    for (int i = 0; i < std::min(steps, 64); ++i) sizes.push_back(std::max(start * std::ldexp(1.0, -i), end));
    return sizes;
}

RenderResult render_image(const scene::Scene& scene, const lighting::Integrator& integrator,
                          const RenderSettings& settings, const ProgressFn& progress, cache::IrradianceCache* cache) {
    RenderResult result{Film(settings.width, settings.height), {}, 0, 0, {}, std::nullopt, {}, {}, {}};
    if (settings.alpha) result.alpha.emplace(settings.width, settings.height);
    const camera::CameraModel camera(scene.camera, settings.width, settings.height, scene.global.noise_generator);
    // Focal blur only when the camera asks for it: a scene without it pays nothing.
    std::optional<camera::FocalBlur> blur;
    if (scene.camera.focal_blur()) blur.emplace(scene.camera, settings.seed);
    const int tiles_x = (settings.width + settings.tile_size - 1) / settings.tile_size;
    const int tiles_y = (settings.height + settings.tile_size - 1) / settings.tile_size;
    const int tile_count = tiles_x * tiles_y;
    std::vector<TileCounters> tile_counters(tile_count);
    const bool cached = cache != nullptr && integrator.uses_cache() && scene.global.radiosity.has_value();
    if (settings.irradiance_aov) result.irradiance.emplace(settings.width, settings.height);

    // Without a cache every tile is independent: one wave. With one, tiles go in waves and each wave's records are
    // merged (in a fixed order) before the next starts, so the image is the same for any thread count.
    std::vector<double> sizes, record_sizes;
    if (cached && settings.pretrace) {
        sizes = pretrace_sizes(*scene.global.radiosity, settings.width, settings.height);
        if (settings.record_pass) record_sizes = {kSparseRecordStep, 1.0};
    }
    std::vector<std::vector<std::vector<int>>> pass_waves(sizes.size() + record_sizes.size() + 1);
    for (std::size_t pass = 0; pass < pass_waves.size(); ++pass) {
        std::vector<std::vector<int>>& waves = pass_waves[pass];
        if (cached) {
            // The first pass starts from an empty cache (unless one was loaded), so its first tile goes alone: a second
            // tile beside it would make most of the same records again. Later passes start from a filled cache,
            // where eight tiles at once make hardly more records than one after the other (0.7 % more over the
            // whole render, at the same error: docs/mpi.md), and small waves of tiles of unequal cost
            // leave threads and processes waiting.
            waves = tile_waves(tiles_x, tiles_y, pass == 0 ? 1 : kLaterFirstWave);
            // The sparse record pass (little work a tile, and a record it makes covers many of its pixels) and the
            // final pass after the record passes (which leave it almost nothing to make) go in one wave: across
            // processes each wave costs an exchange of records, and one wave balances best.
            const bool sparse_record_pass = !record_sizes.empty() && pass == sizes.size();
            const bool final_after_record_passes = !record_sizes.empty() && pass + 1 == pass_waves.size();
            if (sparse_record_pass || final_after_record_passes) {
                for (std::size_t w = 1; w < waves.size(); ++w)
                    waves[0].insert(waves[0].end(), waves[w].begin(), waves[w].end());
                waves.resize(1);
            }
        } else {
            waves.emplace_back(tile_count);
            for (int t = 0; t < tile_count; ++t) waves[0][t] = t;
        }
        if (settings.region) keep_region_tiles(waves, *settings.region, tiles_x, settings.tile_size);
    }
    std::size_t tiles_rendered = 0, wave_count = 0;
    for (const auto& waves : pass_waves) {
        wave_count += waves.size();
        for (const std::vector<int>& wave : waves) tiles_rendered += wave.size();
    }
    // Shared among processes, each process renders its share of every wave and they exchange records between waves.
    TileExchange exchange(settings.communicator);
    exchange.begin(tile_count, wave_count, tiles_x);
    std::vector<TileExchange::TileRect> final_tiles;  // this process's tiles of the final pass
    const int processes = settings.communicator ? std::max(settings.communicator->size(), 1) : 1;
    const double total_work = static_cast<double>(tiles_rendered) / processes;
    std::atomic<int> tiles_done{0};
    std::mutex progress_mutex;
    auto tile_done = [&]() {
        const int done = ++tiles_done;
        if (!progress) return;
        std::lock_guard<std::mutex> lock(progress_mutex);
        progress(done / total_work);
    };
    // One pass over the image in waves, `body` rendering one tile with its trace context.
    int pass_number = 0;
    auto run_pass = [&](bool final_pass, bool colour_kept, const auto& body) {
        if (cached) cache->begin_pass(tile_count);
        exchange.start_pass();
        const std::uint64_t pass_seed = 0x9E3779B97F4A7C15ULL * static_cast<std::uint64_t>(++pass_number);
        for (const std::vector<int>& wave : pass_waves[static_cast<std::size_t>(pass_number - 1)]) {
            exchange.start_wave(wave);
            for_each_tile(settings, [&] { return exchange.next_tile(); }, [&](int tile, int x0, int y0, int x1, int y1) {
                lighting::TraceContext& ctx = tile_counters[tile].trace;
                ctx.cache = cached ? &cache->tile(tile) : nullptr;
                ctx.final_pass = final_pass;
                ctx.colour_kept = colour_kept;
                ctx.gather_seed =
                    reseed(pass_seed ^ (0xD1B54A32D192ED03ULL * static_cast<std::uint64_t>(tile + 1)), settings.seed);
                const double tile_start = exchange.distributed() ? TileExchange::thread_seconds() : 0.0;
                body(tile, x0, y0, x1, y1, ctx);
                if (exchange.distributed()) exchange.tile_cost(tile, TileExchange::thread_seconds() - tile_start);
                ctx.cache = nullptr;
            }, tile_done);
            const std::vector<int> mine = exchange.taken();
            exchange.end_wave(wave, mine, cached ? cache : nullptr);
            if (cached) exchange.merge_wave(wave, *cache);
            if (colour_kept && exchange.distributed()) {
                for (const int tile : mine) {
                    const int x0 = (tile % tiles_x) * settings.tile_size, y0 = (tile / tiles_x) * settings.tile_size;
                    final_tiles.push_back({tile, x0, y0, std::min(x0 + settings.tile_size, settings.width),
                                           std::min(y0 + settings.tile_size, settings.height)});
                }
            }
        }
        if (cached) cache->end_pass();
    };

    // POV-Ray's pretrace: camera rays on a coarse grid fill the cache (their colours are thrown away), the grid
    // halving each pass; each pass sees the records of the passes and waves before it. Then the record passes: the
    // final pass's first rays (through the pixels' centres, in the same tiles) with its lookups, so that
    // the records the final pass would make, each seen only by the pixels after it, are made before it and seen by
    // every pixel; first through every kSparseRecordStep-th pixel a row and column, then through every pixel when
    // that sample says the final pass would make more than kRecordPassShare of the records.
    int grid_pass = 0;
    auto grid_pass_body = [&](double size, bool record_pass) {
        // The record passes' rays go through pixels' centres, as the final pass's first; the pretrace jitters
        // within its blocks.
        const double jitter = record_pass ? 0.0 : std::min(1.0, size / 2.0);
        const double offset = record_pass ? 0.0 : (size - 1.0) / 2.0;
        const int p = grid_pass++;
        return [&, size, jitter, offset, p](int, int x0, int y0, int x1, int y1, lighting::TraceContext& ctx) {
            // POV-Ray compat (RadiosityTask): one jittered ray per size × size block, the grid anchored at the origin.
            for (double y = std::ceil((y0 - 0.5) / size) * size; y < y1; y += size) {
                for (double x = std::ceil((x0 - 0.5) / size) * size; x < x1; x += size) {
                    const double px = x + offset + jitter * pretrace_jitter(p, x, y, 0, settings.seed) + 0.5;
                    const double py = y + offset + jitter * pretrace_jitter(p, x, y, 1, settings.seed) + 0.5;
                    if (const auto ray = camera.ray(px, py)) integrator.trace_camera_ray(*ray, ctx);
                }
            }
        };
    };
    auto records_now = [&] {
        std::size_t n = 0;
        for (int depth = 0; depth < cache->depth_count(); ++depth) n += cache->records(depth).size();
        return n;
    };
    for (const auto& [pass_sizes, final_params, kind] :
         {std::tuple{&sizes, false, "pretrace"}, std::tuple{&record_sizes, true, "record"}}) {
        for (const double size : *pass_sizes) {
            const auto pass_start = std::chrono::steady_clock::now();
            const std::size_t before = cached ? records_now() : 0;
            // The record passes fill holes in the cache's cover; a record made there that shrank its older
            // neighbours (neighbour clamping both ways) would open new holes around them for the final pass to fill.
            if (cached) cache->set_shrink_older(!final_params);
            run_pass(final_params, false, grid_pass_body(size, final_params));
            if (cached) cache->set_shrink_older(true);
            result.passes.push_back(
                {kind, size, std::chrono::duration<double>(std::chrono::steady_clock::now() - pass_start).count()});
            if (final_params && size == kSparseRecordStep) {
                // Every pixel would make about step² times the sample's records: when that is a small share of the
                // cache, the final pass makes them as it goes (the pass's waves are left unused, on every process
                // alike: the merged cache is the same everywhere).
                const double made = static_cast<double>(records_now() - before);
                if (made * kSparseRecordStep * kSparseRecordStep <= kRecordPassShare * records_now()) {
                    ++pass_number;
                    break;
                }
            }
        }
    }

    const auto final_start = std::chrono::steady_clock::now();
    run_pass(true, true, [&](int tile, int x0, int y0, int x1, int y1, lighting::TraceContext&) {
        const Sampler sample(camera, blur ? &*blur : nullptr, integrator, tile_counters[tile],
                             result.irradiance ? &*result.irradiance : nullptr,
                             result.alpha ? &*result.alpha : nullptr);
        if (settings.antialias.enabled && settings.antialias.method == 2) {
            render_block_recursive(sample, result.film, x0, y0, x1, y1, settings.antialias, settings.seed,
                                   tile_counters[tile]);
        } else if (settings.antialias.enabled) {
            render_block_antialiased(sample, result.film, x0, y0, x1, y1, settings.antialias, settings.seed,
                                     tile_counters[tile]);
        } else {
            for (int y = y0; y < y1; ++y)
                for (int x = x0; x < x1; ++x) sample.store(result.film, x, y, sample.centre(x, y));
        }
    });
    result.passes.push_back(
        {"final", 1.0, std::chrono::duration<double>(std::chrono::steady_clock::now() - final_start).count()});
    for (const TileCounters& t : tile_counters) {
        result.rays += t.trace.rays;
        result.non_finite_pixels += t.non_finite;
        result.supersampled_pixels += t.supersampled;
    }
    // Across processes, process 0 now receives the other processes' tiles and counters.
    exchange.gather_image(final_tiles, result.film, result.irradiance ? &*result.irradiance : nullptr,
                          result.alpha ? &*result.alpha : nullptr, result.rays, result.non_finite_pixels,
                          result.supersampled_pixels);
    result.ranks = exchange.ranks();
    result.waves = exchange.waves();
    if (settings.region) {
        // The whole tiles the region touches were rendered; POV-Ray writes the pixels outside it black.
        for (int y = 0; y < settings.height; ++y)
            for (int x = 0; x < settings.width; ++x)
                if (!settings.region->contains(x, y)) {
                    result.film.set_pixel(x, y, Vec3{});
                    if (result.alpha) result.alpha->set_pixel(x, y, Vec3{});
                }
    }
    return result;
}

}  // namespace wardray::render
