// PathGuide: an octree of directional histograms learned from pilot paths, sampled by inverting their CDFs.
#include "lighting/path_guide.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace wardray::lighting {

namespace {

using Distribution = GuideDistribution;
constexpr int kRows = Distribution::kRows;
constexpr int kColumns = Distribution::kColumns;
constexpr int kBins = Distribution::kBins;
/// A leaf holds at most 4·√(all the pilot's vertices), and at least 1024 (as Müller et al. 2017, sec. 3.2, split
/// at c·√(samples of the iteration)), unless it is this deep: enough vertices for a mean per bin of a surface's
/// hemisphere, few enough that a leaf stays near one surface's light.
constexpr int kMaxDepth = 12;

/// The pseudo-angle of (x, y) in [0, 4): a quarter turn per unit, y/(x + y) within the first quadrant. It grows with
/// φ as atan2 does but costs one division, so the columns are its equal steps (Δφ of a column varies a little).
double diamond_angle(double x, double y) {
    if (x == 0.0 && y == 0.0) return 0.0;
    if (y >= 0.0) return x >= 0.0 ? y / (x + y) : 1.0 - x / (y - x);
    return x < 0.0 ? 2.0 + y / (x + y) : 3.0 + x / (x - y);
}

/// φ at each column edge: the angle whose pseudo-angle is 4k/kColumns (within a quadrant t = y/(x + y) is at
/// φ = atan(t/(1 − t))).
const std::array<double, kColumns + 1>& column_edges() {
    static const auto edges = [] {
        std::array<double, kColumns + 1> e{};
        for (int k = 0; k <= kColumns; ++k) {
            const double d = 4.0 * k / kColumns;
            const int quadrant = std::min(3, static_cast<int>(d));
            const double t = d - quadrant;
            e[k] = quadrant * 0.5 * std::numbers::pi + std::atan2(t, 1.0 - t);
        }
        return e;
    }();
    return edges;
}

/// The solid angle of a bin of column `col`: Δz · Δφ.
double bin_solid_angle(int col) {
    const auto& e = column_edges();
    return (2.0 / kRows) * (e[col + 1] - e[col]);
}

/// The bin of a unit direction: the row of z = cos θ, the column of its pseudo-angle.
int bin_of(const Vec3& d) {
    const int row = std::clamp(static_cast<int>((d.z + 1.0) * 0.5 * kRows), 0, kRows - 1);
    const int col = std::clamp(static_cast<int>(diamond_angle(d.x, d.y) * (kColumns / 4.0)), 0, kColumns - 1);
    return row * kColumns + col;
}

/// The direction at fractional grid coordinates (row + a, column + b): z and φ each uniform within the bin, so
/// uniform in solid angle there.
Vec3 direction_at(double row, double col) {
    const double z = std::clamp(-1.0 + 2.0 * row / kRows, -1.0, 1.0);
    const int c = std::clamp(static_cast<int>(col), 0, kColumns - 1);
    const auto& e = column_edges();
    const double phi = e[c] + (col - c) * (e[c + 1] - e[c]);
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    return {r * std::cos(phi), r * std::sin(phi), z};
}

Vec3 axis_vector(int a) {
    Vec3 v;
    const double s = a % 2 == 0 ? 1.0 : -1.0;
    (a / 2 == 0 ? v.x : a / 2 == 1 ? v.y : v.z) = s;
    return v;
}

/// Each bin's mean of max(cos, 0) to each axis, over 4 x 4 points: the irradiance weight of a bin of constant
/// radiance for a surface facing that axis.
const std::array<std::array<double, kBins>, 6>& clamped_cosines() {
    static const auto table = [] {
        std::array<std::array<double, kBins>, 6> t{};
        for (int a = 0; a < 6; ++a) {
            const Vec3 axis = axis_vector(a);
            for (int b = 0; b < kBins; ++b) {
                double sum = 0.0;
                for (int i = 0; i < 4; ++i)
                    for (int j = 0; j < 4; ++j)
                        sum += std::max(0.0, dot(axis, direction_at(b / kColumns + (i + 0.5) / 4,
                                                                   b % kColumns + (j + 0.5) / 4)));
                t[a][b] = sum / 16.0;
            }
        }
        return t;
    }();
    return table;
}

/// The index of the first CDF entry above `u` among cdf[1..n], as a bin (0..n-1), skipping bins of zero mass.
int invert(const float* cdf, int n, double u) {
    int i = static_cast<int>(std::upper_bound(cdf + 1, cdf + n + 1, static_cast<float>(u)) - (cdf + 1));
    i = std::min(i, n - 1);
    while (i > 0 && cdf[i + 1] <= cdf[i]) --i;  // u = 1 rounding: back to a bin that has mass
    return i;
}

Vec3 to_vec(const std::array<float, 3>& a) { return {a[0], a[1], a[2]}; }

}  // namespace

GuideDistribution GuideDistribution::from_weights(const std::array<double, kBins>& weights) {
    GuideDistribution d;
    double total = 0.0;
    for (double w : weights) total += w;
    double row_sum = 0.0;
    for (int r = 0; r < kRows; ++r) {
        double in_row = 0.0;
        for (int c = 0; c < kColumns; ++c) in_row += weights[r * kColumns + c];
        float* cdf = &d.m_col_cdf[r * (kColumns + 1)];
        double run = 0.0;
        for (int c = 0; c < kColumns; ++c) {
            // A row without mass is never drawn; it gets a uniform conditional so that its CDF is valid.
            cdf[c] = static_cast<float>(in_row > 0.0 ? run / in_row : static_cast<double>(c) / kColumns);
            run += weights[r * kColumns + c];
        }
        cdf[kColumns] = 1.0f;
        d.m_row_cdf[r] = static_cast<float>(row_sum / total);
        row_sum += in_row;
    }
    d.m_row_cdf[kRows] = 1.0f;
    return d;
}

Vec3 GuideDistribution::sample(double u, double v, double& pdf) const {
    const int r = invert(m_row_cdf.data(), kRows, u);
    const double row_mass = m_row_cdf[r + 1] - m_row_cdf[r];
    const double ur = std::clamp((u - m_row_cdf[r]) / row_mass, 0.0, 1.0);
    const float* cdf = &m_col_cdf[r * (kColumns + 1)];
    const int c = invert(cdf, kColumns, v);
    const double vc = std::clamp((v - cdf[c]) / (cdf[c + 1] - cdf[c]), 0.0, 1.0);
    pdf = bin_pdf(r * kColumns + c);
    return direction_at(r + ur, c + vc);
}

double GuideDistribution::pdf(const Vec3& dir) const { return bin_pdf(bin_of(dir)); }

double GuideDistribution::bin_pdf(int b) const {
    const int r = b / kColumns, c = b % kColumns;
    const float* cdf = &m_col_cdf[r * (kColumns + 1)];
    // The sampler's own density: the row's marginal times the column's conditional, over the bin's solid angle.
    return (static_cast<double>(m_row_cdf[r + 1]) - m_row_cdf[r]) * (static_cast<double>(cdf[c + 1]) - cdf[c]) /
           bin_solid_angle(c);
}

PathGuide PathGuide::build(const std::vector<GuideSample>& samples) {
    PathGuide guide;
    std::vector<std::uint32_t> all;
    Vec3 lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
    for (std::size_t i = 0; i < samples.size(); ++i) {
        const GuideSample& s = samples[i];
        if (!std::isfinite(s.radiance) || s.radiance < 0.0f) continue;
        const Vec3 p = to_vec(s.p);
        if (!is_finite(p)) continue;
        lo = Vec3{std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
        hi = Vec3{std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
        all.push_back(static_cast<std::uint32_t>(i));
    }
    if (all.empty()) return guide;
    const std::size_t leaf_samples = std::max<std::size_t>(1024, static_cast<std::size_t>(4.0 * std::sqrt(all.size())));
    const double extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z, 1e-9});
    guide.m_size = extent * 1.001;
    guide.m_min = lo - Vec3{1, 1, 1} * (extent * 0.0005);
    const auto& cosines = clamped_cosines();

    // Each leaf: the mean radiance per bin, pulled towards the leaf's mean by one pseudo-sample so that a bin no
    // pilot ray went through is neither trusted nor ruled out; then one density per axis.
    const auto make_leaf = [&](const std::vector<std::uint32_t>& idx) {
        std::array<double, kBins> sum{}, count{};
        double total = 0.0;
        for (std::uint32_t i : idx) {
            const GuideSample& s = samples[i];
            const int b = bin_of(normalize(to_vec(s.dir)));
            sum[b] += s.radiance;
            count[b] += 1.0;
            total += s.radiance;
        }
        const double prior = idx.empty() ? 0.0 : total / static_cast<double>(idx.size());
        std::array<double, kBins> mean{};
        for (int b = 0; b < kBins; ++b) mean[b] = (sum[b] + prior) / (count[b] + 1.0);
        Leaf leaf;
        for (int a = 0; a < 6; ++a) {
            std::array<double, kBins> w{};
            double wsum = 0.0;
            for (int b = 0; b < kBins; ++b) {
                w[b] = mean[b] * cosines[a][b] * bin_solid_angle(b % kColumns);
                wsum += w[b];
            }
            leaf.valid[a] = wsum > 0.0 && std::isfinite(wsum);
            if (leaf.valid[a]) leaf.axes[a] = GuideDistribution::from_weights(w);
        }
        guide.m_leaves.push_back(leaf);
        return static_cast<std::int32_t>(guide.m_leaves.size() - 1);
    };
    // Split a node while it holds too many vertices: the octants in a fixed order, each keeping the input order.
    guide.m_nodes.push_back(Node{});
    struct Task {
        std::int32_t node;
        std::vector<std::uint32_t> idx;
        Vec3 origin;
        double size;
        int depth;
    };
    std::vector<Task> stack;
    stack.push_back({0, std::move(all), guide.m_min, guide.m_size, 0});
    while (!stack.empty()) {
        Task t = std::move(stack.back());
        stack.pop_back();
        if (t.idx.size() <= leaf_samples || t.depth >= kMaxDepth) {
            guide.m_nodes[t.node].leaf = make_leaf(t.idx);
            continue;
        }
        const double half = 0.5 * t.size;
        const Vec3 mid = t.origin + Vec3{half, half, half};
        std::array<std::vector<std::uint32_t>, 8> parts;
        for (std::uint32_t i : t.idx) {
            const Vec3 p = to_vec(samples[i].p);
            parts[(p.x >= mid.x ? 1 : 0) | (p.y >= mid.y ? 2 : 0) | (p.z >= mid.z ? 4 : 0)].push_back(i);
        }
        const auto first = static_cast<std::int32_t>(guide.m_nodes.size());
        guide.m_nodes[t.node].child = first;
        guide.m_nodes.resize(guide.m_nodes.size() + 8);
        for (int k = 7; k >= 0; --k) {
            const Vec3 o = t.origin + Vec3{(k & 1) ? half : 0.0, (k & 2) ? half : 0.0, (k & 4) ? half : 0.0};
            stack.push_back({first + k, std::move(parts[k]), o, half, t.depth + 1});
        }
    }
    return guide;
}

const GuideDistribution* PathGuide::find(const Vec3& p, const Vec3& n) const {
    if (m_nodes.empty()) return nullptr;
    Vec3 origin = m_min;
    double size = m_size;
    const Node* node = &m_nodes[0];
    while (node->child >= 0) {
        size *= 0.5;
        const Vec3 mid = origin + Vec3{size, size, size};
        const int k = (p.x >= mid.x ? 1 : 0) | (p.y >= mid.y ? 2 : 0) | (p.z >= mid.z ? 4 : 0);
        origin = Vec3{(k & 1) ? mid.x : origin.x, (k & 2) ? mid.y : origin.y, (k & 4) ? mid.z : origin.z};
        node = &m_nodes[node->child + k];
    }
    const Leaf& leaf = m_leaves[node->leaf];
    const double ax = std::fabs(n.x), ay = std::fabs(n.y), az = std::fabs(n.z);
    const int a = ax >= ay && ax >= az ? (n.x >= 0.0 ? 0 : 1) : ay >= az ? (n.y >= 0.0 ? 2 : 3) : (n.z >= 0.0 ? 4 : 5);
    return leaf.valid[a] ? &leaf.axes[a] : nullptr;
}

}  // namespace wardray::lighting
