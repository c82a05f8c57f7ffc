// Renderer: traces the image in tiles on a thread pool, deterministically for any thread count.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "geometry/scene_geometry.h"
#include "lighting/integrator.h"
#include "scene/scene.h"
#include "render/film.h"
#include "render/tile_exchange.h"

namespace wardray::cache {
class IrradianceCache;
}  // namespace wardray::cache

namespace wardray::render {

/// POV-Ray's adaptive supersampling (+A) and its parameters: method 1 (non-recursive) or 2 (recursive).
struct AntialiasSettings {
    bool enabled = false;
    double threshold = 0.3;  ///< +A0.3: summed RGB difference of gamma-encoded neighbours that triggers it
    int depth = 3;           ///< +R3: method 1 gives a supersampled pixel depth x depth extra samples; method 2
                             ///< splits it into quarters up to depth - 1 times
    double jitter = 1.0;     ///< +J1.0; 0 turns jitter off
    double gamma = 2.5;      ///< +AG2.5: neighbours are compared as pow(c, 1/gamma)
    int method = 1;          ///< +AM1 or +AM2
};

/// A rectangle of pixels, [x0, x1) × [y0, y1), rows from the top.
struct PixelRegion {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;

    bool contains(int x, int y) const { return x >= x0 && x < x1 && y >= y0 && y < y1; }
    friend bool operator==(const PixelRegion&, const PixelRegion&) = default;
};

struct RenderSettings {
    int width = 320;
    int height = 240;
    /// A partial render (+SR/+ER/+SC/+EC): only these pixels, the rest of the film black. The tiles it touches are
    /// rendered whole, so each pixel is the one the full render makes (byte for byte without radiosity, whose cache
    /// depends on what was traced before).
    std::optional<PixelRegion> region;
    int tile_size = 32;  ///< POV-Ray's render block size; antialiasing decisions are made per block
    AntialiasSettings antialias;
    bool pretrace = true;  ///< fill the irradiance cache with POV-Ray's pretrace passes before the final pass
    /// Then the record passes (--gi-record-pass): the final pass's first rays with its lookups, colours thrown away,
    /// so that the records the final pass would make are made before it and every pixel sees them.
    bool record_pass = true;
    /// --seed: turns the renderer's random streams (cache gathers, pretrace, antialiasing and focal blur jitter);
    /// 0 draws those of a render without it (core/render_seed.h).
    std::uint64_t seed = 0;
    bool irradiance_aov = false;  ///< keep each pixel's indirect irradiance (at its centre sample) in a second film
    /// Output_Alpha (+UA): keep each pixel's alpha in a film of its own (the integrator must see the background
    /// as transparent: IntegratorOptions::output_alpha).
    bool alpha = false;
    /// Processes to share the render with (rendering across MPI ranks); null: this process renders every tile. The
    /// image, the cache and the counters are the same either way; only process 0's result holds the whole image.
    Communicator* communicator = nullptr;
};

/// One pass over the image: a pretrace pass with its block size in pixels, or the final pass.
struct PassTiming {
    std::string kind;  ///< "pretrace", "record" or "final"
    double block_size = 1.0;
    double seconds = 0.0;
};

/// Called as tiles complete with the fraction done (0..1); called from worker threads, one at a time.
using ProgressFn = std::function<void(double fraction)>;

/// The finished image and the rays it took.
struct RenderResult {
    Film film;
    lighting::RayCounters rays;
    std::uint64_t non_finite_pixels = 0;  ///< pixels whose radiance was NaN or infinite (written as black)
    std::uint64_t supersampled_pixels = 0;
    std::vector<PassTiming> passes;
    std::optional<Film> irradiance;  ///< RenderSettings::irradiance_aov: indirect irradiance per pixel, else empty
    std::optional<Film> alpha;       ///< RenderSettings::alpha: each pixel's alpha (all three channels), else empty
    std::vector<RankStatistics> ranks;  ///< each process's share, by rank, when the render was shared among several
    std::vector<WaveStatistics> waves;  ///< and each wave's work and exchange
};

/// POV-Ray's pretrace block sizes in pixels for an image of width × height: pretrace_start to pretrace_end of the
/// larger side, halving.
std::vector<double> pretrace_sizes(const scene::RadiositySettings& settings, int width, int height);

/// Renders every pixel. Each pixel depends only on its own rays and on the cache as it stood when the pass began
/// (plus its own tile's records), so tiles may finish in any order and the image is the same for any number of
/// threads. With an irradiance cache (and an integrator in cache mode) the pretrace passes fill it first; the
/// cache keeps every record made, for statistics and +RFO.
RenderResult render_image(const scene::Scene& scene, const lighting::Integrator& integrator,
                          const RenderSettings& settings, const ProgressFn& progress,
                          cache::IrradianceCache* cache = nullptr);

}  // namespace wardray::render
