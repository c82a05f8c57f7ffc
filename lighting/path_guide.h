// PathGuide: where indirect light comes from, learned from a pilot pass's paths, for sampling the reference's
// bounces towards it (Müller, Gross & Novák 2017, "Practical Path Guiding", with a fixed directional grid).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/vec3.h"

namespace wardray::lighting {

/// One pilot path vertex: radiance `radiance` (the mean of its channels) arrived at `p` along the unit `-dir`,
/// i.e. a ray leaving `p` along `dir` brought it back.
struct GuideSample {
    std::array<float, 3> p{};
    std::array<float, 3> dir{};
    float radiance = 0.0f;
};

/// A piecewise-constant density over the sphere on a grid of bins (z = cos θ about world +z in kRows equal rows,
/// φ in kColumns columns of equal pseudo-angle, about 2π/kColumns each), proportional to one spatial cell's mean
/// radiance per bin times the clamped cosine to one of the six axis normals.
class GuideDistribution {
public:
    static constexpr int kRows = 16;
    static constexpr int kColumns = 32;
    static constexpr int kBins = kRows * kColumns;

    /// A unit direction drawn from the density with two uniforms in [0, 1) (rows by the marginal, then the column
    /// by the row's conditional: the unit square maps piecewise-continuously, so stratified uniforms stay so), and
    /// its density in `pdf`.
    Vec3 sample(double u, double v, double& pdf) const;
    /// The density of `dir` (unit) per steradian.
    double pdf(const Vec3& dir) const;

    /// Builds the density from per-bin weights (≥ 0, not all zero).
    static GuideDistribution from_weights(const std::array<double, kBins>& weights);

private:
    double bin_pdf(int bin) const;

    std::array<float, kRows + 1> m_row_cdf{};      ///< marginal over rows
    std::array<float, kBins + kRows> m_col_cdf{};  ///< per row, its conditional over columns (kColumns + 1 each)
};

/// An octree over the pilot's vertices whose leaves each hold six GuideDistributions, one per axis normal.
/// Built once before the render from samples in a fixed order, it is then read-only, so the image is the same
/// for any thread count.
class PathGuide {
public:
    /// Builds the guide from `samples` (none: an empty guide); the same samples in the same order, the same guide.
    static PathGuide build(const std::vector<GuideSample>& samples);

    bool empty() const { return m_leaves.empty(); }
    /// The density for a surface at `p` with unit normal `n`: that of the leaf containing `p` (or the nearest to
    /// it) for the axis nearest `n`; null when that leaf saw no light towards that side.
    const GuideDistribution* find(const Vec3& p, const Vec3& n) const;
    /// How many leaves the octree has.
    int leaves() const { return static_cast<int>(m_leaves.size()); }

private:
    struct Node {
        std::int32_t child = -1;  ///< the first of 8 children, or −1 for a leaf
        std::int32_t leaf = -1;   ///< for a leaf: its index in m_leaves
    };
    struct Leaf {
        std::array<GuideDistribution, 6> axes;  ///< +x, −x, +y, −y, +z, −z
        std::array<bool, 6> valid{};
    };
    Vec3 m_min;
    double m_size = 0.0;  ///< the root cube's edge
    std::vector<Node> m_nodes;
    std::vector<Leaf> m_leaves;
};

}  // namespace wardray::lighting
