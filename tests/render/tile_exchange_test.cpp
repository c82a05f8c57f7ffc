// TileExchange's shares of a wave among processes, against a scripted second process.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <vector>

#include "cache/irradiance_cache.h"
#include "render/tile_exchange.h"

namespace wardray::render {
namespace {

/// Rank 0 of two; rank 1 is scripted: in each exchange it reports `cost` for each tile of the wave rank 0 did not
/// take, with no records. It cannot draw from shared counters, so the shares are fixed in advance.
class ScriptedPair final : public Communicator {
public:
    int rank() const override { return 0; }
    int size() const override { return 2; }
    [[noreturn]] void abort(int) override { throw std::runtime_error("abort"); }

    std::vector<int> others;      ///< rank 1's tiles in the next exchange
    std::map<int, double> cost;   ///< their processor seconds

protected:
    std::vector<Bytes> do_allgather(const Bytes& mine) override { return {mine, message()}; }
    std::vector<Bytes> do_gather(const Bytes& mine) override { return {mine, message()}; }

private:
    Bytes message() const {
        ByteWriter out;
        out.put(0.0);  // busy seconds
        for (const int tile : others) {
            out.put(static_cast<std::int32_t>(tile));
            out.put(cost.at(tile));
            out.put(std::uint64_t{0});  // lookups
            out.put(std::uint64_t{0});  // hits
            out.put(std::uint64_t{0});  // records
        }
        return out.bytes();
    }
};

/// Rank 0's tiles of `wave`, after it reports `cost` for its own and rank 1 for the rest.
std::vector<int> render_wave(TileExchange& exchange, ScriptedPair& pair, cache::IrradianceCache& cache,
                             const std::vector<int>& wave, const std::map<int, double>& cost) {
    exchange.start_wave(wave);
    std::vector<int> mine;
    for (int tile = exchange.next_tile(); tile >= 0; tile = exchange.next_tile()) {
        mine.push_back(tile);
        exchange.tile_cost(tile, cost.at(tile));
    }
    pair.others.clear();
    for (const int tile : wave)
        if (std::find(mine.begin(), mine.end(), tile) == mine.end()) pair.others.push_back(tile);
    pair.cost = cost;
    exchange.end_wave(wave, exchange.taken(), &cache);
    exchange.merge_wave(wave, cache);
    return mine;
}

TEST(TileExchange, PredictsATilesCostFromHowItsNeighboursGrewThisPass) {
    // Five tiles in a row, all alike in the first pass; in the second, the tile at the left end became ten times
    // dearer and the one at the right end stayed as it was. Of the three between them, the leftmost is then
    // predicted dearest and the rightmost cheapest, so rank 0 takes the leftmost alone (7.75 against 5.5 + 3.25)
    // instead of the first and third, as the first pass's equal costs would have it.
    ScriptedPair pair;
    TileExchange exchange(&pair);
    cache::IrradianceCache cache(1, 1.0);
    exchange.begin(5, 3, 5);
    const std::map<int, double> alike{{0, 1.0}, {1, 1.0}, {2, 1.0}, {3, 1.0}, {4, 1.0}};
    cache.begin_pass(5);
    exchange.start_pass();
    render_wave(exchange, pair, cache, {0, 1, 2, 3, 4}, alike);
    cache.end_pass();
    cache.begin_pass(5);
    exchange.start_pass();
    std::map<int, double> grown = alike;
    grown[0] = 10.0;
    render_wave(exchange, pair, cache, {0, 4}, grown);
    EXPECT_EQ(render_wave(exchange, pair, cache, {1, 2, 3}, grown), std::vector<int>{1});
    cache.end_pass();
}

TEST(TileExchange, WithoutEarlierCostsTheSharesTakeTurns) {
    ScriptedPair pair;
    TileExchange exchange(&pair);
    cache::IrradianceCache cache(1, 1.0);
    exchange.begin(4, 1, 2);
    cache.begin_pass(4);
    exchange.start_pass();
    EXPECT_EQ(render_wave(exchange, pair, cache, {0, 1, 2, 3}, {{0, 1.0}, {1, 5.0}, {2, 1.0}, {3, 1.0}}),
              (std::vector<int>{0, 2}));
    cache.end_pass();
}

}  // namespace
}  // namespace wardray::render
