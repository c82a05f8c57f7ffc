// Tests of the cache: tile visibility within a pass, determinism across thread counts, statistics, save and load.
#include "cache/irradiance_cache.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>

#include "cache/gather.h"

namespace wardray::cache {
namespace {

/// A floor y=0 under a patterned ceiling y=1: an analytic scene cheap enough to render many records.
RadianceFunction ceiling_from(const Vec3& p) {
    return [p](const Vec3& d) {
        if (d.y <= 1e-9) return RadianceSample{{0.2, 0.2, 0.2}, std::numeric_limits<double>::infinity()};
        const double t = (1.0 - p.y) / d.y;
        const Vec3 q = p + d * t;
        const double s = 1.0 + 0.5 * std::sin(3.0 * q.x) * std::cos(2.0 * q.z);
        return RadianceSample{{s, 0.5 * s, 0.25 + 0.1 * q.x}, t};
    };
}

/// Renders a 64×64 grid of floor points in 8×8 tiles: two pretrace passes (every 4th, every 2nd point) and a final
/// pass; tiles run in parallel on `threads` threads.
IrradianceCache render(int threads) {
    scene::RadiositySettings settings;
    settings.recursion_limit = 1;
    IrradianceCache cache(settings);
    // Allow more threads than cores, so that four threads really run even on a small machine.
    const tbb::global_control allow(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
    constexpr int kSize = 64, kTile = 8, kTiles = (kSize / kTile) * (kSize / kTile);
    tbb::task_arena arena(threads);
    for (const int step : {4, 2, 1}) {
        const bool final_pass = step == 1;
        cache.begin_pass(kTiles);
        arena.execute([&] {
            tbb::parallel_for(0, kTiles, [&](int t) {
                TileCache& tile = cache.tile(t);
                const int tx = (t % (kSize / kTile)) * kTile, ty = (t / (kSize / kTile)) * kTile;
                for (int y = ty; y < ty + kTile; y += step) {
                    for (int x = tx; x < tx + kTile; x += step) {
                        const Vec3 p{4.0 * (x + 0.5) / kSize, 0.0, 4.0 * (y + 0.5) / kSize};
                        const Vec3 n{0, 1, 0};
                        if (tile.lookup(p, n, 0, lookup_params(settings, 0, final_pass)).sufficient) continue;
                        const GatherResult g = gather(p, n, strata_for_count(64), ceiling_from(p));
                        tile.add(make_record(p, n, g, 0, radius_limits(settings, 0, 1.5)));
                    }
                }
            });
        });
        cache.end_pass();
    }
    return cache;
}

bool bitwise_equal(const RecordArray& a, const RecordArray& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i) {
        const IrradianceRecord& x = a[i];
        const IrradianceRecord& y = b[i];
        bool same = x.position == y.position && x.normal == y.normal && x.irradiance == y.irradiance &&
                    std::memcmp(&x.radius, &y.radius, sizeof(double)) == 0 && x.depth == y.depth && x.pass == y.pass;
        for (int c = 0; c < 3; ++c) same = same && x.rotational[c] == y.rotational[c];
        for (int c = 0; c < 3; ++c) same = same && x.translational[c] == y.translational[c];
        if (!same) return false;
    }
    return true;
}

TEST(IrradianceCache, SameRecordsInTheSameOrderForAnyThreadCount) {
    const IrradianceCache one = render(1);
    const IrradianceCache four = render(4);
    const IrradianceCache four_again = render(4);
    const IrradianceCache one_again = render(1);
    ASSERT_GT(one.records(0).size(), 50u);
    EXPECT_TRUE(bitwise_equal(one.records(0), four.records(0)));
    EXPECT_TRUE(bitwise_equal(four.records(0), four_again.records(0)));
    EXPECT_TRUE(bitwise_equal(one.records(0), one_again.records(0)));
    const CacheStatistics s1 = one.statistics(), s4 = four.statistics();
    EXPECT_EQ(s1.lookups, s4.lookups);
    EXPECT_EQ(s1.hits, s4.hits);
    EXPECT_EQ(s1.records, s4.records);
    ASSERT_EQ(s1.records.size(), 3u);
    EXPECT_LT(s1.records[2][0], s1.records[0][0] + s1.records[1][0]) << "the final pass should make few records";
    std::printf("records per pass %llu %llu %llu, lookups %llu, hit rate %.3f, mean radius %.4f\n",
                static_cast<unsigned long long>(s1.records[0][0]), static_cast<unsigned long long>(s1.records[1][0]),
                static_cast<unsigned long long>(s1.records[2][0]), static_cast<unsigned long long>(s1.lookups),
                s1.hit_rate(), s1.mean_radius);
}

IrradianceRecord record_at(const Vec3& p, double radius, int depth = 0) {
    IrradianceRecord r;
    r.position = p;
    r.normal = {0, 1, 0};
    r.irradiance = {0.5, 0.25, 0.125};
    r.radius = radius;
    r.depth = depth;
    return r;
}

TEST(IrradianceCache, TilesSeeTheirOwnRecordsOnlyUntilThePassEnds) {
    IrradianceCache cache(2, 2.0);
    const LookupParams lp;
    cache.begin_pass(2);
    cache.tile(0).add(record_at({0, 0, 0}, 1.0));
    EXPECT_EQ(cache.tile(0).lookup({0.1, 0, 0}, {0, 1, 0}, 0, lp).records, 1);
    EXPECT_EQ(cache.tile(1).lookup({0.1, 0, 0}, {0, 1, 0}, 0, lp).records, 0);
    EXPECT_EQ(cache.tile(0).lookup({0.1, 0, 0}, {0, 1, 0}, 1, lp).records, 0) << "depth 0 record seen at depth 1";
    EXPECT_EQ(cache.lookup({0.1, 0, 0}, {0, 1, 0}, 0, lp).records, 0);
    cache.end_pass();
    EXPECT_EQ(cache.lookup({0.1, 0, 0}, {0, 1, 0}, 0, lp).records, 1);
    EXPECT_EQ(cache.lookup({0.1, 0, 0}, {0, 1, 0}, 1, lp).records, 0);
    const CacheStatistics s = cache.statistics();
    EXPECT_EQ(s.lookups, 3u);
    EXPECT_EQ(s.hits, 1u);
    EXPECT_EQ(s.total_records, 1u);
    EXPECT_DOUBLE_EQ(s.mean_radius, 1.0);
}

// The reported memory covers at least the records themselves, grows as records are added and stays within a few
// kilobytes a record (each is filed in at most 27 nodes of each of three filings).
TEST(IrradianceCache, MemoryGrowsWithTheRecords) {
    IrradianceCache cache(2, 1.8);
    const std::uint64_t empty = cache.statistics().memory_bytes;
    std::uint64_t before = empty;
    std::size_t added = 0;
    for (const int batch : {100, 1000, 4000}) {
        for (int i = 0; i < batch; ++i, ++added) {
            const double t = static_cast<double>(added);
            cache.add(record_at({std::fmod(t * 0.37, 10.0), std::fmod(t * 0.11, 3.0), std::fmod(t * 0.053, 7.0)},
                                0.05 + std::fmod(t * 0.007, 0.3), static_cast<int>(added % 2)));
        }
        const CacheStatistics s = cache.statistics();
        ASSERT_EQ(s.total_records, added);
        EXPECT_GT(s.memory_bytes, before) << added << " records";
        EXPECT_GE(s.memory_bytes, added * sizeof(IrradianceRecord)) << added << " records";
        // Small caches pay for their first chunks; from a thousand records on, the cost per record shows.
        if (added >= 1000) {
            EXPECT_LT(s.memory_bytes - empty, added * 8192) << added << " records";
        }
        before = s.memory_bytes;
    }
}

// A lookup sums exactly the records a brute-force scan in insertion order accepts, in that order: the result is
// bit for bit the same, at every error bound up to the reach, at depth 0 and 1 (whose filings differ).
TEST(IrradianceCache, LookupIsBitForBitABruteForceScanInInsertionOrder) {
    SplitMix64 rng(2024);
    IrradianceCache cache(2, 0.6, {0.4, 0.2});
    for (int i = 0; i < 4000; ++i) {
        IrradianceRecord r = record_at({4 * rng.uniform(), 0.2 * rng.uniform(), 4 * rng.uniform()},
                                       0.02 + 0.3 * rng.uniform(), i % 2);
        r.normal = normalize(Vec3{0.3 * rng.uniform() - 0.15, 1, 0.3 * rng.uniform() - 0.15});
        r.irradiance = {rng.uniform(), rng.uniform(), rng.uniform()};
        for (int c = 0; c < 3; ++c) r.translational[c] = {rng.uniform() - 0.5, 0, rng.uniform() - 0.5};
        cache.add(r);
    }
    int found = 0;
    for (int qi = 0; qi < 3000; ++qi) {
        const Vec3 q{4 * rng.uniform(), 0.2 * rng.uniform(), 4 * rng.uniform()};
        const Vec3 n = normalize(Vec3{0.2 * rng.uniform() - 0.1, 1, 0.2 * rng.uniform() - 0.1});
        const int depth = qi % 2;
        LookupParams params;
        params.error_bound = std::ldexp((qi % 7 + 1) * 0.6 / 7, depth);
        InterpolationAccumulator brute(q, n, params);
        for (const IrradianceRecord& r : cache.records(depth)) brute.add(r);
        const Interpolation want = brute.result(), got = cache.lookup(q, n, depth, params);
        ASSERT_EQ(got.records, want.records) << "query " << qi;
        ASSERT_EQ(std::memcmp(&got.irradiance, &want.irradiance, sizeof got.irradiance), 0) << "query " << qi;
        ASSERT_EQ(std::memcmp(&got.weight_sum, &want.weight_sum, sizeof got.weight_sum), 0) << "query " << qi;
        ASSERT_EQ(std::memcmp(&got.coverage, &want.coverage, sizeof got.coverage), 0) << "query " << qi;
        found += want.records > 1 ? 1 : 0;
    }
    EXPECT_GT(found, 200) << "too few lookups found several records to test the order";
}

TEST(IrradianceCache, NeighbourClampingAtInsertion) {
    IrradianceCache cache(1, 1.8);
    cache.add(record_at({0, 0, 0}, 4.0));
    cache.add(record_at({1, 0, 0}, 0.25));
    EXPECT_DOUBLE_EQ(cache.records(0)[0].radius, 1.25);
    cache.add(record_at({1.5, 0, 0}, 3.0));
    EXPECT_DOUBLE_EQ(cache.records(0)[2].radius, 0.75);
    // Within a pass a tile's new record shrinks against the frozen cache; the frozen record is clamped at the merge.
    cache.begin_pass(1);
    cache.tile(0).add(record_at({0, 0, -0.5}, 0.1));
    EXPECT_DOUBLE_EQ(cache.records(0)[0].radius, 1.25);
    cache.end_pass();
    EXPECT_DOUBLE_EQ(cache.records(0)[0].radius, 0.6);
}

TEST(IrradianceCache, NeighbourClampingOffKeepsEachRadius) {
    IrradianceCache cache(1, 1.8);
    cache.set_neighbour_clamp(false);
    cache.add(record_at({0, 0, 0}, 4.0));
    cache.add(record_at({1, 0, 0}, 0.25));
    cache.add(record_at({1.5, 0, 0}, 3.0));
    // Neither at insertion nor in a tile nor at the merge does a radius change.
    cache.begin_pass(1);
    cache.tile(0).add(record_at({0, 0, -0.5}, 0.1));
    cache.tile(0).add(record_at({0, 0, -0.25}, 2.0));
    cache.end_pass();
    const std::vector<double> expected{4.0, 0.25, 3.0, 0.1, 2.0};
    ASSERT_EQ(cache.records(0).size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i) EXPECT_DOUBLE_EQ(cache.records(0)[i].radius, expected[i]) << i;
}

std::string saved(const IrradianceCache& cache) {
    std::ostringstream out(std::ios::binary);
    cache.save(out);
    return out.str();
}

TEST(IrradianceCache, SaveLoadRoundTripIsBitExact) {
    const IrradianceCache original = render(2);
    const std::string bytes = saved(original);
    scene::RadiositySettings settings;
    settings.recursion_limit = 1;
    IrradianceCache loaded(settings);
    std::istringstream in(bytes, std::ios::binary);
    loaded.load(in);
    EXPECT_TRUE(bitwise_equal(original.records(0), loaded.records(0)));
    EXPECT_EQ(saved(loaded), bytes);
    // Loaded records keep the pass that made them (a pass that made none leaves no trace in the file).
    EXPECT_EQ(loaded.statistics().total_records, original.statistics().total_records);
    EXPECT_EQ(loaded.statistics().records[1], original.statistics().records[1]);
    // Lookups agree too, since the records and their order are the same.
    const LookupParams lp;
    for (const Vec3& q : {Vec3{0.3, 0, 0.7}, Vec3{2.1, 0, 3.3}}) {
        EXPECT_EQ(original.lookup(q, {0, 1, 0}, 0, lp).irradiance, loaded.lookup(q, {0, 1, 0}, 0, lp).irradiance);
    }
}

TEST(IrradianceCache, TruncatedOrGarbageFilesAreErrorsAndLeaveTheCacheAlone) {
    IrradianceCache source(1, 1.8);
    for (int i = 0; i < 5; ++i) source.add(record_at({1.0 * i, 0, 0}, 0.5));
    const std::string bytes = saved(source);
    IrradianceCache target(1, 1.8);
    target.add(record_at({9, 9, 9}, 1.0));
    for (std::size_t cut = 0; cut < bytes.size(); ++cut) {
        std::istringstream in(bytes.substr(0, cut), std::ios::binary);
        EXPECT_THROW(target.load(in), CacheFileError) << cut;
    }
    std::string flipped = bytes;
    flipped[60] = static_cast<char>(flipped[60] ^ 0x10);
    std::istringstream corrupt(flipped, std::ios::binary);
    EXPECT_THROW(target.load(corrupt), CacheFileError);
    std::istringstream garbage(std::string(300, '\x7f'), std::ios::binary);
    EXPECT_THROW(target.load(garbage), CacheFileError);
    ASSERT_EQ(target.records(0).size(), 1u);
    EXPECT_EQ(target.records(0)[0].position, (Vec3{9, 9, 9}));
    try {
        std::istringstream in(bytes.substr(0, bytes.size() - 100), std::ios::binary);
        target.load(in);
    } catch (const CacheFileError& e) {
        EXPECT_NE(std::string(e.what()).find("truncated"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace wardray::cache
