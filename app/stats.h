// --stats: the run's phase times, passes, rays and cache figures as a JSON file.
#pragma once

#include <filesystem>

#include "app/run.h"

namespace wardray::app {

/// How long each phase of a run took, in seconds (render includes the pretrace passes).
struct PhaseTimes {
    double parse = 0.0;
    double build = 0.0;
    double render = 0.0;
    double write = 0.0;
};

/// The process's peak resident memory at the end of each phase, in bytes: the parser's memory is the first.
struct PeakMemory {
    std::size_t parse = 0;
    std::size_t build = 0;
    std::size_t total = 0;
};

/// Writes the statistics of a finished run to `path`; false (with a message) when the file cannot be written.
bool write_stats(const std::filesystem::path& path, const Job& job, const scene::Scene& scene,
                 const Illumination& illumination, const render::RenderResult& result, const PhaseTimes& times,
                 const PeakMemory& memory, Clock::time_point run_start);

}  // namespace wardray::app
