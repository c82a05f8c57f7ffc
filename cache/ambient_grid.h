// AmbientGrid: a coarse estimate of a depth's cached irradiance anywhere, one ambient cube per cell of a uniform grid.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "cache/octree.h"
#include "core/vec3.h"

namespace wardray::cache {

/// The records of one bounce depth summed into the cells of a uniform grid, each cell an ambient cube: per face
/// (+x, −x, +y, −y, +z, −z) the mean irradiance of the cell's records facing that way, each record weighted by its
/// normal's squared component along the face's axis. An estimate costs one hash probe and three faces, where a
/// lookup walks an octree and weighs and extrapolates several records: the control variate of
/// --gi-lookup-sampling (IrradianceCache::ambient()).
class AmbientGrid {
public:
    /// Replaces the contents with `tree`'s records, in insertion order, in cells `cell` wide (a positive, finite
    /// width; otherwise, or without records, the grid is empty). Records that are not finite are left out.
    void build(const RecordOctree& tree, double cell);
    bool empty() const { return m_cells.empty(); }
    std::size_t cell_count() const { return m_cells.size(); }
    /// The estimate at (p, n), n a unit vector: n.x² times the face of the cell holding p that n's x faces, and so
    /// on for y and z; a face no record of the cell faces takes the cell's mean. False (`out` untouched) where the
    /// cell holds no record or p is not finite.
    bool estimate(const Vec3& p, const Vec3& n, Vec3& out) const;

private:
    struct Cell {
        std::uint64_t key = 0;
        std::array<Vec3, 6> face{};  ///< +x, −x, +y, −y, +z, −z
    };
    /// The cell key of p, or false when p lies beyond the grid's range of keys.
    bool key_of(const Vec3& p, std::uint64_t& key) const;
    /// The slot of m_slots where `key` is or would go.
    std::size_t slot_of(std::uint64_t key) const;

    double m_inverse_cell = 0.0;
    std::vector<Cell> m_cells;
    /// Open addressing over m_cells: an index + 1, 0 for an empty slot; a power-of-two size over twice the cells.
    std::vector<std::uint32_t> m_slots;
    int m_shift = 64;  ///< 64 − log2(m_slots.size())
};

}  // namespace wardray::cache
