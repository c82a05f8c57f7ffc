// --stats: the run's phase times, passes, rays and cache figures as a JSON file.
#include "app/stats.h"

#include <iostream>
#include <nlohmann/json.hpp>
#include <thread>

#include "app/whole_file.h"
#include "photons/photon_shooter.h"

namespace wardray::app {

namespace {

const char* gi_name(lighting::GiMode mode) {
    switch (mode) {
        case lighting::GiMode::Off: return "off";
        case lighting::GiMode::Cache: return "cache";
        case lighting::GiMode::Reference: return "reference";
    }
    return "off";
}

// The cache's records per pass and depth, lookups, hit rate, mean radius, memory and rays per record; null without one.
nlohmann::json cache_stats(const cache::IrradianceCache* irradiance_cache, const lighting::RayCounters& rays) {
    if (!irradiance_cache) return nullptr;
    const cache::CacheStatistics cs = irradiance_cache->statistics();
    nlohmann::json per_pass = nlohmann::json::array();
    for (const auto& depths : cs.records) per_pass.push_back(depths);
    const double rays_per_record =
        rays.gathers > 0 ? static_cast<double>(rays.gather) / static_cast<double>(rays.gathers) : 0.0;
    return {{"records_per_pass_and_depth", per_pass},
            {"records", cs.total_records},
            {"lookups", cs.lookups},
            {"hits", cs.hits},
            {"hit_rate", cs.hit_rate()},
            {"mean_radius", cs.mean_radius},
            {"memory_bytes", cs.memory_bytes},
            {"rays_per_record", rays_per_record}};
}

// A render shared among processes: each rank's share and traffic, and each wave's work and exchange; null for one.
nlohmann::json process_stats(const render::RenderResult& result) {
    if (result.ranks.empty()) return nullptr;
    nlohmann::json ranks = nlohmann::json::array();
    std::uint64_t bytes = 0;
    for (std::size_t r = 0; r < result.ranks.size(); ++r) {
        const render::RankStatistics& s = result.ranks[r];
        bytes += s.traffic.bytes_sent;
        ranks.push_back({{"rank", r},
                         {"tiles", s.tiles},
                         {"records_made", s.records_made},
                         {"records_received", s.records_received},
                         {"bytes_sent", s.traffic.bytes_sent},
                         {"bytes_received", s.traffic.bytes_received},
                         {"exchanges", s.traffic.exchanges},
                         {"exchange_seconds", s.traffic.seconds},
                         {"busy_cpu_seconds", s.busy_seconds},
                         {"merge_seconds", s.merge_seconds}});
    }
    nlohmann::json waves = nlohmann::json::array();
    double critical = 0.0, busy = 0.0;
    for (const render::WaveStatistics& w : result.waves) {
        critical += w.busy_max;
        busy += w.busy_sum;
        // Each rank's wall time in the wave: its tiles, the exchange (waiting for the slowest rank) and the merge.
        nlohmann::json by_rank = nlohmann::json::array();
        for (const render::RankWaveTimes& t : w.ranks)
            by_rank.push_back({{"busy_cpu_seconds", t.busy}, {"tiles_seconds", t.tiles},
                               {"exchange_seconds", t.exchange}, {"merge_seconds", t.merge}});
        waves.push_back({{"tiles", w.tiles}, {"records", w.records}, {"bytes", w.bytes},
                         {"busy_max_cpu_seconds", w.busy_max}, {"busy_sum_cpu_seconds", w.busy_sum},
                         {"ranks", by_rank}});
    }
    return {{"count", result.ranks.size()},
            {"bytes_exchanged", bytes},
            {"critical_cpu_seconds", critical},
            {"busy_cpu_seconds", busy},
            {"ranks", ranks},
            {"waves", waves}};
}

}  // namespace

bool write_stats(const std::filesystem::path& path, const Job& job, const scene::Scene& scene,
                 const Illumination& illumination, const render::RenderResult& result, const PhaseTimes& times,
                 const PeakMemory& memory, Clock::time_point run_start) {
    const Options& options = job.options;
    nlohmann::json stats;
    stats["scene"] = options.scene.string();
    stats["output"] = options.write_output ? job.output.string() : "";
    stats["width"] = options.width;
    stats["height"] = options.height;
    stats["threads"] = options.threads > 0 ? options.threads : static_cast<int>(std::thread::hardware_concurrency());
    stats["gi"] = gi_name(illumination.settings.gi);
    stats["radiosity_block"] = scene.global.radiosity.has_value();
    double pretrace_seconds = 0.0;
    nlohmann::json passes = nlohmann::json::array();
    for (const render::PassTiming& pass : result.passes) {
        if (pass.kind == "pretrace" || pass.kind == "record") pretrace_seconds += pass.seconds;
        passes.push_back({{"kind", pass.kind}, {"block_size", pass.block_size}, {"seconds", pass.seconds}});
    }
    stats["phases"] = {{"parse", times.parse}, {"build", times.build}, {"pretrace", pretrace_seconds},
                       {"render", times.render - pretrace_seconds}, {"write", times.write}};
    stats["peak_memory_bytes"] = {{"parse", memory.parse}, {"build", memory.build}, {"total", memory.total}};
    stats["passes"] = passes;
    stats["total_seconds"] = seconds_since(run_start);
    stats["rays"] = {{"camera", result.rays.camera},
                     {"shadow", result.rays.shadow},
                     {"secondary", result.rays.secondary},
                     {"gather", result.rays.gather}};
    stats["gathers"] = result.rays.gathers;
    stats["non_finite_pixels"] = result.non_finite_pixels;
    stats["supersampled_pixels"] = result.supersampled_pixels;
    stats["cache"] = cache_stats(illumination.cache.get(), result.rays);
    stats["photons"] = nullptr;
    if (const photons::PhotonStats* ph = illumination.integrator ? illumination.integrator->photon_stats() : nullptr)
        stats["photons"] = {{"units", ph->units},         {"spacing", ph->spacing},
                            {"shot", ph->shot},           {"stored", ph->stored},
                            {"media_stored", ph->media_stored},
                            {"gather_radius", ph->gather_radius},
                            {"media_gather_radius", ph->media_gather_radius},
                            {"shoot_seconds", ph->shoot_seconds}, {"build_seconds", ph->build_seconds}};
    if (!result.ranks.empty()) stats["processes"] = process_stats(result);
    return write_whole_file(path, "statistics", [&](std::ostream& out) { out << stats.dump(2) << "\n"; });
}

}  // namespace wardray::app
