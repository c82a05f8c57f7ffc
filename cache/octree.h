// RecordOctree: irradiance records filed by their validity sphere, with Ward's root-to-leaf multi-resolution lookup.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "cache/irradiance_record.h"
#include "core/vec3.h"

namespace wardray::cache {

/// Records of one bounce depth, each filed by the sphere of radius reach × R_i around its position
/// (Ward, Rubinstein & Clear 1988, section "the octree"). A record goes into every node of the level whose cells
/// are at least as wide as its sphere's radius and that its sphere's box overlaps (at most 27), so a lookup only
/// walks from the root to the leaf holding the query point and tests each record it meets at most once.
/// Not thread-safe for writing; any number of concurrent readers while nobody writes.
class RecordOctree {
public:
    /// `reach` ≥ the largest error bound lookups will use: validity implies |p − p_i| < error_bound × R_i.
    /// Values below 1 are raised to 1 (neighbour clamping needs the R_i sphere).
    explicit RecordOctree(double reach = 1.0);

    /// Files a copy of `record` and returns its index (indices follow insertion order). A record with a
    /// non-finite position or radius is kept but never found.
    std::uint32_t insert(const IrradianceRecord& record);
    /// Every record in insertion order.
    const std::vector<IrradianceRecord>& records() const { return m_records; }
    /// Mutable access for neighbour clamping: the radius may only shrink (the filing stays conservative).
    IrradianceRecord& record(std::uint32_t index) { return m_records[index]; }
    std::size_t size() const { return m_records.size(); }
    double reach() const { return m_reach; }

    /// Calls `visit(index)` for each record whose filed sphere may contain `q` (a superset of the records valid at q
    /// for any error bound ≤ reach), walking from the root to the leaf that holds q; deterministic order.
    template <typename Visit>
    void visit(const Vec3& q, Visit&& visit) const {
        if (m_root < 0 || !is_finite(q)) return;
        const Node& root = m_nodes[static_cast<std::size_t>(m_root)];
        for (int a = 0; a < 3; ++a) {
            if (q[a] < root.min[a] || q[a] >= root.min[a] + root.size) return;
        }
        // Multi-resolution lookup (Ward, Rubinstein & Clear 1988): the records of every node from the root down
        // to the leaf that holds q.
        std::int32_t node = m_root;
        while (node >= 0) {
            const Node& n = m_nodes[static_cast<std::size_t>(node)];
            for (const std::uint32_t index : n.records) visit(index);
            const double half = 0.5 * n.size;
            int octant = 0;
            for (int a = 0; a < 3; ++a) {
                if (q[a] >= n.min[a] + half) octant |= 1 << a;
            }
            node = n.children[static_cast<std::size_t>(octant)];
        }
    }
    /// Each record's position, normal and radius at filing, packed apart from its gradients so that lookups can
    /// reject most candidates without touching the whole record (the radius may since have shrunk, never grown).
    struct Key {
        Vec3 position;
        Vec3 normal;
        double radius = 0.0;
    };
    const std::vector<Key>& keys() const { return m_keys; }
    /// Calls `visit(index)` once for each record whose position lies within `radius` of `centre`.
    void for_each_within(const Vec3& centre, double radius, const std::function<void(std::uint32_t)>& visit) const;

private:
    struct Node {
        std::array<std::int32_t, 8> children{-1, -1, -1, -1, -1, -1, -1, -1};
        Vec3 min;           ///< the cube [min, min + size)
        double size = 0.0;  ///< a power of two
        std::vector<std::uint32_t> records;
    };

    void grow_to_fit(const Vec3& lo, const Vec3& hi);
    std::int32_t child(std::int32_t node, int octant);
    void file(std::uint32_t index, std::int32_t node, const Vec3& lo, const Vec3& hi, double target_size);
    void within(std::int32_t node, const Vec3& centre, double radius, std::vector<std::uint32_t>& found) const;

    double m_reach;
    std::vector<IrradianceRecord> m_records;
    std::vector<Key> m_keys;
    std::vector<Node> m_nodes;
    std::int32_t m_root = -1;
};

}  // namespace wardray::cache
