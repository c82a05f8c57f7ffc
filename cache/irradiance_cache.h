// IrradianceCache: one record octree per bounce depth, filled in passes by tiles and merged in tile order.
#pragma once

#include <array>
#include <functional>
#include <cstdint>
#include <iosfwd>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "cache/ambient_grid.h"
#include "cache/interpolation.h"
#include "cache/irradiance_record.h"
#include "cache/octree.h"
#include "scene/scene.h"

namespace wardray::cache {

/// Counts for --stats; identical for any thread count because tiles count and are summed in tile order.
struct CacheStatistics {
    /// records[pass][depth]: records made in each pass, by bounce depth (loaded records count in pass 0).
    std::vector<std::vector<std::uint64_t>> records;
    std::uint64_t lookups = 0;  ///< lookups made through tiles
    std::uint64_t hits = 0;     ///< of those, lookups that found enough records (Interpolation::sufficient)
    std::uint64_t total_records = 0;
    double mean_radius = 0.0;  ///< over all records, world units
    std::uint64_t memory_bytes = 0;  ///< what the octrees and the open pass's tile views have allocated

    double hit_rate() const { return lookups > 0 ? static_cast<double>(hits) / static_cast<double>(lookups) : 0.0; }
};

/// A malformed, truncated or incompatible cache file.
class CacheFileError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class IrradianceCache;

/// One tile's view of the cache during a pass: lookups see the frozen cache plus this tile's own new records;
/// new records stay here until IrradianceCache::end_pass(). Used by one thread at a time.
class TileCache {
public:
    /// Interpolates at (p, n) for bounce `depth` from the frozen records and this tile's own, in that order.
    Interpolation lookup(const Vec3& p, const Vec3& n, int depth, const LookupParams& params);
    /// The frozen records' coarse estimate at (p, n) for bounce `depth` (IrradianceCache::ambient()).
    bool ambient(const Vec3& p, const Vec3& n, int depth, Vec3& out) const;
    /// Adds a new record (its depth selects the octree, its pass is set here; a depth outside [0, depth_count())
    /// is dropped), clamping its radius against its neighbours (Křivánek et al. 2006): against the frozen cache
    /// only the new record shrinks, against this tile's own records both may.
    void add(IrradianceRecord record);
    /// How many records this tile has made in the pass.
    std::size_t record_count() const { return m_order.size(); }
    /// This tile's records since the last merge, in the order they were made and as they stand now (radii clamped
    /// against each other), with its lookup counts: what another process needs to merge them as this one would.
    struct Contribution {
        std::vector<IrradianceRecord> records;
        std::uint64_t lookups = 0;
        std::uint64_t hits = 0;
    };
    Contribution contribution() const;
    /// Takes over a contribution made by this tile in another process (rendering across processes), replacing
    /// whatever this view holds, so that merge_tiles() then merges exactly what that process would have. The records
    /// are kept as a list, not filed: nothing looks them up before the merge.
    void adopt(Contribution contribution);

private:
    friend class IrradianceCache;
    TileCache(const IrradianceCache& cache, int pass);

    const IrradianceCache* m_cache;
    int m_pass;
    /// This tile's records by depth, filed like the cache's so that lookups stay logarithmic.
    std::vector<RecordOctree> m_own;
    /// (depth, index) of each record in the order it was made: the order end_pass() merges them in.
    std::vector<std::pair<int, std::uint32_t>> m_order;
    /// Records adopted from another process, in the order it made them (merged instead of m_order's).
    std::vector<IrradianceRecord> m_adopted;
    /// The cache's record count per depth when this tile's unmerged records were clamped against it (empty: none
    /// yet): the merge then clamps them only against the records filed since.
    std::vector<std::size_t> m_clamped_against;
    std::uint64_t m_lookups = 0;
    std::uint64_t m_hits = 0;
};

/// The irradiance cache (Ward, Rubinstein & Clear 1988) with a deterministic fill: the cache is frozen during a
/// pass, each tile collects its new records in its TileCache, and end_pass() merges them in tile order.
///
/// Use: begin_pass(tiles); every tile t (any thread, any order) calls tile(t).lookup / tile(t).add, optionally in
/// waves with merge_tiles() between them; end_pass(). Outside a pass, lookup() reads the cache from any number
/// of threads.
class IrradianceCache {
public:
    /// One depth per `recursion_limit` bounce; octrees filed for the largest error bound lookup_params() can give.
    explicit IrradianceCache(const scene::RadiositySettings& settings);
    /// `depths` octrees whose filing reach at depth d is reach × 2^d, with their smaller filings at `inner`
    /// fractions of it (RecordOctree).
    IrradianceCache(int depths, double reach, std::array<double, 2> inner = {0.5, 0.25});

    int depth_count() const { return static_cast<int>(m_octrees.size()); }
    /// The filing reach at `depth`: lookups with a larger error bound are clamped to it.
    double reach(int depth) const;
    /// An empty octree filed as the cache's at `depth`.
    RecordOctree empty_octree(int depth) const;
    /// An empty octree with the reach of the cache's at `depth` and its first filing only (a tile's own records).
    RecordOctree empty_tile_octree(int depth) const;

    /// Freezes the cache and opens `tile_count` tile views; returns the pass number (0, 1, ...).
    int begin_pass(int tile_count);
    /// The view of tile `index` in the open pass (thread-safe: each tile has its own).
    TileCache& tile(int index);
    /// Merges the records of `tiles`, in that order, into the frozen cache, where every tile then sees them; call
    /// only while no tile of the pass is being worked on. A pass done in waves of tiles, merged after each wave,
    /// shares records much sooner and stays the same for any thread count.
    void merge_tiles(const std::vector<int>& tiles);
    /// Merges the tiles' records in tile order (neighbour clamping against all earlier records) and closes the pass.
    void end_pass();
    bool in_pass() const { return m_in_pass; }
    /// Neighbour clamping (Křivánek et al. 2006) of every record added from now on (default on; off keeps each
    /// record's radius as make_record() gave it, as POV-Ray 3.7 does).
    void set_neighbour_clamp(bool on) { m_neighbour_clamp = on; }
    /// With neighbour clamping, whether a new record also shrinks the older records whose spheres hold it (both
    /// ways, the default) or only takes their bound (one way: R_new ≤ R_i + |p_new − p_i|, nothing older shrinks),
    /// for the records of the passes that follow.
    void set_shrink_older(bool on) { m_shrink_older = on; }

    /// Keeps, for each bounce depth from 1 on, two AmbientGrids of its frozen records, in cells as wide as their
    /// median radius and four times that, built afresh when a pass begins and whenever records are merged, for
    /// ambient() (--gi-lookup-sampling; off by default).
    void set_ambient_grids(bool on);
    /// The estimate at (p, n) of the frozen records of `depth` ≥ 1 from the finer grid whose cell holds p, else the
    /// coarser one; false where neither has a record or the grids are off.
    bool ambient(const Vec3& p, const Vec3& n, int depth, Vec3& out) const;

    /// Interpolates from the frozen cache (no statistics; thread-safe while no pass is merging).
    Interpolation lookup(const Vec3& p, const Vec3& n, int depth, const LookupParams& params) const;
    /// Inserts one record outside a pass, with neighbour clamping (std::logic_error inside a pass).
    void add(const IrradianceRecord& record);
    /// The records of `depth` in insertion order.
    const RecordArray& records(int depth) const;
    /// The octree of the records of bounce depth `depth` (for diagnostics, tools/bench/lookup_bench).
    const RecordOctree& octree(int depth) const { return m_octrees.at(static_cast<std::size_t>(depth)); }
    /// Keeps only the records `keep` accepts, each depth's in its order, refiled as they are (no neighbour
    /// clamping): a cache carried to the next frame of an animation without the records that frame invalidates.
    /// Returns how many were dropped. Outside a pass (std::logic_error inside one).
    std::size_t keep_records(const std::function<bool(const IrradianceRecord&)>& keep);
    /// Totals so far (lookups of the open pass are counted when it ends).
    CacheStatistics statistics() const;

    /// Writes every record, bit-exact, with a versioned header (POV-Ray's +RFO).
    void save(std::ostream& out) const;
    /// Replaces the contents with the records of a file written by save() (POV-Ray's +RFI); throws CacheFileError
    /// on a truncated, corrupt or incompatible file and then leaves the cache as it was. Records deeper than this
    /// cache's depth_count() are skipped.
    void load(std::istream& in);

private:
    friend class TileCache;
    /// Adds the frozen records valid at (p, n) to `acc`.
    void accumulate(InterpolationAccumulator& acc, const Vec3& p, int depth) const;
    /// Shrinks `record`'s radius against the frozen records of its depth (Křivánek et al. 2006).
    void clamp_new_record(IrradianceRecord& record) const;
    /// As clamp_new_record(), then shrinks the frozen records' radii against `record` too.
    void clamp_mutual(IrradianceRecord& record);
    void count_record(const IrradianceRecord& record);
    /// The record count of each depth's octree.
    std::vector<std::size_t> sizes() const;
    LookupParams clamp_params(int depth, const LookupParams& params) const;

    /// Rebuilds the ambient grids of the depths whose record count is not the one they were built from.
    void refresh_ambient();

    /// The octree of `depth`, clamped to the depths the cache has.
    const RecordOctree& nearest_depth(int depth) const;
    std::vector<RecordOctree> m_octrees;
    std::vector<std::unique_ptr<TileCache>> m_tiles;
    bool m_in_pass = false;
    bool m_neighbour_clamp = true;
    bool m_shrink_older = true;
    int m_pass = 0;
    std::vector<std::vector<std::uint64_t>> m_records_per_pass;
    std::uint64_t m_lookups = 0;
    std::uint64_t m_hits = 0;
    bool m_ambient_on = false;
    /// Per depth: the finer and the coarser AmbientGrid, and the record count they were built from.
    std::vector<std::array<AmbientGrid, 2>> m_ambient;
    std::vector<std::size_t> m_ambient_sizes;
};

}  // namespace wardray::cache
