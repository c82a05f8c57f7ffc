// RecordOctree: irradiance records filed by their validity sphere, with Ward's root-to-leaf multi-resolution lookup.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <deque>
#include <memory>
#include <vector>

#include "cache/chunked_array.h"
#include "cache/irradiance_record.h"
#include "cache/record_store.h"
#include "cache/run_pool.h"
#include "core/vec3.h"

namespace wardray::cache {

/// Records in insertion order (each read whole as a value).
using RecordArray = RecordStore;

/// Records of one bounce depth, each filed by the sphere of radius reach × R_i around its position
/// (Ward, Rubinstein & Clear 1988, section "the octree"). A record goes into every node of the level whose cells
/// are at least as wide as its sphere's diameter (in the first filing: its radius) and that its sphere's box overlaps
/// (at most 8; 27), so a lookup only walks from the root to the leaf holding the query point and tests each record it
/// meets at most once.
/// The records are filed three times, at reach and at two smaller fractions of it (by default 1/2 and 1/4; the cache
/// chooses the error bounds its lookups use), so that a lookup walks a filing whose spheres are not much larger than
/// its validity spheres: the candidates a node holds grow with the cube of that ratio.
/// Not thread-safe for writing; any number of concurrent readers while nobody writes.
class RecordOctree {
public:
    /// `reach` ≥ the largest error bound lookups will use: validity implies |p − p_i| < error_bound × R_i.
    /// Values below 1 are raised to 1 (neighbour clamping needs the R_i sphere). `inner` are the other two filings'
    /// reaches as fractions of it, each in (0, 1] (others are replaced by the defaults).
    explicit RecordOctree(double reach = 1.0, std::array<double, 2> inner = {0.5, 0.25});
    /// An empty octree filed as this one.
    RecordOctree empty_like() const { return RecordOctree(reach(), m_inner, m_filings.size()); }
    /// An empty octree with this one's reach and only its first filing: for a few records (a tile's own), where
    /// the inner filings would cost more to file than they save in the walk. Lookups find the same records in the
    /// same order either way; only the nodes walked differ.
    RecordOctree empty_single_filing() const { return RecordOctree(reach(), m_inner, 1); }

    /// Files a copy of `record` and returns its index (indices follow insertion order). A record with a
    /// non-finite position or radius is kept but never found.
    std::uint32_t insert(const IrradianceRecord& record);
    /// Every record in insertion order.
    const RecordArray& records() const { return m_records; }
    /// The position, normal and radius of record `index`, packed (what lookups test before reading the record).
    const RecordGeometry& geometry(std::uint32_t index) const { return m_records.geometry(index); }
    /// The irradiance, gradients, depth and pass of record `index` (what a lookup reads of the records it uses).
    const RecordValues& values(std::uint32_t index) const { return m_records.values(index); }
    /// Neighbour clamping: record `index`'s radius becomes `radius` when that is smaller (the filing stays
    /// conservative).
    void shrink_radius(std::uint32_t index, double radius) {
        if (radius < m_records.geometry(index).radius) m_records.set_radius(index, radius);
    }
    std::size_t size() const { return m_records.size(); }
    /// The bytes this octree has allocated (records, packed geometry, nodes, entries and homes, by capacity; not the
    /// allocator's own overhead): what --stats reports as the cache's memory.
    std::size_t memory_bytes() const;
    double reach() const { return m_filings.front().reach; }
    /// How many filings records go into: 3, or 1 for empty_single_filing()'s octrees.
    std::size_t filing_count() const { return m_filings.size(); }

    /// Calls `visit(index)` for each record whose filed sphere may contain `q` (a superset of the records valid at q
    /// for any error bound ≤ reach), walking from the root to the leaf that holds q; deterministic order.
    template <typename Visit>
    void visit(const Vec3& q, Visit&& visit) const {
        walk(m_filings.front(), q, [&](const Node& n, const Cube&) {
            for (std::uint32_t i = 0; i < n.block_count; ++i)
                for (const std::uint32_t index : n.blocks[i].index)
                    if (index != kNoRecord) visit(index);
        });
    }
    /// Calls `visit(index, geometry(index))` for the records with |q − position| < error_bound × radius, from the
    /// tightest filing that holds them all; deterministic order, but not visit()'s. Found by a branch-free scan of
    /// each node's packed positions and radii (floats, four at a time, the test widened by their rounding), then
    /// the exact test on the record's packed geometry (one cache line; the record itself is not read).
    template <typename Visit>
    void visit_near(const Vec3& q, double error_bound, Visit&& visit) const {
        visit_near_counted<false>(q, error_bound, visit, nullptr);
    }
    /// What visit_near() at q walks and scans (a diagnostic for tools/bench/lookup_bench; lookups do not count).
    struct WalkStats {
        std::uint64_t nodes = 0;                 ///< nodes walked, root to leaf
        std::uint64_t nodes_before_entries = 0;  ///< of those, above the first that holds any entry
        std::uint64_t nodes_with_entries = 0;
        std::uint64_t entries_scanned = 0;  ///< lanes of the blocks scanned, unused ones included
        std::uint64_t candidates = 0;       ///< entries the float scan lets through
        std::uint64_t within = 0;           ///< of those, within error_bound × R_i (the records visited)
        WalkStats& operator+=(const WalkStats& o) {
            nodes += o.nodes;
            nodes_before_entries += o.nodes_before_entries;
            nodes_with_entries += o.nodes_with_entries;
            entries_scanned += o.entries_scanned;
            candidates += o.candidates;
            within += o.within;
            return *this;
        }
    };
    WalkStats walk_stats(const Vec3& q, double error_bound) const {
        WalkStats stats;
        visit_near_counted<true>(q, error_bound, [](std::uint32_t, const RecordGeometry&) {}, &stats);
        return stats;
    }
    /// Calls `visit(index)` for every record whose sphere of radius R_i holds q (|q − p_i| < R_i, what neighbour
    /// clamping of a new record at q can shrink), and for a few more: the records that pass visit_near()'s float
    /// scan, without its exact test (its float slack is far wider than a double's rounding), each at most once.
    template <typename Visit>
    void visit_holding(const Vec3& q, Visit&& visit) const {
        const Filing* filing = &m_filings.front();
        for (const Filing& f : m_filings)
            if (f.reach >= 1.0 && f.reach < filing->reach) filing = &f;
        std::uint32_t near[kScanBlocks * kBlock];
        walk(*filing, q, [&](const Node& n, const Cube& cube) {
            for (std::size_t begin = 0; begin < n.block_count; begin += kScanBlocks) {
                const std::size_t found = scan_near(n, cube, q, 1.0, filing->reach, begin, near);
                for (std::size_t i = 0; i < found; ++i) visit(near[i]);
            }
        });
    }
    /// The smallest R_i + |p_i − centre| over the records, or `bound` when none is smaller: the radius neighbour
    /// clamping (Křivánek et al. 2006) leaves to a new record at `centre` whose radius is `bound`. Only records
    /// closer than the bound found so far can lower it, so the walk skips every node farther away.
    double clamped_radius(const Vec3& centre, double bound) const;

private:
    /// The first `filings` of the filings the public constructor makes (1 or 3).
    RecordOctree(double reach, std::array<double, 2> inner, std::size_t filings);

    /// Entries per Node::Block: one SSE register of floats.
    static constexpr std::size_t kBlock = 4;
    /// The index of an unused lane.
    static constexpr std::uint32_t kNoRecord = 0xFFFFFFFFu;
    /// A node's cube [min, min + size), size a power of two. Not stored in the node: the root's is the filing's,
    /// and each child's is derived from its parent's on the way down, as child() once made it.
    struct Cube {
        Vec3 min;
        double size = 0.0;
        /// The octant of the cube that holds p, one bit per axis.
        /// (Axis by axis by name: Vec3's operator[] selects through branches in the walk's inner loop.)
        int octant_of(const Vec3& p) const {
            const double half = 0.5 * size;
            return static_cast<int>(p.x >= min.x + half) | static_cast<int>(p.y >= min.y + half) << 1 |
                   static_cast<int>(p.z >= min.z + half) << 2;
        }
        Cube child(int octant) const {
            const double half = 0.5 * size;
            const auto step = [&](int axis) { return half * static_cast<double>((octant >> axis) & 1); };
            return {{min.x + step(0), min.y + step(1), min.z + step(2)}, half};
        }
    };
    /// 24 bytes: the children are in a group of the filing's (most nodes are leaves and need none), and the blocks
    /// in one run of the filing's pool of exactly the blocks used (a few more in long lists).
    struct Node {
        /// The records filed here in insertion order, four to a block, each field side by side for the scan (one
        /// run per node, read in order): position relative to the cube's min in units of its size, which lies in
        /// [-1, 2] (the filed sphere overlaps the cube and its radius is at most the cube's size), as 16-bit fixed
        /// point (kPositionScale steps a unit, rounded to nearest); the filed sphere's radius reach × R_i at filing
        /// in units of the size, in (0, 1], as 16-bit fixed point rounded up; and the index. 12 bytes an entry,
        /// against 40 in doubles. The last block's unused lanes have index kNoRecord, radius 0 and a position no
        /// query is near.
        struct alignas(16) Block {
            std::uint16_t x[kBlock], y[kBlock], z[kBlock];
            std::uint16_t radius[kBlock];
            std::uint32_t index[kBlock];
        };
        Block* blocks = nullptr;  ///< a run of block_capacity(block_count) in the filing's pool
        std::uint32_t block_count = 0;
        /// The index of this node's group of eight children in the filing's `children`; -1 for none.
        std::int32_t children = -1;
        /// Of those, the indices of the records whose position lies in this node's cube (each record has one such
        /// home node in the first filing), so that range queries test each record once. (Kept in the filing's
        /// home_lists, since only the first filing has them: `home_list` indexes it, -1 for none.)
        std::int32_t home_list = -1;
        /// How many homes this node and the nodes below it hold (first filing): clamping skips empty subtrees.
        std::uint32_t subtree_homes = 0;
    };
    static_assert(sizeof(Node) == 24 || sizeof(void*) != 8, "a node has grown");
    /// The blocks allocated for a node of `count` blocks: all of them up to 8, then up to a quarter more, so that
    /// growing a long list copies it only now and then.
    static std::uint32_t block_capacity(std::uint32_t count) {
        if (count <= 8) return count;
        const std::uint32_t step = (std::uint32_t{1} << (31 - __builtin_clz(count))) / 4;
        return (count + step - 1) / step * step;
    }
    /// A node's eight children (-1: none).
    using Children = std::array<std::int32_t, 8>;
    /// The nodes of one filing of every record, by spheres of radius reach × R_i.
    struct Filing {
        double reach = 1.0;
        ChunkedArray<Node> nodes;  ///< in chunks: no copy of every node and no doubled capacity as it grows
        ChunkedArray<Children> children;  ///< the children of the nodes that have any
        RunPool<Node::Block> blocks;      ///< the nodes' blocks
        std::deque<std::vector<std::uint32_t>> home_lists;
        std::int32_t root = -1;
        Cube root_cube;
    };

    /// Calls `at(node, cube)` for every node from `f`'s root down to the leaf that holds q (Ward, Rubinstein &
    /// Clear 1988's multi-resolution lookup).
    template <typename At>
    static void walk(const Filing& f, const Vec3& q, At&& at) {
        if (f.root < 0 || !is_finite(q)) return;
        Cube cube = f.root_cube;
        for (int a = 0; a < 3; ++a) {
            if (q[a] < cube.min[a] || q[a] >= cube.min[a] + cube.size) return;
        }
        std::int32_t node = f.root;
        while (node >= 0) {
            const Node& n = f.nodes[static_cast<std::size_t>(node)];
            const int octant = cube.octant_of(q);
            const std::int32_t next = n.children < 0 ? -1
                                                     : f.children[static_cast<std::size_t>(n.children)]
                                                                 [static_cast<std::size_t>(octant)];
            // The next node is fetched while this one is scanned (a walk is a chain of dependent loads).
            if (next >= 0) __builtin_prefetch(&f.nodes[static_cast<std::size_t>(next)]);
            at(n, cube);
            cube = cube.child(octant);
            node = next;
        }
    }

    /// visit_near(), counting into `stats` when kCount.
    template <bool kCount, typename Visit>
    void visit_near_counted(const Vec3& q, double error_bound, Visit&& visit, WalkStats* stats) const {
        if (m_records.size() <= kLinearRecords) {
            // A few records (a tile's own, the cache's first): each tested in turn, in insertion order, cheaper
            // than a walk. The records the filings left out (not finite, no positive radius) are left out here too.
            if constexpr (kCount) {
                ++stats->nodes;
                ++stats->nodes_with_entries;
                stats->entries_scanned += m_records.size();
            }
            if (!is_finite(q)) return;
            for (std::uint32_t i = 0; i < m_records.size(); ++i) {
                const RecordGeometry& g = m_records.geometry(i);
                const Vec3 d = q - g.position;
                const double reach = error_bound * g.radius;
                if (dot(d, d) < reach * reach && g.radius > 0.0 && std::isfinite(this->reach() * g.radius) &&
                    is_finite(g.position)) {
                    if constexpr (kCount) {
                        ++stats->candidates;
                        ++stats->within;
                    }
                    visit(i, g);
                }
            }
            return;
        }
        const Filing* filing = &m_filings.front();
        for (const Filing& f : m_filings)
            if (f.reach >= error_bound && f.reach < filing->reach) filing = &f;
        std::uint32_t near[kScanBlocks * kBlock];
        walk(*filing, q, [&](const Node& n, const Cube& cube) {
            if constexpr (kCount) {
                ++stats->nodes;
                if (n.block_count > 0) ++stats->nodes_with_entries;
                if (stats->nodes_with_entries == 0) ++stats->nodes_before_entries;
                stats->entries_scanned += kBlock * n.block_count;
            }
            for (std::size_t begin = 0; begin < n.block_count; begin += kScanBlocks) {
                const std::size_t found = scan_near(n, cube, q, error_bound, filing->reach, begin, near);
                if constexpr (kCount) stats->candidates += found;
                // The candidates' geometry is fetched together, not one miss after another.
                for (std::size_t i = 0; i < found; ++i) __builtin_prefetch(&m_records.geometry(near[i]));
                for (std::size_t i = 0; i < found; ++i) {
                    const RecordGeometry& g = m_records.geometry(near[i]);
                    const Vec3 d = q - g.position;
                    const double reach = error_bound * g.radius;
                    if (dot(d, d) < reach * reach) {
                        if constexpr (kCount) ++stats->within;
                        visit(near[i], g);
                    }
                }
            }
        });
    }
    /// Up to this many records, visit_near() tests each in turn instead of walking a filing.
    static constexpr std::size_t kLinearRecords = 32;
    /// How many blocks visit_near() tests in one scan.
    static constexpr std::size_t kScanBlocks = 16;
    /// Writes to `near` the indices of the records in blocks [begin, begin + kScanBlocks) of `n` (in a filing of
    /// `reach`) that may lie within error_bound × radius of q (a superset: the test is widened by the fixed point's
    /// and the floats' rounding); returns how many.
    static std::size_t scan_near(const Node& n, const Cube& cube, const Vec3& q, double error_bound, double reach,
                                 std::size_t begin, std::uint32_t* near);
    /// The scan of `count` blocks from `blocks` against the query (qx, qy, qz) in position steps, `bound` (steps of
    /// position per step of radius) and the slack, with AVX2: two blocks a step and the passing lanes' indices
    /// compressed by a permutation, no branch and no store per lane. The same test as the portable scan, operation
    /// for operation (no fused multiply-add), so both find the same candidates in the same order.
    static std::size_t scan_blocks_avx2(const Node::Block* blocks, std::size_t count, const float (&query)[5],
                                        std::uint32_t* near);

public:
    /// Whether lookups scan with AVX2 (chosen once from the CPU; tests and benchmarks may turn it off to check and
    /// time the portable scan, which then runs everywhere). Returns whether the wide scan is now used.
    static bool use_wide_scan(bool wanted);

private:
    static void insert_into(Filing& f, const IrradianceRecord& record, std::uint32_t index, bool homes);
    static void grow_to_fit(Filing& f, const Vec3& lo, const Vec3& hi);
    static std::int32_t child(Filing& f, std::int32_t node, int octant);
    static void file(Filing& f, const IrradianceRecord& record, std::uint32_t index, bool homes, std::int32_t node,
                     const Cube& cube, const Vec3& lo, const Vec3& hi, double target_size);
    void clamp_within(std::int32_t node, const Cube& cube, const Vec3& centre, double& bound) const;

    RecordArray m_records;
    std::array<double, 2> m_inner{0.5, 0.25};
    std::vector<Filing> m_filings;  ///< reach, reach × m_inner[0], reach × m_inner[1]
};

}  // namespace wardray::cache
