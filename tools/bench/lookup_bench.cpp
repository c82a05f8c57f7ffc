// lookup_bench: times irradiance-cache lookups on a cache saved by +RFO, with a checksum of every result.
//   lookup_bench FILE.rca [--error-bound E] [--low-error-factor F] [--recursion-limit N] [--rounds R]
//                         [--walk-stats 1] [--wide-scan 0|1] [--order 0|1|2]
// The cache is loaded into a cache made for those radiosity settings (the scene's: they choose its filings); then,
// for each record, lookups near it at its depth as the pretrace, the final pass and a low-weight ray make them.
// Prints the load time, nanoseconds per lookup (best of the rounds), the cache's bytes and a checksum of the
// results, which two builds must print alike when they find the same records in the same order. With --walk-stats 1,
// also what an average lookup walks and scans in the octree of its depth (RecordOctree::walk_stats, untimed).
// --wide-scan 0 times the portable scan where the CPU has AVX2 (the checksum must not change). --order chooses the
// order of the queries: 0 the records' (the default; a record's three lookups together), 1 shuffled (successive
// lookups anywhere in the cache), 2 along a Morton curve of their positions (successive lookups as near as a sort
// makes them): between 1 and 2 lies what batching lookups by position could gain. The checksum depends on the
// order.
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include "cache/interpolation.h"
#include "cache/irradiance_cache.h"

namespace {

using namespace wardray;

struct Query {
    Vec3 p, n;
    int depth;
    cache::LookupParams params;
};

std::uint64_t mix(std::uint64_t h, double v) {
    std::uint64_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    return (h ^ bits) * 0x100000001B3ULL;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: lookup_bench FILE.rca [--error-bound E] [--low-error-factor F] "
                             "[--recursion-limit N] [--rounds R] [--walk-stats 1] [--wide-scan 0|1]\n");
        return 2;
    }
    scene::RadiositySettings settings;
    int rounds = 5;
    bool walk_stats = false;
    int order = 0;
    for (int i = 2; i + 1 < argc; i += 2) {
        const std::string flag = argv[i];
        const double value = std::atof(argv[i + 1]);
        if (flag == "--error-bound") settings.error_bound = value;
        else if (flag == "--low-error-factor") settings.low_error_factor = value;
        else if (flag == "--recursion-limit") settings.recursion_limit = static_cast<int>(value);
        else if (flag == "--rounds") rounds = static_cast<int>(value);
        else if (flag == "--walk-stats") walk_stats = value != 0.0;
        else if (flag == "--wide-scan") cache::RecordOctree::use_wide_scan(value != 0.0);
        else if (flag == "--order") order = static_cast<int>(value);
    }
    cache::IrradianceCache cache(settings);
    std::ifstream in(argv[1], std::ios::binary);
    const auto load_start = std::chrono::steady_clock::now();
    cache.load(in);
    const double load_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - load_start).count();

    // Queries: a fixed pseudo-random offset within half a radius of each record, in its tangent plane's
    // neighbourhood, at the three kinds of lookup.
    std::vector<Query> queries;
    std::uint64_t state = 0x9E3779B97F4A7C15ULL;
    auto uniform = [&] {
        state = state * 6364136223846793005ULL + 1442695040888963407ULL;
        return static_cast<double>(state >> 11) * 0x1p-53;
    };
    for (int d = 0; d < cache.depth_count(); ++d) {
        for (const cache::IrradianceRecord& r : cache.records(d)) {
            const Vec3 offset = Vec3{uniform() - 0.5, uniform() - 0.5, uniform() - 0.5} * r.radius;
            for (const auto& [final_pass, weight] :
                 {std::pair{false, 1.0}, std::pair{true, 1.0}, std::pair{true, 0.1}}) {
                queries.push_back(
                    {r.position + offset, r.normal, d, cache::lookup_params(settings, d, final_pass, weight)});
            }
        }
    }
    if (order == 1) {
        // Fisher-Yates with the same generator: the same order on every run.
        for (std::size_t i = queries.size(); i > 1; --i)
            std::swap(queries[i - 1], queries[static_cast<std::size_t>(uniform() * static_cast<double>(i))]);
    } else if (order == 2 && !queries.empty()) {
        Vec3 lo = queries.front().p, hi = lo;
        for (const Query& q : queries) {
            lo = {std::min(lo.x, q.p.x), std::min(lo.y, q.p.y), std::min(lo.z, q.p.z)};
            hi = {std::max(hi.x, q.p.x), std::max(hi.y, q.p.y), std::max(hi.z, q.p.z)};
        }
        // 21 bits an axis, interleaved.
        auto spread = [](std::uint64_t v) {
            v &= 0x1FFFFF;
            v = (v | v << 32) & 0x1F00000000FFFFULL;
            v = (v | v << 16) & 0x1F0000FF0000FFULL;
            v = (v | v << 8) & 0x100F00F00F00F00FULL;
            v = (v | v << 4) & 0x10C30C30C30C30C3ULL;
            v = (v | v << 2) & 0x1249249249249249ULL;
            return v;
        };
        auto cell = [](double x, double a, double b) {
            const double t = b > a ? (x - a) / (b - a) : 0.0;
            return static_cast<std::uint64_t>(std::clamp(t, 0.0, 1.0) * 2097151.0);
        };
        auto key = [&](const Query& q) {
            return spread(cell(q.p.x, lo.x, hi.x)) | spread(cell(q.p.y, lo.y, hi.y)) << 1 |
                   spread(cell(q.p.z, lo.z, hi.z)) << 2;
        };
        std::stable_sort(queries.begin(), queries.end(),
                         [&](const Query& a, const Query& b) { return key(a) < key(b); });
    }
    double best = 1e300;
    std::uint64_t checksum = 0;
    for (int round = 0; round < rounds; ++round) {
        std::uint64_t h = 0xCBF29CE484222325ULL;
        const auto start = std::chrono::steady_clock::now();
        for (const Query& q : queries) {
            const cache::Interpolation r = cache.lookup(q.p, q.n, q.depth, q.params);
            h = mix(mix(mix(mix(h, r.irradiance.x), r.irradiance.y), r.irradiance.z), r.weight_sum);
            h = mix(h, static_cast<double>(r.records));
        }
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        best = std::min(best, seconds);
        checksum = h;
    }
    if (walk_stats && !queries.empty()) {
        cache::RecordOctree::WalkStats sum;
        std::uint64_t used = 0;
        for (const Query& q : queries) {
            const double bound = std::min(q.params.error_bound, cache.reach(q.depth));  // as lookups clamp it
            sum += cache.octree(q.depth).walk_stats(q.p, bound);
            used += static_cast<std::uint64_t>(cache.lookup(q.p, q.n, q.depth, q.params).records);
        }
        const double n = static_cast<double>(queries.size());
        std::printf("per lookup: nodes walked %.2f (%.2f above the first with entries), nodes with entries %.2f, "
                    "entries scanned %.1f, candidates %.2f, within the bound %.2f, records used %.2f\n",
                    static_cast<double>(sum.nodes) / n, static_cast<double>(sum.nodes_before_entries) / n,
                    static_cast<double>(sum.nodes_with_entries) / n, static_cast<double>(sum.entries_scanned) / n,
                    static_cast<double>(sum.candidates) / n, static_cast<double>(sum.within) / n,
                    static_cast<double>(used) / n);
    }
    const cache::CacheStatistics stats = cache.statistics();
    std::printf("records %llu queries %zu load %.3f s lookup %.1f ns (best of %d) checksum %016llx\n",
                static_cast<unsigned long long>(stats.total_records), queries.size(), load_seconds,
                1e9 * best / static_cast<double>(queries.size()), rounds, static_cast<unsigned long long>(checksum));
    return 0;
}
