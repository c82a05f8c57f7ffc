// CacheCarry: the irradiance cache carried from one frame of an animation to the next (--gi-carry).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "app/options.h"
#include "cache/irradiance_cache.h"
#include "scene/scene.h"

namespace wardray::app {

/// What a frame leaves to the next: its cache's records and what its scene held where records depend on it.
class CacheCarry {
public:
    explicit CacheCarry(CarryMode mode) : m_mode(mode) {}

    bool active() const { return m_mode != CarryMode::Off; }

    /// Starts `cache` (the new frame's, empty) with the previous frame's records: with CarryMode::Still, without
    /// those from which an object that changed between the frames (in either frame's place) covers more than
    /// kChangedShare of the hemisphere, and without any when a light, the sky or the radiosity settings changed
    /// (or an unbounded object did). Returns (kept, dropped); nothing on the first frame.
    std::optional<std::pair<std::size_t, std::size_t>> start(const scene::Scene& scene,
                                                             cache::IrradianceCache& cache) const;
    /// Keeps the frame's records and scene for the next frame.
    void finish(const scene::Scene& scene, const cache::IrradianceCache& cache);

    /// A changed object at the distance from which it covers this share of the hemisphere (its bounding sphere's
    /// solid angle over 2π) or more invalidates a record.
    static constexpr double kChangedShare = 0.01;

private:
    CarryMode m_mode;
    std::string m_records;  ///< the previous frame's cache, as +RFO would write it
    std::optional<scene::Scene> m_previous;
};

}  // namespace wardray::app
