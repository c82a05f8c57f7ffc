// Tests of the record octree: lookups and neighbour clamping agree exactly with brute-force scans.
#include "cache/octree.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "cache/hemisphere_sampler.h"
#include "cache/interpolation.h"

namespace wardray::cache {
namespace {

/// Uniform in [lo, hi).
double uniform(SplitMix64& rng, double lo, double hi) { return lo + (hi - lo) * rng.uniform(); }

Vec3 random_direction(SplitMix64& rng) {
    for (;;) {
        const Vec3 v{uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1)};
        if (dot(v, v) > 1e-4 && dot(v, v) <= 1.0) return normalize(v);
    }
}

IrradianceRecord random_record(SplitMix64& rng, const Vec3& offset, double scale) {
    IrradianceRecord r;
    r.position = offset + Vec3{uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1)} * scale;
    r.normal = rng.uniform() < 0.5 ? Vec3{0, 1, 0} : random_direction(rng);
    r.irradiance = {1, 1, 1};
    r.radius = scale * std::exp(uniform(rng, std::log(1e-3), std::log(0.5)));
    return r;
}

TEST(RecordOctree, LookupFindsExactlyTheValidRecords) {
    // Several scales and offsets (including far from the origin), so the root grows in every direction.
    for (const auto& [offset, scale] : {std::pair{Vec3{0, 0, 0}, 1.0}, std::pair{Vec3{1e4, -3e3, 7}, 50.0},
                                        std::pair{Vec3{-0.3, 0.2, 0.1}, 1e-3}}) {
        SplitMix64 rng(1234);
        const double error_bound = 1.8;
        RecordOctree tree(error_bound);
        std::vector<IrradianceRecord> all;
        for (int i = 0; i < 3000; ++i) {
            all.push_back(random_record(rng, offset, scale));
            tree.insert(all.back());
        }
        int hits = 0;
        for (int qi = 0; qi < 3000; ++qi) {
            // Queries near records (where validity is likely) and anywhere in the volume.
            const Vec3 q = qi % 2 == 0
                               ? all[qi % all.size()].position + random_direction(rng) * (uniform(rng, 0, 2) *
                                                                                          all[qi % all.size()].radius)
                               : offset + Vec3{uniform(rng, -1.2, 1.2), uniform(rng, -1.2, 1.2),
                                               uniform(rng, -1.2, 1.2)} * scale;
            const Vec3 n = rng.uniform() < 0.5 ? Vec3{0, 1, 0} : random_direction(rng);
            std::vector<std::uint32_t> brute, found;
            for (std::uint32_t i = 0; i < all.size(); ++i) {
                if (is_valid(all[i], q, n, error_bound)) brute.push_back(i);
            }
            tree.visit(q, [&](std::uint32_t i) {
                if (is_valid(tree.records()[i], q, n, error_bound)) found.push_back(i);
            });
            std::vector<std::uint32_t> sorted = found;
            std::sort(sorted.begin(), sorted.end());
            EXPECT_TRUE(std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end()) << "visited twice";
            ASSERT_EQ(sorted, brute) << "query " << qi << " scale " << scale;
            hits += brute.empty() ? 0 : 1;
        }
        EXPECT_GT(hits, 1000);
    }
}

// visit_near() walks the tightest filing whose reach covers the bound: with filings chosen at the lookups' bounds
// (as the cache files them) or the default halves, it finds exactly the records within error_bound × R_i, each once.
TEST(RecordOctree, NearLookupFindsTheSameRecordsInEveryFiling) {
    const double reach = 0.75;
    for (const std::array<double, 2> inner : {std::array{0.5, 0.25}, std::array{2.0 / 3.0, 1.0 / 3.0},
                                              std::array{0.2, 0.9}, std::array{0.0, 7.0}}) {
        SplitMix64 rng(99);
        RecordOctree tree(reach, inner);
        std::vector<IrradianceRecord> all;
        for (int i = 0; i < 2000; ++i) {
            all.push_back(random_record(rng, Vec3{3, -2, 1}, 2.0));
            tree.insert(all.back());
        }
        int hits = 0;
        for (int qi = 0; qi < 2000; ++qi) {
            const IrradianceRecord& near_record = all[static_cast<std::size_t>(qi) % all.size()];
            const Vec3 q = near_record.position + random_direction(rng) * (uniform(rng, 0, 1) * near_record.radius);
            for (const double bound : {0.75, 0.5, 0.4, 0.25, 0.1, 0.05}) {
                std::vector<std::uint32_t> brute, found;
                for (std::uint32_t i = 0; i < all.size(); ++i) {
                    const Vec3 d = q - all[i].position;
                    if (dot(d, d) < bound * all[i].radius * bound * all[i].radius) brute.push_back(i);
                }
                tree.visit_near(q, bound, [&](std::uint32_t i, const RecordGeometry& g) {
                    found.push_back(i);
                    EXPECT_EQ(&g, &tree.geometry(i));
                });
                std::sort(found.begin(), found.end());
                EXPECT_TRUE(std::adjacent_find(found.begin(), found.end()) == found.end()) << "visited twice";
                ASSERT_EQ(found, brute) << "query " << qi << " bound " << bound << " inner " << inner[0];
                hits += brute.empty() ? 0 : 1;
                // The walk's diagnostics count the same records, within what was scanned and walked.
                const RecordOctree::WalkStats w = tree.walk_stats(q, bound);
                ASSERT_EQ(w.within, brute.size());
                EXPECT_GE(w.candidates, w.within);
                EXPECT_GE(w.entries_scanned, w.candidates);
                EXPECT_GE(w.nodes, w.nodes_with_entries + w.nodes_before_entries);
                if (!brute.empty()) {
                    EXPECT_GT(w.nodes_with_entries, 0u);
                }
            }
        }
        EXPECT_GT(hits, 3000);
        EXPECT_EQ(tree.empty_like().reach(), tree.reach());
    }
}

TEST(RecordOctree, OneFilingFindsWhatThreeFind) {
    // A tile's own octree files each record once (empty_single_filing): every query must still find the same
    // records, the same holding records and the same clamped radius as the cache's three filings, radii shrunk
    // after filing included.
    SplitMix64 rng(7);
    RecordOctree full(1.3, {0.4, 0.2});
    RecordOctree one = full.empty_single_filing();
    ASSERT_EQ(full.filing_count(), 3u);
    ASSERT_EQ(one.filing_count(), 1u);
    EXPECT_EQ(one.empty_like().filing_count(), 1u);
    EXPECT_EQ(full.empty_like().filing_count(), 3u);
    EXPECT_EQ(one.reach(), full.reach());
    for (int i = 0; i < 600; ++i) {
        const IrradianceRecord r = random_record(rng, Vec3{-1, 4, 2}, 3.0);
        ASSERT_EQ(full.insert(r), one.insert(r));
        if (i % 5 == 0) {
            const auto shrink = static_cast<std::uint32_t>(rng.uniform() * i);
            const double radius = full.geometry(shrink).radius * 0.5;
            full.shrink_radius(shrink, radius);
            one.shrink_radius(shrink, radius);
        }
    }
    const auto collect_near = [](const RecordOctree& tree, const Vec3& q, double bound) {
        std::vector<std::uint32_t> found;
        tree.visit_near(q, bound, [&](std::uint32_t i, const RecordGeometry&) { found.push_back(i); });
        std::sort(found.begin(), found.end());
        return found;
    };
    int hits = 0;
    for (int qi = 0; qi < 1500; ++qi) {
        const IrradianceRecord& near_record = one.records()[static_cast<std::size_t>(qi) % one.size()];
        const Vec3 q = near_record.position + random_direction(rng) * (uniform(rng, 0, 1.5) * near_record.radius);
        for (const double bound : {1.3, 0.5, 0.26, 0.1}) {
            const std::vector<std::uint32_t> found = collect_near(one, q, bound);
            ASSERT_EQ(found, collect_near(full, q, bound)) << "query " << qi << " bound " << bound;
            hits += found.empty() ? 0 : 1;
        }
        // Neighbour clamping's queries: visit_holding() may pass a few more than it must, so compare what it must
        // find (|q - p_i| < R_i), and clamped_radius() exactly.
        const auto holding = [&](const RecordOctree& tree) {
            std::vector<std::uint32_t> found;
            tree.visit_holding(q, [&](std::uint32_t i) {
                const Vec3 d = q - tree.geometry(i).position;
                if (dot(d, d) < tree.geometry(i).radius * tree.geometry(i).radius) found.push_back(i);
            });
            std::sort(found.begin(), found.end());
            return found;
        };
        ASSERT_EQ(holding(one), holding(full)) << "query " << qi;
        EXPECT_EQ(one.clamped_radius(q, 2.0), full.clamped_radius(q, 2.0)) << "query " << qi;
    }
    EXPECT_GT(hits, 2000);
}

// The scan's fixed point is relative to each node's cube, so visit_near() stays exact at any scale and offset.
TEST(RecordOctree, NearLookupIsExactAtEveryScale) {
    for (const auto& [offset, scale] : {std::pair{Vec3{0, 0, 0}, 1e-9}, std::pair{Vec3{1e6, -3e5, 7}, 1e3},
                                        std::pair{Vec3{-0.3, 0.2, 0.1}, 1e-3}, std::pair{Vec3{5, 5, 5}, 1e8}}) {
        SplitMix64 rng(31);
        RecordOctree tree(1.5, {0.5, 0.2});
        std::vector<IrradianceRecord> all;
        for (int i = 0; i < 1500; ++i) {
            all.push_back(random_record(rng, offset, scale));
            tree.insert(all.back());
        }
        int hits = 0;
        for (int qi = 0; qi < 1000; ++qi) {
            const IrradianceRecord& near_record = all[static_cast<std::size_t>(qi) % all.size()];
            const Vec3 q = near_record.position + random_direction(rng) * (uniform(rng, 0, 1.6) * near_record.radius);
            for (const double bound : {1.5, 1.0, 0.75, 0.3, 0.2, 0.01}) {
                std::vector<std::uint32_t> brute, found;
                for (std::uint32_t i = 0; i < all.size(); ++i) {
                    const Vec3 d = q - all[i].position;
                    if (dot(d, d) < bound * all[i].radius * (bound * all[i].radius)) brute.push_back(i);
                }
                tree.visit_near(q, bound, [&](std::uint32_t i, const RecordGeometry&) { found.push_back(i); });
                std::sort(found.begin(), found.end());
                ASSERT_EQ(found, brute) << "query " << qi << " bound " << bound << " scale " << scale;
                hits += brute.empty() ? 0 : 1;
            }
        }
        EXPECT_GT(hits, 2000);
    }
}

// The packed geometry lookups test follows the records, through shrunk radii too, and visit_near() then finds
// exactly the records within the shrunk spheres.
TEST(RecordOctree, PackedGeometryFollowsShrunkRadii) {
    SplitMix64 rng(7);
    RecordOctree tree(1.0);
    std::vector<IrradianceRecord> all;
    for (int i = 0; i < 1000; ++i) {
        all.push_back(random_record(rng, {0, 0, 0}, 1.0));
        tree.insert(all.back());
    }
    for (std::uint32_t i = 0; i < all.size(); i += 3) {
        tree.shrink_radius(i, all[i].radius * 0.5);
        tree.shrink_radius(i, all[i].radius * 2.0);  // never grows
        all[i].radius *= 0.5;
    }
    for (std::uint32_t i = 0; i < all.size(); ++i) {
        const RecordGeometry& g = tree.geometry(i);
        ASSERT_EQ(g.radius, all[i].radius);
        ASSERT_EQ(tree.records()[i].radius, all[i].radius);
        ASSERT_EQ(g.position, all[i].position);
        ASSERT_EQ(g.normal, all[i].normal);
    }
    for (int qi = 0; qi < 500; ++qi) {
        const Vec3 q{uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1)};
        std::vector<std::uint32_t> brute, found;
        for (std::uint32_t i = 0; i < all.size(); ++i) {
            const Vec3 d = q - all[i].position;
            if (dot(d, d) < 0.9 * all[i].radius * (0.9 * all[i].radius)) brute.push_back(i);
        }
        tree.visit_near(q, 0.9, [&](std::uint32_t i, const RecordGeometry&) { found.push_back(i); });
        std::sort(found.begin(), found.end());
        ASSERT_EQ(found, brute) << "query " << qi;
    }
}

// The AVX2 scan (where the CPU has it) and the portable one let through the same entries in the same order, so
// lookups find the same records in the same order, and holding visits the same records, whichever runs.
TEST(RecordOctree, WideAndPortableScansFindTheSameRecordsInTheSameOrder) {
    SplitMix64 rng(2024);
    RecordOctree tree(1.2, {0.6, 0.3});
    std::vector<IrradianceRecord> all;
    // Nodes of every length: odd and even block counts, and runs longer than one scan.
    for (int i = 0; i < 4000; ++i) {
        all.push_back(random_record(rng, Vec3{-5, 2, 9}, 3.0));
        tree.insert(all.back());
    }
    const bool wide = RecordOctree::use_wide_scan(true);
    int hits = 0;
    for (int qi = 0; qi < 1500; ++qi) {
        const IrradianceRecord& near_record = all[static_cast<std::size_t>(qi * 7) % all.size()];
        const Vec3 q = near_record.position + random_direction(rng) * (uniform(rng, 0, 1.3) * near_record.radius);
        for (const double bound : {1.2, 0.6, 0.45, 0.3, 0.1}) {
            std::vector<std::uint32_t> in_order[2], holding[2];
            for (const bool use : {false, true}) {
                RecordOctree::use_wide_scan(use);
                tree.visit_near(q, bound, [&](std::uint32_t i, const RecordGeometry&) { in_order[use].push_back(i); });
                tree.visit_holding(q, [&](std::uint32_t i) { holding[use].push_back(i); });
            }
            ASSERT_EQ(in_order[0], in_order[1]) << "query " << qi << " bound " << bound;
            ASSERT_EQ(holding[0], holding[1]) << "query " << qi;
            std::vector<std::uint32_t> brute;
            for (std::uint32_t i = 0; i < all.size(); ++i) {
                const Vec3 d = q - all[i].position;
                if (dot(d, d) < bound * all[i].radius * (bound * all[i].radius)) brute.push_back(i);
            }
            std::sort(in_order[1].begin(), in_order[1].end());
            ASSERT_EQ(in_order[1], brute) << "query " << qi << " bound " << bound;
            hits += brute.empty() ? 0 : 1;
        }
    }
    EXPECT_GT(hits, 3000);
    // Turning it back on gives the wide scan again exactly when the CPU has it.
    EXPECT_EQ(RecordOctree::use_wide_scan(true), wide);
}

// Up to a few dozen records visit_near() tests each in turn instead of walking: it finds exactly the records a walk
// finds, in insertion order, and never the degenerate ones the filings leave out (non-finite position, radius zero,
// negative or infinite), however many records the tree holds as it grows past the threshold.
TEST(RecordOctree, SmallTreesFindWhatTheWalkFinds) {
    SplitMix64 rng(5);
    RecordOctree tree(1.0);
    std::vector<IrradianceRecord> all;
    const double inf = std::numeric_limits<double>::infinity();
    int hits = 0;
    for (int i = 0; i < 80; ++i) {
        IrradianceRecord r = random_record(rng, {1, 1, 1}, 1.0);
        if (i % 9 == 4) r.position = {std::nan(""), 1, 1};
        if (i % 9 == 5) r.radius = 0.0;
        if (i % 9 == 6) r.radius = -0.3;
        if (i % 9 == 7) r.radius = inf;
        if (i % 9 == 8) r.position = {1, inf, 1};
        all.push_back(r);
        tree.insert(r);
        for (int qi = 0; qi < 40; ++qi) {
            const IrradianceRecord& near_record = all[rng.next() % all.size()];
            const bool usable = is_finite(near_record.position) && near_record.radius > 0.0 && near_record.radius < inf;
            const double offset = uniform(rng, 0, 1.2) * near_record.radius;
            const Vec3 q = usable ? near_record.position + random_direction(rng) * offset
                                  : Vec3{uniform(rng, 0, 2), uniform(rng, 0, 2), uniform(rng, 0, 2)};
            for (const double bound : {1.0, 0.5, 0.2}) {
                std::vector<std::uint32_t> brute, found;
                for (std::uint32_t k = 0; k < all.size(); ++k) {
                    const Vec3 d = q - all[k].position;
                    const bool filed = is_finite(all[k].position) && all[k].radius > 0.0 && all[k].radius < inf;
                    if (filed && dot(d, d) < bound * all[k].radius * (bound * all[k].radius)) brute.push_back(k);
                }
                tree.visit_near(q, bound, [&](std::uint32_t k, const RecordGeometry&) { found.push_back(k); });
                if (all.size() <= 32) {
                    ASSERT_EQ(found, brute) << "records " << all.size() << " query " << qi;  // in insertion order
                } else {
                    std::sort(found.begin(), found.end());
                    ASSERT_EQ(found, brute) << "records " << all.size() << " query " << qi;
                }
                hits += brute.empty() ? 0 : 1;
            }
        }
    }
    EXPECT_GT(hits, 2000);
}

TEST(RecordOctree, ClampedRadiusMatchesBruteForce) {
    SplitMix64 rng(99);
    RecordOctree tree(2.0);
    std::vector<IrradianceRecord> all;
    for (int i = 0; i < 2000; ++i) {
        all.push_back(random_record(rng, {3, 3, 3}, 2.0));
        tree.insert(all.back());
    }
    int clamped = 0;
    for (int qi = 0; qi < 500; ++qi) {
        IrradianceRecord q;
        q.position = Vec3{3, 3, 3} + Vec3{uniform(rng, -2, 2), uniform(rng, -2, 2), uniform(rng, -2, 2)};
        q.radius = uniform(rng, 0.0, 0.8);
        // Every record in turn, as neighbour clamping one way reads.
        double brute = q.radius;
        for (const IrradianceRecord& r : all) brute = std::min(brute, clamped_radius(q, r));
        ASSERT_EQ(tree.clamped_radius(q.position, q.radius), brute) << "query " << qi;
        clamped += brute < q.radius ? 1 : 0;
    }
    EXPECT_GT(clamped, 10);
}

// visit_holding() (what neighbour clamping shrinks) finds every record whose sphere R_i holds the point, once, even
// after radii shrank below what was filed, and far fewer than visit()'s whole path.
TEST(RecordOctree, HoldingVisitFindsEveryRecordWhoseSphereHoldsThePoint) {
    for (const auto& [offset, scale] : {std::pair{Vec3{0, 0, 0}, 1.0}, std::pair{Vec3{1e4, -3e3, 7}, 50.0},
                                        std::pair{Vec3{-0.3, 0.2, 0.1}, 1e-3}}) {
        for (const double reach : {1.0, 1.8}) {
            SplitMix64 rng(7);
            RecordOctree tree(reach, {0.6, 0.3});
            for (int i = 0; i < 2000; ++i) tree.insert(random_record(rng, offset, scale));
            for (std::uint32_t i = 0; i < tree.size(); i += 3) tree.shrink_radius(i, 0.5 * tree.records()[i].radius);
            std::size_t held = 0, holding_visits = 0, path_visits = 0;
            for (int qi = 0; qi < 2000; ++qi) {
                const IrradianceRecord& near = tree.records()[static_cast<std::size_t>(qi) % tree.size()];
                const Vec3 q = qi % 2 == 0 ? near.position + random_direction(rng) * (uniform(rng, 0, 1.2) * near.radius)
                                           : offset + Vec3{uniform(rng, -1, 1), uniform(rng, -1, 1),
                                                           uniform(rng, -1, 1)} * scale;
                std::vector<std::uint32_t> brute, found;
                for (std::uint32_t i = 0; i < tree.size(); ++i)
                    if (length(q - tree.records()[i].position) < tree.records()[i].radius) brute.push_back(i);
                tree.visit_holding(q, [&](std::uint32_t i) { found.push_back(i); });
                tree.visit(q, [&](std::uint32_t) { ++path_visits; });
                std::sort(found.begin(), found.end());
                EXPECT_TRUE(std::adjacent_find(found.begin(), found.end()) == found.end()) << "visited twice";
                EXPECT_TRUE(std::includes(found.begin(), found.end(), brute.begin(), brute.end()))
                    << "query " << qi << " scale " << scale << " reach " << reach;
                held += brute.size();
                holding_visits += found.size();
            }
            EXPECT_GT(held, 1000u);
            EXPECT_LT(holding_visits, path_visits / 2);
        }
    }
}

TEST(RecordOctree, DegenerateRecordsAreKeptButNeverFound) {
    RecordOctree tree(1.8);
    IrradianceRecord bad;
    bad.position = {std::nan(""), 0, 0};
    bad.radius = 1.0;
    tree.insert(bad);
    IrradianceRecord zero;
    zero.radius = 0.0;
    tree.insert(zero);
    int visited = 0;
    tree.visit({0, 0, 0}, [&](std::uint32_t) { ++visited; });
    EXPECT_EQ(visited, 0);
    EXPECT_EQ(tree.size(), 2u);
}

}  // namespace
}  // namespace wardray::cache
