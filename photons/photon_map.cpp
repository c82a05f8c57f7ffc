// PhotonMap: packing photons as POV-Ray 3.7 does, the balanced kd-tree, the k-nearest gather and POV-Ray's
// estimate of the gather radius (Jensen 1996, "Global Illumination using Photon Maps", sec. 3 and 4).
#include "photons/photon_map.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/render_seed.h"
#include "photons/photon_random.h"

namespace wardray::photons {

int flux_exponent_offset(double spacing, int dimensions) {
    // Zero below a spacing of 1/32, where POV-Ray's byte holds its photons (a flux of spacing^n up to 2^5), so the
    // maps are POV-Ray's there; beyond, the offset follows the spacing's binade, and the stored flux stays as it is
    // at that spacing.
    if (!(spacing > 0.0) || !std::isfinite(spacing)) return 0;
    return std::max(0, dimensions * (std::ilogb(spacing) + 6));
}

Photon make_photon(const Vec3& position, const Vec3& colour, const Vec3& origin, int exponent_offset) {
    Photon ph;
    ph.position = {static_cast<float>(position.x), static_cast<float>(position.y), static_cast<float>(position.z)};
    // Ward's RGBE: a shared exponent, 8-bit mantissas; POV-Ray biases the exponent by 250 for dim photons. The
    // map's power-of-two offset comes off the exponent alone, so the mantissas are POV-Ray's at any offset, and a
    // flux of spacing² or spacing³ stays in the byte's range (POV-Ray's wraps round past 2^5, at large scales).
    const float c[3] = {static_cast<float>(colour.x), static_cast<float>(colour.y), static_cast<float>(colour.z)};
    const float v = std::max(c[0], std::max(c[1], c[2]));
    int e = 0;
    if (v > 0.0f) std::frexp(v, &e);
    const int biased = e - exponent_offset + 250;
    if (!(std::ldexp(static_cast<double>(v), -exponent_offset) >= static_cast<double>(1e-32f)) || biased < 1) {
        ph.rgbe = {0, 0, 0, 0};
    } else if (biased > 255 && exponent_offset > 0) {
        ph.rgbe = {255, 255, 255, 255};
    } else {
        // POV-Ray compat: without an offset, a flux of 2^5 or more wraps round in the byte, as POV-Ray's does.
        const float scale = static_cast<float>(std::frexp(v, &e) * 256.0 / v);
        for (int i = 0; i < 3; ++i) ph.rgbe[i] = static_cast<std::uint8_t>(std::max(0.0f, c[i] * scale));
        ph.rgbe[3] = static_cast<std::uint8_t>(biased & 255);
    }
    // The direction towards the origin as two angles of 127 steps per π (POV-Ray's addSurfacePhoton).
    const Vec3 d = normalize(origin - position);
    const double horizontal = std::sqrt(d.x * d.x + d.z * d.z);
    double phi = horizontal > 0.0 ? std::acos(std::clamp(d.x / horizontal, -1.0, 1.0)) : 0.0;
    if (d.z < 0.0) phi = -phi;
    double theta = std::acos(std::min(1.0, horizontal));
    if (d.y < 0.0) theta = -theta;
    ph.theta = static_cast<std::int8_t>(theta * 127.0 / std::numbers::pi);
    ph.phi = static_cast<std::int8_t>(phi * 127.0 / std::numbers::pi);
    return ph;
}

Vec3 photon_colour(const Photon& p, int exponent_offset) {
    if (p.rgbe[3] == 0) return {};
    const float f = static_cast<float>(std::ldexp(1.0, static_cast<int>(p.rgbe[3]) - (250 + 8) + exponent_offset));
    return {p.rgbe[0] * f, p.rgbe[1] * f, p.rgbe[2] * f};
}

bool beyond_povray_flux(const Photon& p, int exponent_offset) {
    // Without an offset the byte wraps as POV-Ray's does; with one, make_photon clamps a flux beyond the byte even
    // with its offset to all 255s.
    if (exponent_offset <= 0) return false;
    const bool clamped = p.rgbe[0] == 255 && p.rgbe[1] == 255 && p.rgbe[2] == 255 && p.rgbe[3] == 255;
    return clamped || (p.rgbe[3] != 0 && static_cast<int>(p.rgbe[3]) + exponent_offset > 255);
}

Vec3 photon_direction(const Photon& p) {
    // The sines and cosines of the 256 angles a byte encodes (k·π/127), computed once: a media gather decodes
    // every photon it finds.
    struct Table {
        double sin[256], cos[256];
        Table() {
            for (int k = -128; k < 128; ++k) {
                const double a = k * std::numbers::pi / 127.0;
                sin[k + 128] = std::sin(a);
                cos[k + 128] = std::cos(a);
            }
        }
    };
    static const Table table;
    const int theta = p.theta + 128, phi = p.phi + 128;
    return {table.cos[theta] * table.cos[phi], table.sin[theta], table.cos[theta] * table.sin[phi]};
}

PhotonMap::PhotonMap(std::vector<Photon> photons, const scene::PhotonSettings& settings, bool media,
                     std::uint64_t seed, int exponent_offset)
    : m_photons(std::move(photons)),
      m_gather_max(settings.gather_max),
      m_gather_min(settings.gather_min),
      m_expand_tolerance(settings.expand_tolerance),
      m_expand_min(settings.expand_min),
      m_exponent_offset(exponent_offset) {
    if (m_photons.empty()) return;
    // Boxes for the top of the tree (about one per 8 photons): enough to skip a subtree whose photons all lie off
    // a query's reach, as the planes of the cells alone cannot when the photons cover a thin layer.
    std::size_t boxes = 1;
    while (boxes * 16 <= m_photons.size()) boxes *= 2;
    m_boxes.resize(boxes);
    build(0, static_cast<int>(m_photons.size()), 1);
    estimate_radius(settings, media, seed);
}

void PhotonMap::build(int begin, int end, std::size_t id) {
    if (end - begin < 1) return;
    // Split at the median of the axis along which the photons spread most (a balanced kd-tree, stored implicitly:
    // the node of [begin, end) is its middle element).
    float lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (int i = begin; i < end; ++i)
        for (int a = 0; a < 3; ++a) {
            lo[a] = std::min(lo[a], m_photons[i].position[a]);
            hi[a] = std::max(hi[a], m_photons[i].position[a]);
        }
    if (id < m_boxes.size()) m_boxes[id] = {lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]};
    int axis = 0;
    for (int a = 1; a < 3; ++a)
        if (hi[a] - lo[a] > hi[axis] - lo[axis]) axis = a;
    const int mid = (begin + end - 1) / 2;
    std::nth_element(m_photons.begin() + begin, m_photons.begin() + mid, m_photons.begin() + end,
                     [axis](const Photon& a, const Photon& b) { return a.position[axis] < b.position[axis]; });
    m_photons[mid].axis = static_cast<std::uint8_t>(axis);
    build(begin, mid, 2 * id);
    build(mid + 1, end, 2 * id + 1);
}

namespace {

/// A candidate photon: its (flattened) squared distance, then its address, which breaks ties the same on every run.
using Candidate = std::pair<double, const Photon*>;

/// Keeps the nearest `limit` of more than `limit` candidates, and shrinks the reach to the farthest of them.
void keep_nearest(std::vector<Candidate>& found, std::size_t limit, double& max_d2) {
    std::nth_element(found.begin(), found.begin() + static_cast<std::ptrdiff_t>(limit - 1), found.end());
    max_d2 = found[limit - 1].first;
    found.resize(limit);
}

// Below this many photons a subtree is read whole rather than pruned cell by cell.
constexpr int kLeaf = 8;

// Every photon of the subtree [begin, end) of the tree's array, in the order the pruned walk meets them: each node,
// then the side of its split that `p` lies on, then the other.
template <typename Consider>
void scan(const std::vector<Photon>& photons, int begin, int end, const Vec3& p, Consider& consider) {
    while (end > begin) {
        const int mid = (begin + end - 1) / 2;
        const Photon& ph = photons[static_cast<std::size_t>(mid)];
        consider(ph);
        const int axis = ph.axis;
        const double delta = (axis == 0 ? p.x : axis == 1 ? p.y : p.z) - ph.position[axis];
        if (delta < 0.0) {
            scan(photons, begin, mid, p, consider);
            begin = mid + 1;
        } else {
            scan(photons, mid + 1, end, p, consider);
            end = mid;
        }
    }
}

}  // namespace

void PhotonMap::search(const Vec3& p, const Vec3* n, double& max_d2, std::size_t limit,
                       std::vector<Candidate>& found) const {
    // Depth first, near side first, as a recursion would (the order decides which of two photons at exactly the
    // same distance is kept). A far side is visited only while its cell is within reach: the squared distance from
    // p to the cell, kept per axis as the walk goes down (Arya & Mount 1993, "Algorithms for fast vector
    // quantization": incremental distance), prunes more than the distance to the one splitting plane. Pruning
    // skips only photons that could not be kept, so the photons found are the same. The tree is balanced, so 64
    // levels hold any map.
    struct Cell {
        int begin, end;
        std::size_t id;     // the node (see build)
        double d2;          // squared distance from p to the cell
        double offset[3];   // p's distance outside the cell along each axis
    };
    // Near the top of the tree the cell shrinks to its photons' box, which lies inside it: p's distance to it along
    // each axis is no less than to the cell, and the splits below stay within it, so the walk goes on as above.
    const auto tighten = [&](Cell& c) {
        if (c.id >= m_boxes.size()) return;
        const std::array<float, 6>& b = m_boxes[c.id];
        const double q[3] = {p.x, p.y, p.z};
        c.d2 = 0.0;
        for (int a = 0; a < 3; ++a) {
            c.offset[a] = q[a] < b[a] ? b[a] - q[a] : q[a] > b[a + 3] ? q[a] - b[a + 3] : 0.0;
            c.d2 += c.offset[a] * c.offset[a];
        }
    };
    Cell pending[64];
    int n_pending = 0;
    Cell cell{0, static_cast<int>(m_photons.size()), 1, 0.0, {0.0, 0.0, 0.0}};
    tighten(cell);
    if (!(cell.d2 * (1.0 - 1e-12) < max_d2)) return;
    const auto consider = [&](const Photon& ph) {
        const Vec3 v = ph.point() - p;
        double d2 = dot(v, v);
        // POV-Ray's flattened gather: a disc more than a sphere, d² · (1 + 16·|n·v|).
        if (n && d2 < max_d2) d2 += std::fabs(dot(*n, v)) * d2 * 16.0;
        if (!(d2 < max_d2)) return;
        // Candidates pile up to twice the limit; then the nearest `limit` are kept and the reach shrinks to the
        // farthest of them (a found kept per photon costs more, as most photons in reach are replaced later).
        found.push_back({d2, &ph});
        if (found.size() >= 2 * limit) keep_nearest(found, limit, max_d2);
    };
    for (;;) {
        while (cell.end - cell.begin >= 1) {
            // A small subtree is read straight through, in the tree's order (each node before its two sides, the
            // near side first), without the bookkeeping of its cells: fewer than kLeaf photons cost less to test
            // than to prune.
            if (cell.end - cell.begin <= kLeaf) {
                scan(m_photons, cell.begin, cell.end, p, consider);
                break;
            }
            const int mid = (cell.begin + cell.end - 1) / 2;
            const Photon& ph = m_photons[mid];
            consider(ph);
            const int axis = ph.axis;
            const double delta = (axis == 0 ? p.x : axis == 1 ? p.y : p.z) - ph.position[axis];
            Cell& far = pending[n_pending++];
            far = cell;
            far.d2 += delta * delta - cell.offset[axis] * cell.offset[axis];
            far.offset[axis] = delta;
            if (delta < 0.0) {
                far.begin = mid + 1;
                far.id = 2 * cell.id + 1;
                cell.end = mid;
                cell.id = 2 * cell.id;
            } else {
                far.end = mid;
                far.id = 2 * cell.id;
                cell.begin = mid + 1;
                cell.id = 2 * cell.id + 1;
            }
            tighten(far);
            tighten(cell);
            // The near side too is left when its box is out of reach.
            if (!(cell.d2 * (1.0 - 1e-12) < max_d2)) break;
        }
        // The far side once the near one is done, while its cell is within reach. The cell's distance is summed in
        // another order than a photon's own, so it is shaded down by a trillionth: rounding can then only visit a
        // cell too many, never skip a photon at the cell's nearest corner.
        for (;;) {
            if (n_pending == 0) {
                if (found.size() > limit) keep_nearest(found, limit, max_d2);
                return;
            }
            cell = pending[--n_pending];
            if (cell.d2 * (1.0 - 1e-12) < max_d2) break;
        }
    }
}

void PhotonMap::gather(const Vec3& p, double size, const Vec3* n, Gathered& out) const {
    out.photons.clear();
    out.radius = size;
    out.exponent_offset = m_exponent_offset;
    if (m_photons.empty() || m_gather_max <= 0) return;
    // One buffer per thread: a gather runs at every lit surface point.
    thread_local std::vector<Candidate> found;
    found.clear();
    found.reserve(2 * static_cast<std::size_t>(m_gather_max));
    double max_d2 = size * size;
    search(p, n, max_d2, static_cast<std::size_t>(m_gather_max), found);
    out.radius = std::sqrt(max_d2);
    // Nearest first, ties by storage order, so the sum's rounding is the same on every run.
    std::sort(found.begin(), found.end());
    out.photons.reserve(found.size());
    for (const auto& e : found) out.photons.push_back(e.second);
}

void PhotonMap::gather_adaptive(const Vec3& p, const Vec3* n, Gathered& out) const {
    gather(p, m_min_radius, n, out);
    double previous = out.photons.size() / (out.radius * out.radius);
    if (previous == 0.0) previous = 1e-16;
    // POV-Ray's gatherNumSteps is 2: at most one wider gather, at the radius plus twice it.
    if (static_cast<int>(out.photons.size()) >= m_gather_min) return;
    thread_local Gathered wider;
    gather(p, m_min_radius + m_radius_step, n, wider);
    const double density = wider.photons.size() / (wider.radius * wider.radius);
    const int found = static_cast<int>(wider.photons.size());
    if ((density - previous) / previous < m_expand_tolerance || (found < m_expand_min && found > 0))
        std::swap(out, wider);
}

void PhotonMap::estimate_radius(const scene::PhotonSettings& settings, bool media, std::uint64_t seed) {
    m_min_radius = media ? settings.media_radius : settings.radius;
    // The photons' density around a point: per area on surfaces, per volume in media (4/3 π r³).
    auto density_of = [media](const Gathered& g) {
        const double r = g.radius;
        return media ? 3.0 * g.photons.size() / (4.0 * std::numbers::pi * r * r * r)
                     : g.photons.size() / (std::numbers::pi * r * r);
    };
    if (m_min_radius <= 0.0) {
        // POV-Ray's setGatherOptions: the mean density of the gather_max photons around sampled photons gives the
        // radius that holds gather_max photons on average; it grows by up to 21 times with the fraction of
        // samples whose density at that radius is under 70 % (but over 5 %) of the mean.
        const int n = static_cast<int>(m_photons.size());
        const int samples = std::clamp(n / 20, 100, 1000);
        Random rng(reseed(0x50484F544F4E53ull, seed));
        Gathered g;
        double sum = 0.0;
        for (int i = 0; i < samples; ++i) {
            gather(m_photons[rng.below(n)].point(), 10000000.0, nullptr, g);
            const double density = g.radius > 0.0 ? density_of(g) : (i > 0 ? sum / i : 0.0);
            sum += density;
        }
        const double mean = sum / samples;
        // POV-Ray compat: the cube root is pow(x, 0.3333).
        m_min_radius = !(mean > 0.0) ? 1.0
                       : media       ? std::pow(3.0 * m_gather_max / (mean * std::numbers::pi * 4.0), 0.3333)
                                     : std::sqrt(m_gather_max / (mean * std::numbers::pi));
        int sparse = 0;
        for (int i = 0; i < samples; ++i) {
            gather(m_photons[rng.below(n)].point(), m_min_radius, nullptr, g);
            if (g.radius <= 0.0) continue;
            const double density = density_of(g);
            if (density < mean * 0.7 && density > mean * 0.05) ++sparse;
        }
        m_min_radius *= 1.0 + 20.0 * static_cast<double>(sparse) / samples;
    }
    m_min_radius *= media ? settings.media_radius_multiplier : settings.radius_multiplier;
    // POV-Ray compat: a media map's radius is doubled.
    if (media) m_min_radius *= 2.0;
    m_radius_step = m_min_radius * 2.0;
}

double MediaPhotonGather::gather(const Vec3& p, std::vector<Sample>& out) const {
    // One list per thread: a media sample gathers at every step of every ray through the medium.
    thread_local Gathered g;
    m_map.gather_adaptive(p, nullptr, g);
    out.clear();
    for (const Photon* ph : g.photons) out.push_back({photon_colour(*ph, g.exponent_offset), photon_direction(*ph)});
    return g.radius;
}

}  // namespace wardray::photons
