// AmbientGrid: records summed into ambient cubes on a hashed uniform grid, and the estimate at a point.
#include "cache/ambient_grid.h"

#include <bit>
#include <cmath>

namespace wardray::cache {
namespace {

/// Cell coordinates are kept within ±2^20 an axis (21 bits each in a key): a grid with a cell per record spans far
/// fewer cells a side. Points beyond have no estimate and take a full lookup.
constexpr std::int64_t kKeyHalf = std::int64_t{1} << 20;

/// The face of an ambient cube that a normal's component along `axis` faces.
int face_of(int axis, double component) { return 2 * axis + (component < 0.0 ? 1 : 0); }

}  // namespace

bool AmbientGrid::key_of(const Vec3& p, std::uint64_t& key) const {
    std::uint64_t k = 0;
    for (int a = 0; a < 3; ++a) {
        const double c = std::floor(p[a] * m_inverse_cell);
        // Also false for NaN.
        if (!(c > -static_cast<double>(kKeyHalf) && c < static_cast<double>(kKeyHalf))) return false;
        k = k << 21 | static_cast<std::uint64_t>(static_cast<std::int64_t>(c) + kKeyHalf);
    }
    key = k;
    return true;
}

std::size_t AmbientGrid::slot_of(std::uint64_t key) const {
    const std::size_t mask = m_slots.size() - 1;
    std::size_t s = static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ULL) >> m_shift);
    while (m_slots[s] != 0 && m_cells[m_slots[s] - 1].key != key) s = (s + 1) & mask;
    return s;
}

void AmbientGrid::build(const RecordOctree& tree, double cell) {
    m_cells.clear();
    m_slots.clear();
    if (!(cell > 0.0) || !std::isfinite(cell) || !std::isfinite(1.0 / cell) || tree.size() == 0) return;
    m_inverse_cell = 1.0 / cell;
    std::size_t capacity = 16;
    while (capacity < 2 * tree.size()) capacity *= 2;
    m_slots.assign(capacity, 0);
    m_shift = 64 - std::countr_zero(capacity);
    struct Sums {
        std::array<Vec3, 6> face{};
        std::array<double, 6> weight{};
        Vec3 all;
        double count = 0.0;
    };
    std::vector<Sums> sums;
    for (std::uint32_t i = 0; i < tree.size(); ++i) {
        const RecordGeometry& g = tree.geometry(i);
        const Vec3& e = tree.values(i).irradiance;
        std::uint64_t key = 0;
        if (!is_finite(e) || !is_finite(g.normal) || !key_of(g.position, key)) continue;
        const std::size_t s = slot_of(key);
        if (m_slots[s] == 0) {
            m_cells.emplace_back().key = key;
            sums.emplace_back();
            m_slots[s] = static_cast<std::uint32_t>(m_cells.size());
        }
        Sums& sum = sums[m_slots[s] - 1];
        for (int a = 0; a < 3; ++a) {
            const double w = g.normal[a] * g.normal[a];
            sum.face[face_of(a, g.normal[a])] += e * w;
            sum.weight[face_of(a, g.normal[a])] += w;
        }
        sum.all += e;
        sum.count += 1.0;
    }
    for (std::size_t c = 0; c < m_cells.size(); ++c) {
        const Sums& sum = sums[c];
        const Vec3 mean = sum.all / sum.count;
        // A face its records barely face (weights are squared normal components) takes the cell's mean.
        for (int f = 0; f < 6; ++f)
            m_cells[c].face[f] = sum.weight[f] > 1e-6 * sum.count ? sum.face[f] / sum.weight[f] : mean;
    }
}

bool AmbientGrid::estimate(const Vec3& p, const Vec3& n, Vec3& out) const {
    std::uint64_t key = 0;
    if (m_cells.empty() || !key_of(p, key)) return false;
    const std::uint32_t index = m_slots[slot_of(key)];
    if (index == 0) return false;
    const Cell& cell = m_cells[index - 1];
    out = cell.face[face_of(0, n.x)] * (n.x * n.x) + cell.face[face_of(1, n.y)] * (n.y * n.y) +
          cell.face[face_of(2, n.z)] * (n.z * n.z);
    return true;
}

}  // namespace wardray::cache
