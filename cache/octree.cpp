// RecordOctree: filing records by validity sphere, growing the root, and the root-to-leaf lookup.
#include "cache/octree.h"

#include <algorithm>
#include <cmath>

namespace wardray::cache {
namespace {

/// Levels below the root at most; smaller spheres are filed at this level (correct, only less selective).
constexpr int kMaxLevels = 30;

/// Cubes are widened by this fraction of their size in the overlap tests, so that rounding can only add a record
/// to a node, never leave it out.
constexpr double kSlack = 1e-9;

Vec3 octant_offset(int octant, double half) {
    return {(octant & 1) ? half : 0.0, (octant & 2) ? half : 0.0, (octant & 4) ? half : 0.0};
}

bool box_overlaps_cube(const Vec3& lo, const Vec3& hi, const Vec3& cube_min, double size) {
    const double slack = kSlack * size;
    for (int a = 0; a < 3; ++a) {
        if (hi[a] < cube_min[a] - slack || lo[a] > cube_min[a] + size + slack) return false;
    }
    return true;
}

}  // namespace

RecordOctree::RecordOctree(double reach) : m_reach(std::isfinite(reach) ? std::max(reach, 1.0) : 1.0) {}

std::uint32_t RecordOctree::insert(const IrradianceRecord& record) {
    const auto index = static_cast<std::uint32_t>(m_records.size());
    m_records.push_back(record);
    m_keys.push_back({record.position, record.normal, record.radius});
    const double s = m_reach * record.radius;
    if (!is_finite(record.position) || !(s > 0.0) || !std::isfinite(s)) return index;
    const Vec3 lo = record.position - Vec3{s, s, s};
    const Vec3 hi = record.position + Vec3{s, s, s};

    if (m_root < 0) {
        // The first root: a power-of-two cube aligned to its size, so that later cube corners are exact.
        int e = 0;
        std::frexp(4.0 * s, &e);
        Node root;
        root.size = std::ldexp(1.0, e);
        for (int a = 0; a < 3; ++a) root.min[a] = std::floor(lo[a] / root.size) * root.size;
        m_nodes.push_back(std::move(root));
        m_root = 0;
    }
    grow_to_fit(lo, hi);

    // Ward, Rubinstein & Clear 1988 file at the level whose cells are as wide as the sphere's diameter; one level
    // finer (cells as wide as its radius) costs up to 27 entries a record but fetches about 3x fewer candidates.
    double target = m_nodes[m_root].size;
    for (int level = 0; level < kMaxLevels && target * 0.5 >= s; ++level) target *= 0.5;
    file(index, m_root, lo, hi, target);
    return index;
}

void RecordOctree::grow_to_fit(const Vec3& lo, const Vec3& hi) {
    for (;;) {
        const Node& root = m_nodes[m_root];
        bool fits = hi.x - lo.x <= root.size;
        for (int a = 0; a < 3; ++a) fits = fits && lo[a] >= root.min[a] && hi[a] < root.min[a] + root.size;
        if (fits) return;
        // Double the root towards the box: the old root becomes the octant on the far side of the growth.
        Node bigger;
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
        bigger.children[octant] = m_root;
        m_nodes.push_back(std::move(bigger));
        m_root = static_cast<std::int32_t>(m_nodes.size() - 1);
    }
}

std::int32_t RecordOctree::child(std::int32_t node, int octant) {
    if (m_nodes[node].children[octant] < 0) {
        Node c;
        c.size = 0.5 * m_nodes[node].size;
        c.min = m_nodes[node].min + octant_offset(octant, c.size);
        m_nodes.push_back(std::move(c));
        m_nodes[node].children[octant] = static_cast<std::int32_t>(m_nodes.size() - 1);
    }
    return m_nodes[node].children[octant];
}

void RecordOctree::file(std::uint32_t index, std::int32_t node, const Vec3& lo, const Vec3& hi, double target_size) {
    if (m_nodes[node].size <= target_size) {
        m_nodes[node].records.push_back(index);
        return;
    }
    // Into every child the sphere's box overlaps: at most three per axis once cells are as wide as its radius.
    const double half = 0.5 * m_nodes[node].size;
    for (int octant = 0; octant < 8; ++octant) {
        const Vec3 cmin = m_nodes[node].min + octant_offset(octant, half);
        if (box_overlaps_cube(lo, hi, cmin, half)) file(index, child(node, octant), lo, hi, target_size);
    }
}

void RecordOctree::within(std::int32_t node, const Vec3& centre, double radius,
                          std::vector<std::uint32_t>& found) const {
    const Node& n = m_nodes[node];
    const Vec3 r{radius, radius, radius};
    if (!box_overlaps_cube(centre - r, centre + r, n.min, n.size)) return;
    for (const std::uint32_t index : n.records) {
        // A record is filed in up to 27 nodes; it is reported only from the one that holds its position.
        const Vec3& p = m_keys[index].position;
        bool home = true;
        for (int a = 0; a < 3; ++a) home = home && p[a] >= n.min[a] && p[a] < n.min[a] + n.size;
        if (home && length(p - centre) <= radius) found.push_back(index);
    }
    for (const std::int32_t c : n.children) {
        if (c >= 0) within(c, centre, radius, found);
    }
}

void RecordOctree::for_each_within(const Vec3& centre, double radius,
                                   const std::function<void(std::uint32_t)>& visit) const {
    if (m_root < 0 || !is_finite(centre) || !(radius >= 0.0)) return;
    std::vector<std::uint32_t> found;
    within(m_root, centre, radius, found);
    // In insertion order.
    std::sort(found.begin(), found.end());
    for (const std::uint32_t index : found) visit(index);
}

}  // namespace wardray::cache
