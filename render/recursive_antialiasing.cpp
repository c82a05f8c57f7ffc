// Method 2 antialiasing (+AM2): POV-Ray 3.7's adaptive recursive supersampling of each pixel from its corners.
#include <vector>

#include "render/sampler.h"

namespace wardray::render {

namespace {

/// One pixel's grid of samples, (2^depth + 1)² positions from corner to corner, each traced at most once.
class SubdivisionGrid {
public:
    explicit SubdivisionGrid(int size) : m_size(size), m_colour(size * size), m_sampled(size * size, 0) {}
    void clear() { std::fill(m_sampled.begin(), m_sampled.end(), 0); }
    bool sampled(int i, int j) const { return m_sampled[j * m_size + i] != 0; }
    const Rgbt& at(int i, int j) const { return m_colour[j * m_size + i]; }
    void set(int i, int j, const Rgbt& c) {
        m_colour[j * m_size + i] = c;
        m_sampled[j * m_size + i] = 1;
    }

private:
    int m_size;
    std::vector<Rgbt> m_colour;
    std::vector<char> m_sampled;
};

struct Subdivider {
    const Sampler& sample;
    const AntialiasSettings& aa;
    SubdivisionGrid& grid;
    double jitter_scale;
    std::uint64_t seed;

    // A sample at image position (px, py) into grid point (i, j) unless it has one; jittered as POV-Ray does.
    void fill(int i, int j, double px, double py) {
        if (grid.sampled(i, j)) return;
        const Vec3 jit = jitter_scale > 0.0 ? jitter_at(px, py, seed) * jitter_scale : Vec3{};
        grid.set(i, j, sample(px + jit.x, py + jit.y));
    }

    // POV-Ray's SubdivideOnePixel: the square of half-width d centred on (cx, cy), its corners at grid (i, j) and
    // (i + step, j + step). When any two corners differ by the threshold and levels remain, the edge midpoints and
    // the centre are traced and each quarter is subdivided; else the square is its corners' mean.
    Rgbt subdivide(double cx, double cy, double d, int i, int j, int step, int level) {
        const Rgbt c00 = grid.at(i, j), c01 = grid.at(i, j + step);
        const Rgbt c10 = grid.at(i + step, j), c11 = grid.at(i + step, j + step);
        const double g = aa.gamma, t = aa.threshold;
        const bool differ = encoded_distance(c00, c01, g) >= t || encoded_distance(c00, c10, g) >= t ||
                            encoded_distance(c00, c11, g) >= t || encoded_distance(c01, c10, g) >= t ||
                            encoded_distance(c01, c11, g) >= t || encoded_distance(c10, c11, g) >= t;
        if (level <= 0 || !differ) return (c00 + c01 + c10 + c11) / 4.0;
        const int half = step / 2;
        fill(i, j + half, cx - d, cy);
        fill(i + half, j, cx, cy - d);
        fill(i + step, j + half, cx + d, cy);
        fill(i + half, j + step, cx, cy + d);
        fill(i + half, j + half, cx, cy);
        const double d2 = 0.5 * d;
        return (subdivide(cx - d2, cy - d2, d2, i, j, half, level - 1) +
                subdivide(cx - d2, cy + d2, d2, i, j + half, half, level - 1) +
                subdivide(cx + d2, cy - d2, d2, i + half, j, half, level - 1) +
                subdivide(cx + d2, cy + d2, d2, i + half, j + half, half, level - 1)) /
               4.0;
    }
};

}  // namespace

void render_block_recursive(const Sampler& sample, Film& film, int x0, int y0, int x1, int y1,
                            const AntialiasSettings& aa, std::uint64_t seed, TileCounters& counters) {
    // Every pixel corner of the block, traced unjittered; the block's far edges are its neighbours' corners, traced
    // again here so that a block depends on nothing outside it.
    const int w = x1 - x0 + 1;
    const int h = y1 - y0 + 1;
    std::vector<Rgbt> corner(static_cast<std::size_t>(w) * h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) corner[y * w + x] = sample(x0 + x, y0 + y);
    const int size = 1 << aa.depth;
    SubdivisionGrid grid(size + 1);
    // POV-Ray compat: the jitter is scaled down by the finest grid's spacing.
    Subdivider sub{sample, aa, grid, aa.jitter / (size + 1.0), seed};
    for (int y = 0; y < h - 1; ++y) {
        for (int x = 0; x < w - 1; ++x) {
            grid.clear();
            grid.set(0, 0, corner[y * w + x]);
            grid.set(0, size, corner[(y + 1) * w + x]);
            grid.set(size, 0, corner[y * w + x + 1]);
            grid.set(size, size, corner[(y + 1) * w + x + 1]);
            const Rgbt c = sub.subdivide(x0 + x + 0.5, y0 + y + 0.5, 0.5, 0, 0, size, aa.depth - 1);
            if (grid.sampled(size / 2, size / 2)) ++counters.supersampled;
            sample.store(film, x0 + x, y0 + y, c);
        }
    }
}

}  // namespace wardray::render
