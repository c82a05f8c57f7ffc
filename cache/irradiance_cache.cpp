// IrradianceCache: passes, tile views, the merge in tile order, neighbour clamping and statistics.
#include "cache/irradiance_cache.h"

#include <algorithm>
#include <cmath>

namespace wardray::cache {
namespace {

/// The largest error bound lookup_params() gives at depth 0: the final pass's or the pretrace's, plus POV-Ray's
/// widening for low-weight rays (at most 0.25).
double largest_error_bound(const scene::RadiositySettings& settings) {
    return settings.error_bound * std::max(1.0, settings.low_error_factor) + 0.25;
}

/// The smaller filings: at the final pass's and the pretrace's error bounds, where most lookups are made (rays of
/// weight 0.25 and more), as fractions of the largest bound. Only the filing walked changes; the records found and
/// their order do not.
std::array<double, 2> lookup_filings(const scene::RadiositySettings& settings) {
    const double largest = largest_error_bound(settings);
    return {settings.error_bound / largest, settings.error_bound * settings.low_error_factor / largest};
}

/// Neighbour clamping (Křivánek et al. 2006) of `tree`'s records by a new one: R_i ≤ R_new + |p_i − p_new| for those
/// whose sphere R_i holds the new point (only they can bind; each shrinks on its own, so the few more the scan finds
/// change nothing).
void shrink_holding(RecordOctree& tree, const IrradianceRecord& record) {
    tree.visit_holding(record.position,
                       [&](std::uint32_t i) { tree.shrink_radius(i, clamped_radius(tree.geometry(i), record)); });
}

/// Neighbour clamping of a new record: R_new ≤ R_i + |p_new − p_i| for the records closer than R_new, then, both
/// ways (`shrink_older`), shrink_holding().
void clamp_new(RecordOctree& tree, IrradianceRecord& record, bool shrink_older = true) {
    record.radius = tree.clamped_radius(record.position, record.radius);
    if (shrink_older) shrink_holding(tree, record);
}

/// Adds the records of `tree` valid at p to `acc` in insertion order, so that the sum does not depend on how the
/// tree files them. Validity and weights come from the octree's packed geometry; only the valid records are read.
void add_in_insertion_order(InterpolationAccumulator& acc, const RecordOctree& tree, const Vec3& p) {
    struct Valid {
        std::uint32_t index;
        RecordWeight weight;
    };
    thread_local std::vector<Valid> valid;
    valid.clear();
    tree.visit_near(p, acc.error_bound(), [&](std::uint32_t i, const RecordGeometry& g) {
        // Weighed in place: no copy of the weights through the stack.
        Valid& v = valid.emplace_back();
        v.index = i;
        if (!acc.weigh_near(g, v.weight)) {
            valid.pop_back();
            return;
        }
        // The values add_weighted() reads (irradiance and gradients) are fetched meanwhile.
        const char* values = reinterpret_cast<const char*>(&tree.values(i));
        const char* values_end = values + sizeof(RecordValues) - 1;
        for (const char* line = values; line < values_end; line += 64) __builtin_prefetch(line);
        __builtin_prefetch(values_end);
    });
    // Into insertion order. The walk visits nodes root to leaf, each node's entries in insertion order, so the list
    // is a few ascending runs of a few records: an insertion sort moves little (std::sort's set-up costs more).
    for (std::size_t i = 1; i < valid.size(); ++i) {
        const Valid v = valid[i];
        std::size_t j = i;
        for (; j > 0 && valid[j - 1].index > v.index; --j) valid[j] = valid[j - 1];
        valid[j] = v;
    }
    for (const Valid& v : valid) acc.add_weighted(tree.geometry(v.index), tree.values(v.index), v.weight);
}

/// The records one merge_tiles() call has filed so far at one depth, positions side by side for the scan: a record
/// made against the cache as the call found it was clamped against every older record when it was made
/// (TileCache::add), so only these can still lower its radius (Křivánek et al. 2006, R_new ≤ R_i + |p_new − p_i|).
/// An older record shrunk by one of these in the meantime binds no tighter than that one does (triangle inequality).
class MergedRecords {
public:
    /// Beyond this many, the octree's own scan (which prunes by the bound found so far) is cheaper.
    static constexpr std::size_t kMaxScan = 4096;

    std::size_t size() const { return m_position.size(); }
    /// Keeps record `index` of `tree` when the octree filed it (as a home, so its own clamping sees it too).
    void add(const RecordOctree& tree, std::uint32_t index) {
        const RecordGeometry& r = tree.geometry(index);
        const double s = tree.reach() * r.radius;
        if (!is_finite(r.position) || !(s > 0.0) || !std::isfinite(s)) return;
        m_position.push_back(r.position);
        m_index.push_back(index);
    }
    /// `bound` lowered to R_i + |p_i − centre| for each kept record i closer than it, with its radius as it stands
    /// in `tree`: the same value RecordOctree::clamped_radius() finds among these records.
    double clamped_radius(const RecordOctree& tree, const Vec3& centre, double bound) const {
        if (!is_finite(centre) || !(bound >= 0.0)) return bound;
        // Squared distances screen the candidates, with a margin over rounding; the test itself is the octree's.
        double screen = bound * bound * (1.0 + 0x1p-40);
        for (std::size_t k = 0; k < m_position.size(); ++k) {
            const Vec3 offset = m_position[k] - centre;
            const double d2 = dot(offset, offset);
            if (!(d2 < screen)) continue;
            const double d = std::sqrt(d2);
            if (d < bound) {
                bound = std::min(bound, tree.geometry(m_index[k]).radius + d);
                screen = bound * bound * (1.0 + 0x1p-40);
            }
        }
        return bound;
    }

private:
    std::vector<Vec3> m_position;
    std::vector<std::uint32_t> m_index;
};

}  // namespace

TileCache::TileCache(const IrradianceCache& cache, int pass) : m_cache(&cache), m_pass(pass) {
    for (int d = 0; d < cache.depth_count(); ++d) m_own.push_back(cache.empty_tile_octree(d));
}

Interpolation TileCache::lookup(const Vec3& p, const Vec3& n, int depth, const LookupParams& params) {
    const LookupParams clamped = m_cache->clamp_params(depth, params);
    InterpolationAccumulator acc(p, n, clamped);
    m_cache->accumulate(acc, p, depth);
    // Then this tile's own records of the same depth.
    if (depth >= 0 && depth < static_cast<int>(m_own.size())) {
        const RecordOctree& own = m_own[static_cast<std::size_t>(depth)];
        add_in_insertion_order(acc, own, p);
    }
    const Interpolation out = acc.result();
    ++m_lookups;
    if (out.sufficient) ++m_hits;
    return out;
}

bool TileCache::ambient(const Vec3& p, const Vec3& n, int depth, Vec3& out) const {
    return m_cache->ambient(p, n, depth, out);
}

void TileCache::add(IrradianceRecord record) {
    if (record.depth < 0 || record.depth >= m_cache->depth_count()) return;
    record.pass = m_pass;
    if (m_order.empty() && m_adopted.empty()) m_clamped_against = m_cache->sizes();
    m_cache->clamp_new_record(record);
    // Then against this tile's own records, both ways.
    RecordOctree& own = m_own[static_cast<std::size_t>(record.depth)];
    if (m_cache->m_neighbour_clamp) clamp_new(own, record, m_cache->m_shrink_older);
    m_order.emplace_back(record.depth, own.insert(record));
}

TileCache::Contribution TileCache::contribution() const {
    Contribution c;
    c.records.reserve(m_order.size());
    for (const auto& [depth, index] : m_order)
        c.records.push_back(m_own[static_cast<std::size_t>(depth)].records()[index]);
    c.lookups = m_lookups;
    c.hits = m_hits;
    return c;
}

void TileCache::adopt(Contribution contribution) {
    m_order.clear();
    // An octree nothing was filed in is already empty: making a fresh one costs a dozen allocations.
    for (RecordOctree& own : m_own)
        if (own.size() > 0) own = own.empty_like();
    // As they stand: merge_tiles() takes them in this order and clamps them against the merged cache.
    m_adopted = std::move(contribution.records);
    std::erase_if(m_adopted, [&](const IrradianceRecord& record) {
        return record.depth < 0 || record.depth >= static_cast<int>(m_own.size());
    });
    // Made against the cache as it stands now, in the process that rendered the tile.
    m_clamped_against = m_cache->sizes();
    m_lookups = contribution.lookups;
    m_hits = contribution.hits;
}

IrradianceCache::IrradianceCache(const scene::RadiositySettings& settings)
    : IrradianceCache(std::max(settings.recursion_limit, 1), largest_error_bound(settings), lookup_filings(settings)) {}

IrradianceCache::IrradianceCache(int depths, double reach, std::array<double, 2> inner) {
    const int n = std::max(depths, 1);
    for (int d = 0; d < n; ++d) m_octrees.emplace_back(std::ldexp(reach, d), inner);
}

const RecordOctree& IrradianceCache::nearest_depth(int depth) const {
    return m_octrees[static_cast<std::size_t>(std::clamp(depth, 0, depth_count() - 1))];
}

RecordOctree IrradianceCache::empty_octree(int depth) const {
    return nearest_depth(depth).empty_like();
}

RecordOctree IrradianceCache::empty_tile_octree(int depth) const {
    // A tile makes a few dozen records a pass: filing each three times cost more than the narrower walks saved (box
    // at count 80: inserts were 14 % of the profile, half of them into the tiles' own octrees).
    return nearest_depth(depth).empty_single_filing();
}

double IrradianceCache::reach(int depth) const {
    return nearest_depth(depth).reach();
}

int IrradianceCache::begin_pass(int tile_count) {
    if (m_in_pass) end_pass();
    m_tiles.clear();
    for (int i = 0; i < std::max(tile_count, 0); ++i) m_tiles.emplace_back(new TileCache(*this, m_pass));
    m_in_pass = true;
    // Records loaded, added or dropped since the last merge: the grids are built afresh.
    std::fill(m_ambient_sizes.begin(), m_ambient_sizes.end(), ~std::size_t{0});
    refresh_ambient();
    return m_pass;
}

TileCache& IrradianceCache::tile(int index) { return *m_tiles.at(static_cast<std::size_t>(index)); }

void IrradianceCache::merge_tiles(const std::vector<int>& tiles) {
    if (!m_in_pass) throw std::logic_error("IrradianceCache::merge_tiles outside a pass");
    // Every pass gets its row of statistics, even one that made no records.
    const auto rows = static_cast<std::size_t>(m_pass) + 1;
    if (m_records_per_pass.size() < rows) m_records_per_pass.resize(rows, std::vector<std::uint64_t>(m_octrees.size()));
    // A tile's records made against the cache as this call finds it need clamping only against what it files.
    const std::vector<std::size_t> found = sizes();
    std::vector<MergedRecords> merged(m_octrees.size());
    // The order given, never thread-completion order: the merged cache is the same for any thread count.
    for (const int i : tiles) {
        if (i < 0 || i >= static_cast<int>(m_tiles.size())) continue;
        TileCache& t = *m_tiles[static_cast<std::size_t>(i)];
        const bool made_against_found = t.m_clamped_against == found;
        auto merge = [&](IrradianceRecord record) {
            const auto depth = static_cast<std::size_t>(record.depth);
            RecordOctree& tree = m_octrees[depth];
            if (!m_neighbour_clamp) {
                // --gi-neighbour-clamp=off: the radius stays as make_record() gave it.
            } else if (made_against_found && merged[depth].size() <= MergedRecords::kMaxScan) {
                record.radius = merged[depth].clamped_radius(tree, record.position, record.radius);
                if (m_shrink_older) shrink_holding(tree, record);
            } else {
                clamp_new(tree, record, m_shrink_older);
            }
            merged[depth].add(tree, tree.insert(record));
            count_record(record);
        };
        for (const auto& [depth, index] : t.m_order) merge(t.m_own[static_cast<std::size_t>(depth)].records()[index]);
        for (const IrradianceRecord& record : t.m_adopted) merge(record);
        m_lookups += t.m_lookups;
        m_hits += t.m_hits;
        // The tile starts afresh: what it made is now part of the frozen cache.
        t.m_order.clear();
        t.m_adopted.clear();
        t.m_clamped_against.clear();
        for (RecordOctree& own : t.m_own)
            if (own.size() > 0) own = own.empty_like();
        t.m_lookups = 0;
        t.m_hits = 0;
    }
    refresh_ambient();
}

void IrradianceCache::set_ambient_grids(bool on) {
    m_ambient_on = on;
    m_ambient.clear();
    m_ambient_sizes.clear();
    refresh_ambient();
}

void IrradianceCache::refresh_ambient() {
    if (!m_ambient_on) return;
    // The finer grid's cells as wide as the median radius, the coarser one's four times as wide (on cornell's ladder
    // the finer grid alone covered 73 % of the gather hits, and its estimates were closer: docs/reports/speed.md).
    constexpr std::array<double, 2> kCellPerRadius = {1.0, 4.0};
    m_ambient.resize(m_octrees.size());
    m_ambient_sizes.resize(m_octrees.size(), 0);
    for (std::size_t d = 1; d < m_octrees.size(); ++d) {
        const RecordOctree& tree = m_octrees[d];
        if (tree.size() == m_ambient_sizes[d]) continue;
        m_ambient_sizes[d] = tree.size();
        std::vector<double> radii;
        radii.reserve(tree.size());
        for (std::uint32_t i = 0; i < tree.size(); ++i) {
            const double r = tree.geometry(i).radius;
            if (r > 0.0 && std::isfinite(r)) radii.push_back(r);
        }
        if (radii.empty()) {
            m_ambient[d] = {};
            continue;
        }
        const auto middle = radii.begin() + static_cast<std::ptrdiff_t>(radii.size() / 2);
        std::nth_element(radii.begin(), middle, radii.end());
        for (std::size_t g = 0; g < 2; ++g) m_ambient[d][g].build(tree, kCellPerRadius[g] * *middle);
    }
}

bool IrradianceCache::ambient(const Vec3& p, const Vec3& n, int depth, Vec3& out) const {
    if (depth < 1 || depth >= static_cast<int>(m_ambient.size())) return false;
    const auto& grids = m_ambient[static_cast<std::size_t>(depth)];
    return grids[0].estimate(p, n, out) || grids[1].estimate(p, n, out);
}

void IrradianceCache::end_pass() {
    if (!m_in_pass) return;
    std::vector<int> all(m_tiles.size());
    for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);
    merge_tiles(all);
    m_tiles.clear();
    m_in_pass = false;
    ++m_pass;
}

LookupParams IrradianceCache::clamp_params(int depth, const LookupParams& params) const {
    LookupParams out = params;
    out.error_bound = std::min(params.error_bound, reach(depth));
    return out;
}

void IrradianceCache::accumulate(InterpolationAccumulator& acc, const Vec3& p, int depth) const {
    if (depth < 0 || depth >= depth_count()) return;
    const RecordOctree& tree = m_octrees[static_cast<std::size_t>(depth)];
    add_in_insertion_order(acc, tree, p);
}

Interpolation IrradianceCache::lookup(const Vec3& p, const Vec3& n, int depth, const LookupParams& params) const {
    InterpolationAccumulator acc(p, n, clamp_params(depth, params));
    accumulate(acc, p, depth);
    return acc.result();
}

void IrradianceCache::clamp_new_record(IrradianceRecord& record) const {
    // Křivánek et al. 2006, neighbour clamping R_new ≤ R_i + |p_new − p_i|: only records closer than R_new can bind.
    if (!m_neighbour_clamp) return;
    const RecordOctree& tree = m_octrees[static_cast<std::size_t>(record.depth)];
    record.radius = tree.clamped_radius(record.position, record.radius);
}

void IrradianceCache::clamp_mutual(IrradianceRecord& record) {
    if (m_neighbour_clamp) clamp_new(m_octrees[static_cast<std::size_t>(record.depth)], record);
}

void IrradianceCache::add(const IrradianceRecord& record) {
    if (m_in_pass) throw std::logic_error("IrradianceCache::add during a pass: add through the tile's TileCache");
    if (record.depth < 0 || record.depth >= depth_count()) return;
    IrradianceRecord r = record;
    clamp_mutual(r);
    m_octrees[static_cast<std::size_t>(r.depth)].insert(r);
    count_record(r);
}

void IrradianceCache::count_record(const IrradianceRecord& record) {
    const auto pass = static_cast<std::size_t>(std::max(record.pass, 0));
    if (m_records_per_pass.size() <= pass) m_records_per_pass.resize(pass + 1);
    std::vector<std::uint64_t>& per_depth = m_records_per_pass[pass];
    if (per_depth.size() < m_octrees.size()) per_depth.resize(m_octrees.size());
    ++per_depth[static_cast<std::size_t>(record.depth)];
}

std::vector<std::size_t> IrradianceCache::sizes() const {
    std::vector<std::size_t> out;
    out.reserve(m_octrees.size());
    for (const RecordOctree& tree : m_octrees) out.push_back(tree.size());
    return out;
}

const RecordArray& IrradianceCache::records(int depth) const {
    return m_octrees.at(static_cast<std::size_t>(depth)).records();
}

std::size_t IrradianceCache::keep_records(const std::function<bool(const IrradianceRecord&)>& keep) {
    if (m_in_pass) throw std::logic_error("IrradianceCache::keep_records during a pass");
    std::size_t dropped = 0;
    for (auto& per_depth : m_records_per_pass) std::fill(per_depth.begin(), per_depth.end(), 0);
    for (std::size_t d = 0; d < m_octrees.size(); ++d) {
        RecordOctree kept = m_octrees[d].empty_like();
        for (const IrradianceRecord& r : m_octrees[d].records()) {
            if (!keep(r)) {
                ++dropped;
                continue;
            }
            kept.insert(r);
            const auto pass = static_cast<std::size_t>(r.pass);
            if (m_records_per_pass.size() <= pass)
                m_records_per_pass.resize(pass + 1, std::vector<std::uint64_t>(m_octrees.size()));
            ++m_records_per_pass[pass][d];
        }
        m_octrees[d] = std::move(kept);
    }
    return dropped;
}

CacheStatistics IrradianceCache::statistics() const {
    CacheStatistics s;
    s.records = m_records_per_pass;
    s.lookups = m_lookups;
    s.hits = m_hits;
    double radius_sum = 0.0;
    for (const RecordOctree& tree : m_octrees) {
        for (std::uint32_t i = 0; i < tree.size(); ++i) radius_sum += tree.geometry(i).radius;
        s.total_records += tree.size();
        s.memory_bytes += tree.memory_bytes();
    }
    for (const auto& tile : m_tiles)
        for (const RecordOctree& own : tile->m_own) s.memory_bytes += own.memory_bytes();
    if (s.total_records > 0) s.mean_radius = radius_sum / static_cast<double>(s.total_records);
    return s;
}

}  // namespace wardray::cache
