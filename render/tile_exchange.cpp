// TileExchange: which process renders which tile, and the records, pixels and counters they exchange.
#include "render/tile_exchange.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstring>
#include <ctime>
#include <stdexcept>
#include <type_traits>
#include <utility>

#include "cache/irradiance_cache.h"

namespace wardray::render {

namespace {

using Clock = std::chrono::steady_clock;

/// The positions of `cost` from the costliest to the cheapest; equal costs keep their order.
std::vector<std::size_t> costliest_first(const std::vector<double>& cost) {
    std::vector<std::size_t> order(cost.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return cost[a] > cost[b]; });
    return order;
}

// Records travel as their bytes: every process is the same executable on the same kind of machine.
static_assert(std::is_trivially_copyable_v<cache::IrradianceRecord>);
static_assert(std::is_trivially_copyable_v<lighting::RayCounters>);
static_assert(std::is_trivially_copyable_v<RankStatistics>);
static_assert(std::is_trivially_copyable_v<RankWaveTimes>);

/// This process's processor time in seconds, every thread together.
double cpu_seconds() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

/// Wall time in seconds from a steady clock.
double wall_seconds() { return std::chrono::duration<double>(Clock::now().time_since_epoch()).count(); }

}  // namespace

std::vector<Bytes> Communicator::allgather(const Bytes& mine) {
    const auto start = Clock::now();
    std::vector<Bytes> all = do_allgather(mine);
    count(mine, all, std::chrono::duration<double>(Clock::now() - start).count());
    return all;
}

std::vector<Bytes> Communicator::gather(const Bytes& mine) {
    const auto start = Clock::now();
    std::vector<Bytes> all = do_gather(mine);
    count(mine, all, std::chrono::duration<double>(Clock::now() - start).count());
    return all;
}

void Communicator::count(const Bytes& mine, const std::vector<Bytes>& received, double seconds) {
    ++m_traffic.exchanges;
    m_traffic.bytes_sent += mine.size();
    for (std::size_t r = 0; r < received.size(); ++r)
        if (static_cast<int>(r) != rank()) m_traffic.bytes_received += received[r].size();
    m_traffic.seconds += seconds;
}

void ByteReader::take(void* out, std::size_t n) {
    if (m_bytes->size() - m_at < n) throw std::out_of_range("tile exchange: a message ends early");
    std::memcpy(out, m_bytes->data() + m_at, n);
    m_at += n;
}

TileExchange::TileExchange(Communicator* communicator)
    : m_comm(communicator && communicator->size() > 1 ? communicator : nullptr) {}

void TileExchange::begin(int tile_count, std::size_t wave_count, int tiles_x) {
    m_cost.assign(static_cast<std::size_t>(std::max(tile_count, 0)), 0.0);
    m_measured = m_cost;
    m_cost_before = m_cost;
    m_cost_pass.assign(m_cost.size(), -1);
    m_tiles_x = std::max(tiles_x, 1);
    m_pass = 0;
    m_waves = 0;
    m_counters.reset();
    if (m_comm) m_counters = m_comm->shared_counters(wave_count);
}

double TileExchange::thread_seconds() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

void TileExchange::tile_cost(int tile, double seconds) {
    if (m_comm && tile >= 0 && static_cast<std::size_t>(tile) < m_measured.size())
        m_measured[static_cast<std::size_t>(tile)] = seconds;
}

std::vector<double> TileExchange::predicted_costs(const std::vector<int>& wave) const {
    std::vector<double> cost;
    for (const int tile : wave) {
        const auto t = static_cast<std::size_t>(tile);
        if (t >= m_cost.size() || !(m_cost[t] > 0.0) || m_cost_pass[t] >= m_pass) return {};
        cost.push_back(m_cost[t]);
    }
    // The growth of the tiles rendered in this pass, each weighing 1 / distance in tiles: a tile's cost follows
    // the records its region still needs, which changes smoothly across the image from one pass to the next.
    std::vector<std::size_t> grown;
    for (std::size_t u = 0; u < m_cost.size(); ++u)
        if (m_cost_pass[u] == m_pass && m_cost_before[u] > 0.0) grown.push_back(u);
    if (grown.empty()) return cost;
    for (std::size_t i = 0; i < wave.size(); ++i) {
        const int tx = wave[i] % m_tiles_x, ty = wave[i] / m_tiles_x;
        double weighted = 0.0, weights = 0.0;
        for (const std::size_t u : grown) {
            const double dx = static_cast<double>(static_cast<int>(u) % m_tiles_x - tx);
            const double dy = static_cast<double>(static_cast<int>(u) / m_tiles_x - ty);
            const double w = 1.0 / std::max(std::sqrt(dx * dx + dy * dy), 1e-3);
            weighted += w * (m_cost[u] / m_cost_before[u]);
            weights += w;
        }
        cost[i] *= weighted / weights;
    }
    return cost;
}

std::vector<int> TileExchange::fixed_share(const std::vector<int>& wave) const {
    const auto size = static_cast<std::size_t>(m_comm->size());
    const auto rank = static_cast<std::size_t>(m_comm->rank());
    const std::vector<double> cost = wave.size() > size ? predicted_costs(wave) : std::vector<double>{};
    std::vector<int> mine;
    if (!cost.empty()) {
        // Longest processing time first (Graham 1969), on the costs every process holds alike: the same shares
        // everywhere. Ties go to the earlier tile of the wave and the lower rank.
        std::vector<double> load(size, 0.0);
        for (const std::size_t i : costliest_first(cost)) {
            const auto least = static_cast<std::size_t>(std::min_element(load.begin(), load.end()) - load.begin());
            load[least] += cost[i];
            if (least == rank) mine.push_back(wave[i]);
        }
    } else {
        for (std::size_t i = 0; i < wave.size(); ++i)
            if ((i + m_waves) % size == rank) mine.push_back(wave[i]);
    }
    return mine;
}

void TileExchange::start_wave(const std::vector<int>& wave) {
    m_wave = wave;
    m_taken.clear();
    m_next = 0;
    if (!m_comm) {
        m_order = wave;
        return;
    }
    m_wave_start = cpu_seconds();
    m_wave_wall_start = wall_seconds();
    if (m_counters) {
        // Drawn as processes become free, the costliest first when every cost is known: greedy list scheduling
        // in that order ends within the last tile's cost of the best split. The order is the same everywhere, as
        // the costs are.
        m_order = wave;
        const std::vector<double> cost = predicted_costs(wave);
        if (!cost.empty()) {
            const std::vector<std::size_t> order = costliest_first(cost);
            for (std::size_t i = 0; i < order.size(); ++i) m_order[i] = wave[order[i]];
        }
    } else {
        m_order = fixed_share(wave);
    }
}

int TileExchange::next_tile() {
    std::size_t i = 0;
    if (m_counters) {
        if (m_waves >= m_counters->size()) throw std::logic_error("tile exchange: more waves than counters");
        i = static_cast<std::size_t>(m_counters->take(static_cast<std::size_t>(m_waves)));
    } else {
        i = m_next.fetch_add(1);
    }
    if (i >= m_order.size()) return -1;
    const int tile = m_order[i];
    if (m_comm) {
        std::lock_guard<std::mutex> lock(m_taken_mutex);
        m_taken.push_back(tile);
    }
    return tile;
}

std::vector<int> TileExchange::taken() const {
    if (!m_comm) return m_wave;
    std::vector<char> mine(m_cost.size(), 0);
    {
        std::lock_guard<std::mutex> lock(m_taken_mutex);
        for (const int tile : m_taken) mine[static_cast<std::size_t>(tile)] = 1;
    }
    std::vector<int> in_order;
    for (const int tile : m_wave)
        if (static_cast<std::size_t>(tile) < mine.size() && mine[static_cast<std::size_t>(tile)]) in_order.push_back(tile);
    return in_order;
}

void TileExchange::end_wave(const std::vector<int>& wave, const std::vector<int>& mine,
                            cache::IrradianceCache* cache) {
    ++m_waves;
    m_mine.tiles += mine.size();
    if (!m_comm || wave.empty()) return;
    const double busy = cpu_seconds() - m_wave_start;
    const double tiles_done = wall_seconds();
    m_mine.busy_seconds += busy;
    if (!cache) {
        m_unexchanged += busy;
        return;
    }
    // This process's time on the wave, then each of its tiles: its index, its lookup counts and its records in the
    // order they were made.
    ByteWriter out;
    out.put(busy);
    std::uint64_t made = 0;
    for (const int tile : mine) {
        const cache::TileCache::Contribution c = cache->tile(tile).contribution();
        out.put(static_cast<std::int32_t>(tile));
        out.put(m_measured[static_cast<std::size_t>(tile)]);
        out.put(c.lookups);
        out.put(c.hits);
        out.put(static_cast<std::uint64_t>(c.records.size()));
        for (const cache::IrradianceRecord& r : c.records) out.put(r);
        made += c.records.size();
    }
    m_mine.records_made += made;
    const std::vector<Bytes> all = m_comm->allgather(out.bytes());
    m_wave_times.push_back({busy, tiles_done - m_wave_wall_start, wall_seconds() - tiles_done, 0.0});
    WaveStatistics stats;
    stats.tiles = wave.size();
    stats.records = made;
    // The other processes' tiles take over what those processes made; merge_tiles(wave) then fixes the order.
    std::vector<char> in_wave(static_cast<std::size_t>(*std::max_element(wave.begin(), wave.end())) + 1, 0);
    for (const int tile : wave) in_wave[static_cast<std::size_t>(tile)] = 1;
    for (std::size_t r = 0; r < all.size(); ++r) {
        ByteReader in(all[r]);
        const auto rank_busy = in.get<double>();
        stats.bytes += all[r].size();
        stats.busy_max = std::max(stats.busy_max, rank_busy);
        stats.busy_sum += rank_busy;
        while (!in.done()) {
            const auto tile = in.get<std::int32_t>();
            if (tile < 0 || static_cast<std::size_t>(tile) >= in_wave.size() || !in_wave[static_cast<std::size_t>(tile)])
                throw std::runtime_error("tile exchange: a process sent a tile outside the wave");
            // Every process keeps the same costs: its own tiles' as it sent them.
            const auto t = static_cast<std::size_t>(tile);
            if (m_cost_pass[t] < m_pass) m_cost_before[t] = m_cost[t];
            m_cost[t] = std::max(in.get<double>(), 1e-9);
            m_cost_pass[t] = m_pass;
            cache::TileCache::Contribution c;
            c.lookups = in.get<std::uint64_t>();
            c.hits = in.get<std::uint64_t>();
            const auto count = in.get<std::uint64_t>();
            in.get(c.records, static_cast<std::size_t>(count));
            if (static_cast<int>(r) == m_comm->rank()) continue;
            m_mine.records_received += count;
            stats.records += count;
            cache->tile(tile).adopt(std::move(c));
        }
    }
    m_wave_stats.push_back(stats);
}

void TileExchange::merge_wave(const std::vector<int>& wave, cache::IrradianceCache& cache) {
    if (!m_comm) {
        cache.merge_tiles(wave);
        return;
    }
    const double start = wall_seconds();
    cache.merge_tiles(wave);
    const double seconds = wall_seconds() - start;
    m_mine.merge_seconds += seconds;
    if (!m_wave_times.empty()) m_wave_times.back().merge = seconds;
}

void TileExchange::gather_image(const std::vector<TileRect>& mine, Film& film, Film* irradiance, Film* alpha,
                                lighting::RayCounters& rays, std::uint64_t& non_finite, std::uint64_t& supersampled) {
    if (!m_comm) {
        m_ranks.clear();
        return;
    }
    // The counters first, then each tile's pixels row by row (and its irradiance pixels).
    ByteWriter out;
    out.put(m_unexchanged);
    out.put(rays);
    out.put(non_finite);
    out.put(supersampled);
    for (const TileRect& t : mine) {
        out.put(t);
        for (const Film* f : {static_cast<const Film*>(&film), static_cast<const Film*>(irradiance),
                              static_cast<const Film*>(alpha)}) {
            if (!f) continue;
            for (int y = t.y0; y < t.y1; ++y)
                for (int x = t.x0; x < t.x1; ++x) {
                    const Vec3 c = f->pixel(x, y);
                    out.put(std::array<float, 3>{static_cast<float>(c.x), static_cast<float>(c.y),
                                                 static_cast<float>(c.z)});
                }
        }
    }
    const std::vector<Bytes> all = m_comm->gather(out.bytes());
    if (m_comm->rank() == 0) {
        // The waves without an exchange (a render without a cache is one) as one more wave.
        WaveStatistics final_wave;
        final_wave.busy_max = final_wave.busy_sum = m_unexchanged;
        for (std::size_t r = 0; r < all.size(); ++r) final_wave.bytes += all[r].size();
        for (std::size_t r = 1; r < all.size(); ++r) {
            ByteReader in(all[r]);
            const auto busy = in.get<double>();
            final_wave.busy_max = std::max(final_wave.busy_max, busy);
            final_wave.busy_sum += busy;
            rays += in.get<lighting::RayCounters>();
            non_finite += in.get<std::uint64_t>();
            supersampled += in.get<std::uint64_t>();
            while (!in.done()) {
                const auto t = in.get<TileRect>();
                if (t.x0 < 0 || t.y0 < 0 || t.x1 > film.width() || t.y1 > film.height())
                    throw std::runtime_error("tile exchange: a process sent pixels outside the image");
                for (Film* f : {&film, irradiance, alpha}) {
                    if (!f) continue;
                    for (int y = t.y0; y < t.y1; ++y)
                        for (int x = t.x0; x < t.x1; ++x) {
                            const auto c = in.get<std::array<float, 3>>();
                            f->set_pixel(x, y, {c[0], c[1], c[2]});
                        }
                }
            }
        }
        if (final_wave.busy_sum > 0.0) m_wave_stats.push_back(final_wave);
    }
    // Last, each process's share and traffic (this exchange's own bytes not included), and its times per wave.
    ByteWriter stats;
    RankStatistics s = m_mine;
    s.traffic = m_comm->traffic();
    stats.put(s);
    for (const RankWaveTimes& t : m_wave_times) stats.put(t);
    const std::vector<Bytes> every = m_comm->gather(stats.bytes());
    m_ranks.clear();
    for (const Bytes& b : every) {
        ByteReader in(b);
        m_ranks.push_back(in.get<RankStatistics>());
        for (std::size_t w = 0; w < m_wave_times.size() && w < m_wave_stats.size(); ++w)
            m_wave_stats[w].ranks.push_back(in.get<RankWaveTimes>());
    }
}

}  // namespace wardray::render
