// What travels with a ray through the integrator's recursion: its trace level, weight, band and interiors, and the
// worker's counters and cache view.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/vec3.h"
#include "lighting/path_guide.h"
#include "photons/dispersion.h"

namespace wardray::scene {
struct Scene;
struct Object;
}  // namespace wardray::scene

namespace wardray::cache {
class TileCache;
}  // namespace wardray::cache

namespace wardray::lighting {

/// Rays traced, by kind, for --stats. Each thread keeps its own and the totals are summed.
struct RayCounters {
    std::uint64_t camera = 0;
    std::uint64_t shadow = 0;
    std::uint64_t secondary = 0;  ///< reflected, refracted and transmitted rays
    std::uint64_t gather = 0;     ///< hemisphere rays for indirect light (cache gathers and reference paths)
    std::uint64_t gathers = 0;    ///< hemisphere gathers made (new cache records, or reference estimates)

    /// Adds another thread's counts.
    RayCounters& operator+=(const RayCounters& o) {
        camera += o.camera;
        shadow += o.shadow;
        secondary += o.secondary;
        gather += o.gather;
        gathers += o.gathers;
        return *this;
    }
};

/// What one worker carries through the ray recursion of one tile: its counters and its view of the cache.
struct TraceContext {
    RayCounters rays;
    cache::TileCache* cache = nullptr;  ///< the tile's view of the irradiance cache (cache mode only)
    bool final_pass = true;             ///< false in POV-Ray's pretrace passes: their lookups' parameters
    /// False in every pass whose colours are thrown away (the pretrace and the record passes after it): camera hits
    /// there only fill the cache, so their own direct light is skipped.
    bool colour_kept = true;
    /// The next cache gather's seed: set per tile and pass by the renderer and stepped by each gather, so a record's
    /// samples depend on the order the tile makes records in (fixed), not on its position: a scene scaled by any
    /// factor then draws the same samples.
    std::uint64_t gather_seed = 0;
    /// POV-Ray's litObjectIgnoresPhotons: the surface being lit has `collect off`, so shadows through photon
    /// targets stay filtered for it.
    bool lit_ignores_photons = false;
    /// --aov irradiance: the indirect irradiance first computed on the current camera path lands here.
    bool capture_irradiance = false;
    bool captured = false;
    Vec3 irradiance;
    /// Output_Alpha: how much of the transparent background the last traced ray (or shaded surface) lets through,
    /// POV-Ray's transmit channel of its colour; 0 on rays that see the background opaque.
    double transmit = 0.0;
    /// Reference mode's pilot pass (Integrator::learn_guide): where every path vertex's incoming radiance is
    /// recorded, and how many paths a camera hit starts (0: --gi-rays); null outside the pilot.
    std::vector<GuideSample>* guide_samples = nullptr;
    int pilot_paths = 0;
};

/// The interiors a ray is inside, innermost last (POV-Ray's ray interior list), each named by the object whose
/// surface the ray crossed (a CSG leaf): objects that share an interior (scene::same_interior) count as one.
struct InteriorStack {
    static constexpr int kMax = 16;
    std::array<const scene::Object*, kMax> objects{};
    int size = 0;

    /// True when the ray is inside the interior of object `o`.
    bool contains(const scene::Object& o) const;
    /// Enters the interior of `o` (ignored beyond kMax interiors).
    void push(const scene::Object& o);
    /// Leaves the interior of `o`; false when the ray was not inside it.
    bool remove(const scene::Object& o);
    /// The innermost interior's object (size > 0).
    const scene::Object& top() const { return *objects[size - 1]; }
};

/// POV-Ray's IsHollowRay: the ray is inside no object whose interior is not hollow (fog reaches it).
bool hollow_ray(const InteriorStack& interiors);

/// What travels with a ray through the recursion: POV-Ray's trace level, weight (for adc_bailout) and interiors.
struct RayState {
    int level = 0;
    int max_level = 5;    ///< POV-Ray's max_trace_level, raised for gathers so they always see one surface
    double weight = 1.0;
    double adc_bailout = 0.0;  ///< POV-Ray's ticket bailout: the scene's, or radiosity's inside a gather
    int gi_depth = 0;          ///< radiosity bounce depth: 0 for camera paths, +1 per gather
    bool gather_ray = false;   ///< on a gather ray's path: highlights are left out (POV-Ray compat)
    /// Output_Alpha (+UA): the background is transparent on this ray (POV-Ray's alphaBackground: camera rays and
    /// the rays they refract or transmit; reflected and gather rays see it opaque).
    bool alpha_background = false;
    std::uint64_t path_seed = 0;  ///< reference mode: tells the independent paths of one pixel apart
    /// Reference mode: the scrambling of the Sobol sequence a pixel's paths share (lighting/path_sequence.h),
    /// this path's point in it and the number of paths (0: not a reference path; deeper bounces draw uniformly).
    std::uint64_t path_group = 0;
    int path_index = 0;
    int path_count = 0;
    /// The spectral band of a ray that a dispersive surface split (POV-Ray's SpectralBand): later dispersive
    /// surfaces bend it by its band's index instead of splitting it again. White light until then.
    photons::SpectralBand band;
    InteriorStack interiors;
};

}  // namespace wardray::lighting
