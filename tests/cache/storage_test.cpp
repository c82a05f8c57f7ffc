// Tests of the cache's storage: ChunkedArray keeps order and addresses; RunPool gives disjoint runs and reuses them.
#include "cache/chunked_array.h"
#include "cache/irradiance_record.h"
#include "cache/record_store.h"
#include "cache/run_pool.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cstring>
#include <cstdint>
#include <utility>
#include <vector>

namespace wardray::cache {
namespace {

TEST(ChunkedArray, KeepsEveryElementInOrderAndItsAddressOnceTheFirstChunkIsFull) {
    ChunkedArray<std::uint64_t, 4> a;  // chunks of 16
    std::vector<const std::uint64_t*> addresses;
    for (std::uint64_t i = 0; i < 1000; ++i) {
        a.push_back(i * 7 + 1);
        addresses.push_back(&a[i]);
    }
    ASSERT_EQ(a.size(), 1000u);
    EXPECT_GE(a.capacity(), 1000u);
    EXPECT_LT(a.capacity(), 1000u + 16u) << "at most one chunk unused";
    for (std::uint64_t i = 0; i < 1000; ++i) {
        ASSERT_EQ(a[i], i * 7 + 1);
        if (i >= 16) {
            ASSERT_EQ(&a[i], addresses[i]) << "moved as the array grew";
        }
    }
    std::uint64_t expected = 0, n = 0;
    for (const std::uint64_t v : a) {
        ASSERT_EQ(v, expected * 7 + 1);
        ++expected;
        ++n;
    }
    EXPECT_EQ(n, 1000u);
    const ChunkedArray<std::uint64_t, 4> copy = a;
    ASSERT_EQ(copy.size(), a.size());
    EXPECT_TRUE(std::equal(copy.begin(), copy.end(), a.begin()));
    // A small array stays small: its first chunk grows from 16.
    ChunkedArray<std::uint64_t> small;
    small.push_back(1);
    EXPECT_LE(small.capacity(), 16u);
}

TEST(RunPool, RunsAreDisjointAndReleasedRunsAreReusedByLength) {
    struct Item {
        std::uint64_t a, b;
    };
    RunPool<Item, 64> pool;
    // Lists grown one item at a time through the lengths 1..8, 10, 12, 14, 16, 20, ... as the octree grows its
    // nodes, each run filled with its owner's mark.
    const auto capacity = [](std::uint32_t count) -> std::uint32_t {
        if (count <= 8) return count;
        const std::uint32_t step = (std::uint32_t{1} << (31 - __builtin_clz(count))) / 4;
        return (count + step - 1) / step * step;
    };
    struct List {
        Item* run = nullptr;
        std::uint32_t count = 0;
    };
    std::vector<List> lists(50);
    std::size_t taken = 0;  // items of every run ever allocated
    for (int round = 0; round < 100; ++round) {
        for (std::size_t l = 0; l < lists.size(); ++l) {
            List& list = lists[l];
            // Lists of every length at once, some growing while others start, as nodes do.
            if (round < static_cast<int>(l) || list.count > 60) continue;
            if (list.count == capacity(list.count)) {
                Item* more = pool.allocate(capacity(list.count + 1));
                taken += capacity(list.count + 1);
                std::copy(list.run, list.run + list.count, more);
                if (list.count > 0) pool.release(list.run, list.count);
                list.run = more;
            }
            list.run[list.count++] = {l, list.count};
        }
        // Every list still holds its own items: no two runs in use overlap.
        for (std::size_t l = 0; l < lists.size(); ++l)
            for (std::uint32_t i = 0; i < lists[l].count; ++i) {
                ASSERT_EQ(lists[l].run[i].a, l) << "round " << round;
                ASSERT_EQ(lists[l].run[i].b, i + 1) << "round " << round;
            }
    }
    // The released runs were reused: less allocated than every run ever taken, though more than those held.
    std::size_t held = 0;
    for (const List& list : lists) held += capacity(list.count);
    EXPECT_GE(pool.memory_bytes(), held * sizeof(Item));
    EXPECT_LT(pool.memory_bytes(), taken * sizeof(Item) / 2);
    // A run longer than a chunk is allocated on its own and given back.
    Item* large = pool.allocate(100);
    large[99] = {1, 2};
    const std::size_t with_large = pool.memory_bytes();
    pool.release(large, 100);
    EXPECT_LT(pool.memory_bytes(), with_large);
}

TEST(RecordStore, GivesBackARecordFromMakeRecordBitForBitAndKeepsGradientsInSinglePrecision) {
    GatherResult gathered;
    gathered.irradiance = {0.3, 0.5, 0.7};
    gathered.harmonic_mean_distance = 0.8;
    gathered.nearest_distance = 0.2;
    // Values a float does not hold exactly, one beyond its range.
    gathered.rotational = {Vec3{0.1, -0.2, 0.3}, Vec3{1.0 / 3.0, 0, 1e-7}, Vec3{-0.7, 2.0 / 3.0, 1e40}};
    gathered.translational = {Vec3{0.01, 0.02, -0.03}, Vec3{0, 0.1, 0}, Vec3{-1e-3, 0, 0.9}};
    const IrradianceRecord made = make_record({1, 2, 3}, {0, 1, 0}, gathered, 1, {0.01, 10.0});
    for (int c = 0; c < 3; ++c) {
        for (int a = 0; a < 3; ++a) {
            for (const ChannelGradients* g : {&made.rotational, &made.translational})
                EXPECT_EQ((*g)[c][a], static_cast<double>(static_cast<float>((*g)[c][a]))) << c << a;
            // Rounded to nearest, not truncated or zeroed.
            EXPECT_NEAR(made.translational[c][a], gathered.translational[c][a],
                        1e-7 * std::fabs(gathered.translational[c][a]));
        }
    }
    EXPECT_EQ(made.rotational[2].z, double{FLT_MAX});

    RecordStore store;
    IrradianceRecord other = made;
    other.position = {4, 5, 6};
    other.pass = 3;
    store.push_back(made);
    store.push_back(other);
    ASSERT_EQ(store.size(), 2u);
    const IrradianceRecord back = store[0];
    EXPECT_EQ(std::memcmp(&back, &made, sizeof back), 0);
    EXPECT_EQ(store[1].position, other.position);
    EXPECT_EQ(store[1].pass, 3);
    store.set_radius(1, 0.25);
    EXPECT_EQ(store.geometry(1).radius, 0.25);
    EXPECT_EQ(store[1].radius, 0.25);
    EXPECT_EQ(store[0].radius, made.radius);
}

}  // namespace
}  // namespace wardray::cache
