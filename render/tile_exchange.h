// TileExchange: a render's tiles shared among processes, with the cache records of each wave exchanged in tile order.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

#include "lighting/trace_context.h"
#include "render/communicator.h"
#include "render/film.h"

namespace wardray::cache {
class IrradianceCache;
}  // namespace wardray::cache

namespace wardray::render {

/// One process's share of a render across processes, for --stats.
struct RankStatistics {
    std::uint64_t tiles = 0;             ///< tiles rendered, over every pass
    std::uint64_t records_made = 0;      ///< cache records this process gathered
    std::uint64_t records_received = 0;  ///< cache records adopted from the other processes
    double busy_seconds = 0.0;           ///< processor time spent on its tiles (robust on a shared machine)
    double merge_seconds = 0.0;          ///< wall time merging the waves' records (every process merges them all)
    Communicator::Traffic traffic;       ///< bytes sent and received, and time in exchanges
};

/// Where one process's wall time went in one wave: its share of the tiles, the exchange (mostly waiting for the
/// slowest process) and the merge.
struct RankWaveTimes {
    double busy = 0.0;      ///< processor seconds on its tiles
    double tiles = 0.0;     ///< wall seconds from the wave's start until its last tile was done
    double exchange = 0.0;  ///< wall seconds in the exchange: waiting for the others, then the transfer
    double merge = 0.0;     ///< wall seconds merging the wave's records
};

/// One wave of one pass across processes, for --stats and the scaling model (docs/mpi.md).
struct WaveStatistics {
    std::uint64_t tiles = 0;
    std::uint64_t records = 0;  ///< records the wave made, over every process
    std::uint64_t bytes = 0;    ///< bytes every process sent in the wave's exchange, together
    double busy_max = 0.0;      ///< processor seconds of the busiest process: the wave's length on idle processors
    double busy_sum = 0.0;      ///< processor seconds over every process
    std::vector<RankWaveTimes> ranks;  ///< each process's times, by rank (on process 0 after gather_image())
};

/// How the tiles of one render are shared among the processes of a Communicator, deterministically: every
/// process renders its share of each wave, then the wave's records are exchanged and every process merges the
/// records of the whole wave in the wave's tile order, as one process would. So the cache, and with it the image,
/// is the same bit for bit for any number of processes and threads.
class TileExchange {
public:
    /// `communicator` null or of one process: this process renders every tile and nothing is exchanged.
    explicit TileExchange(Communicator* communicator);

    bool distributed() const { return m_comm != nullptr; }
    bool root() const { return !m_comm || m_comm->rank() == 0; }

    /// Readies the exchange for a render of `tile_count` tiles, `tiles_x` to a row, in `wave_count` waves over every
    /// pass (collective when distributed: the processes then set up the counters they draw tiles from).
    void begin(int tile_count, std::size_t wave_count, int tiles_x = 1);
    /// A new pass over the tiles begins: each tile's cost in the passes before is what start_wave() predicts from.
    void start_pass() { ++m_pass; }
    /// Starts `wave`: afterwards next_tile() hands out its tiles. Distributed, processes draw the wave's tiles from
    /// a counter they share, each taking the next tile as it becomes free, the costliest first once every tile's
    /// cost in an earlier pass is known (predicted_costs()). Where the processes cannot share counters, the shares
    /// are fixed in advance: longest processing time first on the known costs, otherwise every size()-th tile, the
    /// starting point turning with each wave so that one-tile waves do not all fall to the same process. Who renders
    /// a tile never changes a pixel.
    void start_wave(const std::vector<int>& wave);
    /// The next tile of the wave this process renders, or -1 when there is none left for it (any thread).
    int next_tile();
    /// The tiles of the wave this process took, in the wave's order (after every next_tile() call of the wave).
    std::vector<int> taken() const;
    /// The processor seconds tile `tile` took in this pass (from its worker thread; each tile is one thread's).
    void tile_cost(int tile, double seconds);
    /// This thread's processor time in seconds.
    static double thread_seconds();
    /// After each wave (collective when there is a cache): sends the records this process's tiles made and adopts
    /// the other processes' into their tiles' views, so that cache->merge_tiles(wave) then merges the same records
    /// everywhere. Without a cache (one wave, no records) it only keeps the time.
    void end_wave(const std::vector<int>& wave, const std::vector<int>& mine, cache::IrradianceCache* cache);
    /// Then cache->merge_tiles(wave), timed when distributed.
    void merge_wave(const std::vector<int>& wave, cache::IrradianceCache& cache);
    /// True when the tiles are drawn from shared counters (for --stats and tests).
    bool drawn() const { return m_counters != nullptr; }

    /// The pixels of a tile: [x0, x1) × [y0, y1).
    struct TileRect {
        int tile, x0, y0, x1, y1;
    };
    /// After the final pass: the pixels of `mine` (and of `irradiance` and `alpha` when given), the counters and each
    /// process's statistics go to process 0, whose films then hold the whole image and whose totals are everyone's
    /// (collective). Other processes keep only their own.
    void gather_image(const std::vector<TileRect>& mine, Film& film, Film* irradiance, Film* alpha,
                      lighting::RayCounters& rays, std::uint64_t& non_finite, std::uint64_t& supersampled);

    /// Every process's statistics, by rank, on process 0 once gather_image() has run; empty elsewhere and for
    /// one process.
    const std::vector<RankStatistics>& ranks() const { return m_ranks; }
    /// Every wave exchanged, in order (the same on every process); empty for one process.
    const std::vector<WaveStatistics>& waves() const { return m_wave_stats; }

private:
    /// The fixed shares of a wave, for processes that cannot draw from shared counters.
    std::vector<int> fixed_share(const std::vector<int>& wave) const;
    /// Each tile of `wave`'s cost in this pass as predicted from what every process holds alike, or empty when a
    /// tile's cost in an earlier pass is not known: that cost, scaled by how much dearer the tiles already rendered
    /// in this pass became since their previous pass, nearer tiles weighing more.
    std::vector<double> predicted_costs(const std::vector<int>& wave) const;

    Communicator* m_comm;
    std::unique_ptr<SharedCounters> m_counters;  ///< one counter per wave; null: fixed shares
    std::uint64_t m_waves = 0;
    std::vector<int> m_order;         ///< the current wave's tiles in the order they are handed out
    std::atomic<std::size_t> m_next{0};  ///< the next of m_order to hand out, without counters
    std::vector<int> m_wave;          ///< the current wave, as listed
    mutable std::mutex m_taken_mutex;
    std::vector<int> m_taken;         ///< the current wave's tiles this process took
    double m_wave_start = 0.0;   ///< processor time when this process started its share of the wave
    double m_wave_wall_start = 0.0;  ///< and the wall time
    std::vector<RankWaveTimes> m_wave_times;  ///< this process's times in each exchanged wave
    double m_unexchanged = 0.0;  ///< busy time of waves without an exchange, sent with the image
    std::vector<double> m_cost;  ///< each tile's last exchanged cost (the same on every process); 0: not known
    std::vector<double> m_cost_before;  ///< and its cost the time before that; 0: not known
    std::vector<int> m_cost_pass;  ///< the pass m_cost was measured in
    int m_tiles_x = 1;
    int m_pass = 0;
    std::vector<double> m_measured;  ///< this process's tiles' costs in the current wave
    RankStatistics m_mine;
    std::vector<RankStatistics> m_ranks;
    std::vector<WaveStatistics> m_wave_stats;
};

}  // namespace wardray::render
