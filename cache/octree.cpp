// RecordOctree: filing records by validity sphere, growing the root, and the root-to-leaf lookup.
#include "cache/octree.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#ifdef __SSE2__
#include <emmintrin.h>
#endif
#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#define WARDRAY_WIDE_SCAN 1
#endif

namespace wardray::cache {
namespace {

/// Levels below the root at most; smaller spheres are filed at this level (correct, only less selective).
constexpr int kMaxLevels = 30;

/// Cubes are widened by this fraction of their size in the overlap tests, so that rounding can only add a record
/// to a node, never leave it out.
constexpr double kSlack = 1e-9;

/// Block positions: steps of 1 / kPositionScale node sizes from -1 (0) to 2 (65535).
constexpr double kPositionScale = 65535.0 / 3.0;
/// Block radii: steps of 1 / kRadiusScale node sizes, in (0, 1].
constexpr double kRadiusScale = 65535.0;

/// A coordinate in node sizes, in [-1, 2], to the nearest step.
std::uint16_t quantized_position(double local) {
    return static_cast<std::uint16_t>(std::clamp(std::nearbyint((local + 1.0) * kPositionScale), 0.0, 65535.0));
}

bool box_overlaps_cube(const Vec3& lo, const Vec3& hi, const Vec3& cube_min, double size) {
    const double slack = kSlack * size;
    for (int a = 0; a < 3; ++a) {
        if (hi[a] < cube_min[a] - slack || lo[a] > cube_min[a] + size + slack) return false;
    }
    return true;
}

/// The octants of the cube [cube_min, cube_min + 2 half) whose cubes the box overlaps, one bit each: the same
/// answer as box_overlaps_cube() on each child, from two tests per axis instead of six per child.
unsigned overlapped_octants(const Vec3& lo, const Vec3& hi, const Vec3& cube_min, double half) {
    const double slack = kSlack * half;
    unsigned mask = 0xFF;
    for (int a = 0; a < 3; ++a) {
        const double low_min = cube_min[a] + 0.0, high_min = cube_min[a] + half;
        const bool low = !(hi[a] < low_min - slack || lo[a] > low_min + half + slack);
        const bool high = !(hi[a] < high_min - slack || lo[a] > high_min + half + slack);
        // The octants with bit a clear are the low ones on axis a.
        static constexpr unsigned kHigh[3] = {0xAA, 0xCC, 0xF0};
        if (!low) mask &= kHigh[a];
        if (!high) mask &= ~kHigh[a] & 0xFFu;
    }
    return mask;
}

#ifdef WARDRAY_WIDE_SCAN
/// For each 8-bit mask of passing lanes, the lanes in order, then zeros: the permutation that packs them first.
struct CompressTable {
    std::uint8_t lanes[256][8];
    constexpr CompressTable() : lanes{} {
        for (unsigned mask = 0; mask < 256; ++mask) {
            unsigned k = 0;
            for (unsigned lane = 0; lane < 8; ++lane)
                if (mask & (1u << lane)) lanes[mask][k++] = static_cast<std::uint8_t>(lane);
        }
    }
};
constexpr CompressTable kCompress;

/// The four 16-bit steps at `first` and the four at `second`, as eight floats.
__attribute__((target("avx2"), always_inline)) inline __m256 widen_pair(const std::uint16_t* first,
                                                                       const std::uint16_t* second) {
    const __m128i both = _mm_unpacklo_epi64(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(first)),
                                            _mm_loadl_epi64(reinterpret_cast<const __m128i*>(second)));
    return _mm256_cvtepi32_ps(_mm256_cvtepu16_epi32(both));
}

bool cpu_has_avx2() {
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("popcnt");
}
const bool kCpuHasAvx2 = cpu_has_avx2();
#else
const bool kCpuHasAvx2 = false;
#endif
/// Whether scan_near() uses the AVX2 scan (RecordOctree::use_wide_scan()).
bool g_wide_scan = kCpuHasAvx2;

}  // namespace

bool RecordOctree::use_wide_scan(bool wanted) {
    g_wide_scan = wanted && kCpuHasAvx2;
    return g_wide_scan;
}

RecordOctree::RecordOctree(double reach, std::array<double, 2> inner) : RecordOctree(reach, inner, 3) {}

RecordOctree::RecordOctree(double reach, std::array<double, 2> inner, std::size_t filings) {
    const double r = std::isfinite(reach) ? std::max(reach, 1.0) : 1.0;
    const std::array<double, 2> defaults{0.5, 0.25};
    for (std::size_t k = 0; k < inner.size(); ++k)
        if (!(inner[k] > 0.0 && inner[k] <= 1.0)) inner[k] = defaults[k];
    m_inner = inner;
    m_filings.emplace_back().reach = r;
    if (filings > 1)
        for (const double f : inner) m_filings.emplace_back().reach = r * f;
}

std::uint32_t RecordOctree::insert(const IrradianceRecord& record) {
    const auto index = static_cast<std::uint32_t>(m_records.size());
    m_records.push_back(record);
    for (std::size_t k = 0; k < m_filings.size(); ++k) insert_into(m_filings[k], record, index, k == 0);
    return index;
}

void RecordOctree::insert_into(Filing& f, const IrradianceRecord& record, std::uint32_t index, bool homes) {
    const double s = f.reach * record.radius;
    if (!is_finite(record.position) || !(s > 0.0) || !std::isfinite(s)) return;
    const Vec3 lo = record.position - Vec3{s, s, s};
    const Vec3 hi = record.position + Vec3{s, s, s};

    if (f.root < 0) {
        // The first root: a power-of-two cube aligned to its size, so that later cube corners are exact.
        int e = 0;
        std::frexp(4.0 * s, &e);
        Cube& root = f.root_cube;
        root.size = std::ldexp(1.0, e);
        for (int a = 0; a < 3; ++a) root.min[a] = std::floor(lo[a] / root.size) * root.size;
        f.nodes.push_back(Node{});
        f.root = 0;
    }
    grow_to_fit(f, lo, hi);

    // Ward, Rubinstein & Clear 1988 file at the level whose cells are as wide as the sphere's diameter (up to 8
    // entries a record), as the inner filings do. The first filing goes one level finer (cells as wide as its
    // radius: up to 27 entries, about 3x fewer candidates), since its lookups (neighbour clamping, low-weight rays)
    // meet spheres up to 1 / error_bound times wider than their validity spheres. The inner filings, at the bounds
    // most lookups use, are walked about as fast either way (14-textures: 8% faster coarse, its nodes being fewer)
    // and hold about 2.8x fewer entries.
    double target = f.root_cube.size;
    const double cell = homes ? s : 2.0 * s;  // homes: the first filing
    for (int level = 0; level < kMaxLevels && target * 0.5 >= cell; ++level) target *= 0.5;
    file(f, record, index, homes, f.root, f.root_cube, lo, hi, target);
    if (!homes) return;
    // Count the home on the path from the root down to the node that holds it.
    Cube cube = f.root_cube;
    for (std::int32_t node = f.root; node >= 0;) {
        Node& n = f.nodes[static_cast<std::size_t>(node)];
        ++n.subtree_homes;
        if (cube.size <= target) break;
        const int octant = cube.octant_of(record.position);
        cube = cube.child(octant);
        node = n.children < 0 ? -1 : f.children[static_cast<std::size_t>(n.children)][static_cast<std::size_t>(octant)];
    }
}

void RecordOctree::grow_to_fit(Filing& f, const Vec3& lo, const Vec3& hi) {
    for (;;) {
        const Cube& root = f.root_cube;
        bool fits = hi.x - lo.x <= root.size;
        for (int a = 0; a < 3; ++a) fits = fits && lo[a] >= root.min[a] && hi[a] < root.min[a] + root.size;
        if (fits) return;
        // Double the root towards the box: the old root becomes the octant on the far side of the growth.
        Cube bigger;
        bigger.size = 2.0 * root.size;
        int octant = 0;
        for (int a = 0; a < 3; ++a) {
            if (lo[a] < root.min[a]) {
                bigger.min[a] = root.min[a] - root.size;
                octant |= 1 << a;
            } else {
                bigger.min[a] = root.min[a];
            }
        }
        Node node;
        Children children;
        children.fill(-1);
        children[static_cast<std::size_t>(octant)] = f.root;
        node.children = static_cast<std::int32_t>(f.children.size());
        f.children.push_back(children);
        node.subtree_homes = f.nodes[static_cast<std::size_t>(f.root)].subtree_homes;
        f.nodes.push_back(std::move(node));
        f.root = static_cast<std::int32_t>(f.nodes.size() - 1);
        f.root_cube = bigger;
    }
}

std::int32_t RecordOctree::child(Filing& f, std::int32_t node, int octant) {
    if (f.nodes[node].children < 0) {
        Children none;
        none.fill(-1);
        f.nodes[node].children = static_cast<std::int32_t>(f.children.size());
        f.children.push_back(none);
    }
    Children& children = f.children[static_cast<std::size_t>(f.nodes[node].children)];
    if (children[octant] < 0) {
        children[octant] = static_cast<std::int32_t>(f.nodes.size());
        f.nodes.push_back(Node{});
    }
    return children[octant];
}

void RecordOctree::file(Filing& f, const IrradianceRecord& record, std::uint32_t index, bool homes,
                        std::int32_t node, const Cube& cube, const Vec3& lo, const Vec3& hi, double target_size) {
    if (cube.size <= target_size) {
        Node& n = f.nodes[node];
        // In units of the node's size (a power of two, so the scaling is exact): the scan's floats neither
        // underflow nor overflow at any scene scale.
        const double unit = 1.0 / cube.size;
        const Vec3 local = (record.position - cube.min) * unit;
        // The filed sphere's radius, rounded up (at least one step, at most a node size: it is filed here).
        const auto radius = static_cast<std::uint16_t>(
            std::clamp(std::ceil(f.reach * record.radius * unit * kRadiusScale), 1.0, kRadiusScale));
        if (n.block_count == 0 || n.blocks[n.block_count - 1].index[kBlock - 1] != kNoRecord) {
            // Position 0 is a node size outside the cube, where no query is, and radius 0 reaches no farther than
            // the scan's slack.
            Node::Block unused;
            for (std::size_t k = 0; k < kBlock; ++k) {
                unused.x[k] = unused.y[k] = unused.z[k] = 0;
                unused.radius[k] = 0;
                unused.index[k] = kNoRecord;
            }
            if (n.block_count == block_capacity(n.block_count)) {
                // Full: a run of the next capacity, the old one back to the pool.
                Node::Block* more = f.blocks.allocate(block_capacity(n.block_count + 1));
                if (n.block_count > 0) {
                    std::copy(n.blocks, n.blocks + n.block_count, more);
                    f.blocks.release(n.blocks, n.block_count);
                }
                n.blocks = more;
            }
            n.blocks[n.block_count++] = unused;
        }
        Node::Block& b = n.blocks[n.block_count - 1];
        std::size_t lane = 0;
        while (b.index[lane] != kNoRecord) ++lane;
        b.x[lane] = quantized_position(local.x);
        b.y[lane] = quantized_position(local.y);
        b.z[lane] = quantized_position(local.z);
        b.radius[lane] = radius;
        b.index[lane] = index;
        bool home = homes;
        for (int a = 0; a < 3; ++a)
            home = home && record.position[a] >= cube.min[a] && record.position[a] < cube.min[a] + cube.size;
        if (home) {
            if (n.home_list < 0) {
                n.home_list = static_cast<std::int32_t>(f.home_lists.size());
                f.home_lists.emplace_back();
            }
            f.home_lists[static_cast<std::size_t>(n.home_list)].push_back(index);
        }
        return;
    }
    // Into every child the sphere's box overlaps: at most three per axis once cells are as wide as its radius.
    const unsigned octants = overlapped_octants(lo, hi, cube.min, 0.5 * cube.size);
    for (int octant = 0; octant < 8; ++octant) {
        if (octants & (1u << octant))
            file(f, record, index, homes, child(f, node, octant), cube.child(octant), lo, hi, target_size);
    }
}

std::size_t RecordOctree::scan_near(const Node& n, const Cube& cube, const Vec3& q, double error_bound, double reach,
                                   std::size_t begin, std::uint32_t* near) {
    const std::size_t end = std::min<std::size_t>(n.block_count, begin + kScanBlocks);
    // In position steps, as filed: q lies in the cube, so within [kPositionScale, 2 kPositionScale). A filed
    // position is off by at most half a step an axis (under a step in distance), its radius only rounded up, and
    // every float term is under 2^17 (rounding moves it by under 2^-6): the slack of 4 steps covers both.
    const Vec3 local = (q - cube.min) * (1.0 / cube.size);
    // x, y, z, then the bound (a radius step is 1 / (reach kRadiusScale) node sizes of R_i, times error_bound, in
    // position steps), then the slack.
    const float query[5] = {static_cast<float>((local.x + 1.0) * kPositionScale),
                            static_cast<float>((local.y + 1.0) * kPositionScale),
                            static_cast<float>((local.z + 1.0) * kPositionScale),
                            static_cast<float>(error_bound / reach * kPositionScale / kRadiusScale), 4.0f};
#ifdef WARDRAY_WIDE_SCAN
    if (g_wide_scan) return begin < end ? scan_blocks_avx2(n.blocks + begin, end - begin, query, near) : 0;
#endif
    // Four lanes at a time (GCC/Clang vector extensions: SSE on x86-64, NEON on ARM).
    using Floats = float __attribute__((vector_size(16)));
    // Four 16-bit steps to floats. On x86-64 widened by an unpack with zero and converted as a vector (GCC makes
    // four scalar conversions of the generic form).
    const auto widen = [](const std::uint16_t* p) {
#ifdef __SSE2__
        const __m128i steps = _mm_loadl_epi64(reinterpret_cast<const __m128i*>(p));
        const __m128 floats = _mm_cvtepi32_ps(_mm_unpacklo_epi16(steps, _mm_setzero_si128()));
        Floats out;
        std::memcpy(&out, &floats, sizeof out);
        return out;
#else
        using Steps = std::uint16_t __attribute__((vector_size(8)));
        Steps steps;
        std::memcpy(&steps, p, sizeof steps);
        return __builtin_convertvector(steps, Floats);
#endif
    };
    const Floats qx = Floats{} + query[0], qy = Floats{} + query[1], qz = Floats{} + query[2];
    const Floats bound = Floats{} + query[3];
    const float slack = query[4];
    std::size_t found = 0;
    for (std::size_t i = begin; i < end; ++i) {
        const Node::Block& b = n.blocks[i];
        const Floats dx = qx - widen(b.x), dy = qy - widen(b.y), dz = qz - widen(b.z);
        const Floats within = bound * widen(b.radius) + slack;
        const auto inside = dx * dx + dy * dy + dz * dz < within * within;  // -1 in the lanes that pass
        // Branch-free: most entries fail, and a mispredicted branch per entry costs more than the test.
        for (std::size_t k = 0; k < kBlock; ++k) {
            near[found] = b.index[k];
            found -= static_cast<std::size_t>(static_cast<std::ptrdiff_t>(inside[k]));
        }
    }
    return found;
}

#ifdef WARDRAY_WIDE_SCAN
__attribute__((target("avx2,popcnt"))) std::size_t RecordOctree::scan_blocks_avx2(const Node::Block* blocks,
                                                                                   std::size_t count,
                                                                                   const float (&query)[5],
                                                                                   std::uint32_t* near) {
    static_assert(kBlock == 4, "the wide scan takes two blocks of four a step");
    const __m256 qx = _mm256_set1_ps(query[0]), qy = _mm256_set1_ps(query[1]), qz = _mm256_set1_ps(query[2]);
    const __m256 bound = _mm256_set1_ps(query[3]), slack = _mm256_set1_ps(query[4]);
    std::size_t found = 0;
    for (std::size_t i = 0; i < count; i += 2) {
        const Node::Block& b0 = blocks[i];
        // An odd last block is taken twice and its second copy's lanes masked off.
        const Node::Block& b1 = blocks[i + 1 < count ? i + 1 : i];
        const unsigned lanes = i + 1 < count ? 0xFFu : 0x0Fu;
        // The portable scan's operations in its order: (q - p)² summed x, y, z against (bound r + slack)².
        const __m256 dx = _mm256_sub_ps(qx, widen_pair(b0.x, b1.x));
        const __m256 dy = _mm256_sub_ps(qy, widen_pair(b0.y, b1.y));
        const __m256 dz = _mm256_sub_ps(qz, widen_pair(b0.z, b1.z));
        const __m256 within = _mm256_add_ps(_mm256_mul_ps(bound, widen_pair(b0.radius, b1.radius)), slack);
        const __m256 d2 = _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(dx, dx), _mm256_mul_ps(dy, dy)),
                                        _mm256_mul_ps(dz, dz));
        const unsigned mask =
            static_cast<unsigned>(_mm256_movemask_ps(_mm256_cmp_ps(d2, _mm256_mul_ps(within, within), _CMP_LT_OQ))) &
            lanes;
        // The passing lanes' indices packed to the front and stored whole; the count moves past them only.
        const __m256i index = _mm256_inserti128_si256(
            _mm256_castsi128_si256(_mm_load_si128(reinterpret_cast<const __m128i*>(b0.index))),
            _mm_load_si128(reinterpret_cast<const __m128i*>(b1.index)), 1);
        const __m256i order =
            _mm256_cvtepu8_epi32(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(kCompress.lanes[mask])));
        _mm256_storeu_si256(reinterpret_cast<__m256i*>(near + found), _mm256_permutevar8x32_epi32(index, order));
        found += static_cast<std::size_t>(__builtin_popcount(mask));
    }
    return found;
}
#endif

void RecordOctree::clamp_within(std::int32_t node, const Cube& cube, const Vec3& centre, double& bound) const {
    const Filing& f = m_filings.front();
    const Node& n = f.nodes[node];
    // A record is filed in up to 27 nodes; it is tested only in the one that holds its position. Only records
    // closer than the bound can lower it (R_i > 0).
    if (n.home_list >= 0) {
        for (const std::uint32_t home : f.home_lists[static_cast<std::size_t>(n.home_list)]) {
            const RecordGeometry& g = m_records.geometry(home);
            const double d = length(g.position - centre);
            if (d < bound) bound = std::min(bound, g.radius + d);
        }
    }
    // The child holding the centre first: its records are the likeliest to lower the bound for the others.
    const double half = 0.5 * cube.size;
    const int first = cube.octant_of(centre);
    if (n.children < 0) return;
    const Children& children = f.children[static_cast<std::size_t>(n.children)];
    for (int k = 0; k < 8; ++k) {
        const int octant = k ^ first;
        const std::int32_t c = children[static_cast<std::size_t>(octant)];
        if (c < 0 || m_filings.front().nodes[static_cast<std::size_t>(c)].subtree_homes == 0) continue;
        // Only children within the bound found so far.
        const Vec3 b{bound, bound, bound};
        if (overlapped_octants(centre - b, centre + b, cube.min, half) & (1u << octant))
            clamp_within(c, cube.child(octant), centre, bound);
    }
}

double RecordOctree::clamped_radius(const Vec3& centre, double bound) const {
    const Filing& f = m_filings.front();
    if (f.root < 0 || !is_finite(centre) || !(bound >= 0.0)) return bound;
    const Vec3 b{bound, bound, bound};
    const Cube& root = f.root_cube;
    if (box_overlaps_cube(centre - b, centre + b, root.min, root.size)) clamp_within(f.root, root, centre, bound);
    return bound;
}

std::size_t RecordOctree::memory_bytes() const {
    std::size_t bytes = m_records.memory_bytes();
    for (const Filing& f : m_filings) {
        bytes += f.nodes.memory_bytes() + f.children.memory_bytes() + f.blocks.memory_bytes();
        for (const auto& homes : f.home_lists) bytes += sizeof homes + homes.capacity() * sizeof(std::uint32_t);
    }
    return bytes;
}

}  // namespace wardray::cache
