// Pavement: POV-Ray 3.7's `pavement` pattern. The plane y = 0 is cut into unit squares or into equilateral triangles
// of side 1 (hexagons are six triangles), and each cell has a code: which of its edges are a paver's boundary, which
// of its corners are inner corners of a paver, and which are rounded or cut by `form`. The value is 0 in a paver's
// body and rises to 1 on its boundary. Which paver repeats how is POV-Ray's own paving for each number_of_sides,
// number_of_tiles and pattern (texture/pavement_pavings.cpp).
#include "texture/pavement.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include "texture/pavement_pavings.h"

namespace wardray::texture {

namespace {

long wrap(long a, long m) {
    const long r = a % m;
    return r < 0 ? r + m : r;
}

std::uint16_t cell_code(const Paving& paving, long xv, long zv) {
    const Lattice& l = paving.lattice;
    long column = 0;
    long row = 0;
    if (l.along_x) {
        const long xm = wrap(xv, l.period);
        row = wrap(zv + l.shear * (xm / l.step), l.rows);
        column = xm % l.width;
    } else {
        const long zm = wrap(zv, l.period);
        column = wrap(xv + l.shear * (zm / l.step), l.width);
        row = zm % l.rows;
    }
    return paving.cells[static_cast<std::size_t>(column + l.width * row)];
}

/// The paving of a pattern, or null when its numbers are outside the tables (the parser refuses those).
const Paving* find_paving(const std::vector<std::vector<Paving>>& table, const scene::PavementParams& pv) {
    if (pv.tiles < 1 || pv.tiles > static_cast<int>(table.size())) return nullptr;
    const auto& of_tiles = table[static_cast<std::size_t>(pv.tiles - 1)];
    if (pv.number < 1 || pv.number > static_cast<int>(of_tiles.size())) return nullptr;
    return &of_tiles[static_cast<std::size_t>(pv.number - 1)];
}

/// A corner's distance in half-cell units by the shape `shape` gives it: 0 square (the larger offset), 1 cut (their
/// sum), 2 round (Euclidean).
double corner_distance(int shape, double u, double v) {
    if (shape == 0) return std::max(u, v);
    if (shape == 1) return u + v;
    return std::sqrt(u * u + v * v);
}

// A unit square's corners, in the order POV-Ray tries their forms: where it is, its bit (an inner corner of the
// paver), the two edges meeting there (bits 0x01 top z = 1, 0x02 right x = 1, 0x04 bottom z = 0, 0x08 left x = 0)
// and the corner across the square.
struct SquareCorner {
    int x;
    int z;
    std::uint16_t bit;
    std::uint16_t edges;
    int across;
};
constexpr SquareCorner k_square_corners[4] = {
    {1, 0, 0x40, 0x06, 2}, {0, 0, 0x80, 0x0C, 3}, {0, 1, 0x10, 0x09, 0}, {1, 1, 0x20, 0x03, 1}};

double square_value(const scene::PavementParams& pv, const Vec3& p) {
    const Paving* paving = find_paving(square_pavings(), pv);
    if (paving == nullptr) return 0.0;
    const double fx = std::floor(p.x);
    const double fz = std::floor(p.z);
    const std::uint16_t code = cell_code(*paving, static_cast<long>(fx), static_cast<long>(fz));
    const double x = p.x - fx;
    const double z = p.z - fz;
    // Twice the offsets from a corner.
    auto offsets = [&](const SquareCorner& c) {
        return std::pair{c.x == 0 ? 2.0 * x : 2.0 - 2.0 * x, c.z == 0 ? 2.0 * z : 2.0 - 2.0 * z};
    };
    // form 0 to 2: a paver's outer corner (two edges, the corner across flagged) is a quarter ring about the corner
    // across; form 3 leaves it sharp.
    if (pv.form < 3) {
        for (const SquareCorner& c : k_square_corners) {
            const SquareCorner& across = k_square_corners[c.across];
            const std::uint16_t need = c.edges | across.bit;
            if ((code & need) != need) continue;
            const auto [u, v] = offsets(across);
            return std::min(std::fabs(corner_distance(pv.form, u, v) - 1.0), 1.0);
        }
    }
    // The edges: 0 at the cell's middle line, 1 on the edge.
    double value = 0.0;
    if (code & 0x01) value = std::max(value, 2.0 * z - 1.0);
    if (code & 0x02) value = std::max(value, 2.0 * x - 1.0);
    if (code & 0x04) value = std::max(value, 1.0 - 2.0 * z);
    if (code & 0x08) value = std::max(value, 1.0 - 2.0 * x);
    // Inner corners, shaped by `interior`.
    for (const SquareCorner& c : k_square_corners) {
        if (!(code & c.bit)) continue;
        const auto [u, v] = offsets(c);
        value = std::max(value, 1.0 - corner_distance(pv.interior, u, v));
    }
    // Outer corners, shaped by `exterior`: 1 cuts them, 2 rounds them about the cell's centre.
    const double a = 2.0 * x - 1.0;
    const double b = 2.0 * z - 1.0;
    bool rounded = false;
    for (const SquareCorner& c : k_square_corners) {
        if ((code & c.edges) != c.edges) continue;
        if (pv.exterior == 1) {
            const auto [u, v] = offsets(c);
            value = std::max(value, std::min(2.0 - (u + v), 1.0));
        } else if (pv.exterior == 2) {
            rounded = rounded || ((c.x == 1 ? a >= 0.0 : a <= 0.0) && (c.z == 1 ? b >= 0.0 : b <= 0.0));
        }
    }
    if (rounded) value = std::max(value, std::min(std::sqrt(a * a + b * b), 1.0));
    return value;
}

constexpr double kSqrt3 = std::numbers::sqrt3;
constexpr double kHalfSqrt3 = std::numbers::sqrt3 / 2.0;

/// A point in the triangle grid: the triangle's indices (x counts half triangles, odd for the downward ones; z
/// counts rows) and the point in the upward triangle (0, 0), (1, 0), (1/2, √3/2) the triangle is turned onto.
struct TrianglePoint {
    long xv;
    long zv;
    double x;
    double z;
};

TrianglePoint locate_triangle(const Vec3& p) {
    // Rows of height √3 hold two rows of triangles; the upper one is shifted half a side.
    const double fx = std::floor(p.x);
    const double fz = std::floor(p.z / kSqrt3);
    TrianglePoint t{2 * static_cast<long>(fx), 2 * static_cast<long>(fz), p.x - fx, p.z - kSqrt3 * fz};
    if (t.z > kHalfSqrt3) {
        t.z -= kHalfSqrt3;
        if (t.x > 0.5) {
            t.x -= 0.5;
            ++t.xv;
        } else {
            t.x += 0.5;
            --t.xv;
        }
        ++t.zv;
    }
    // Left or right of the upward triangle: the downward neighbour, turned half a turn onto it.
    if (t.x == 0.0 || t.z / t.x > kSqrt3) {
        t.z = kHalfSqrt3 - t.z;
        t.x = 0.5 - t.x;
        --t.xv;
    }
    if (t.x == 1.0 || t.z / (1.0 - t.x) > kSqrt3) {
        t.z = kHalfSqrt3 - t.z;
        t.x = 1.5 - t.x;
        ++t.xv;
    }
    return t;
}

/// A vertex of the upward triangle: where it is, the code bits whose absence makes it a paver's inner corner (its
/// two edges and 0x80), and the bit that makes it one whatever the edges say (hexagon pavings).
struct TriangleVertex {
    double x;
    double z;
    std::uint16_t edges;
    std::uint16_t inner;
};
constexpr TriangleVertex k_apex{0.5, kHalfSqrt3, 0x83, 0x4000};
constexpr TriangleVertex k_origin{0.0, 0.0, 0x85, 0x2000};
constexpr TriangleVertex k_right{1.0, 0.0, 0x86, 0x1000};

bool is_inner(std::uint16_t code, const TriangleVertex& v) { return (code & v.edges) == 0 || (code & v.inner) != 0; }

double distance_to(const TrianglePoint& t, const TriangleVertex& v) {
    const double dx = t.x - v.x;
    const double dz = t.z - v.z;
    return std::sqrt(dx * dx + dz * dz);
}

// The sixths of the triangle a corner's form applies in, told by the signs of three lines through its centre.
enum class Sixth { BelowBoth, LeftOfMiddle, RightOfMiddle };

/// A corner `form` can shape: the code bits it needs, the part of the triangle, the vertex it rounds about, and the
/// line (1 to 3, signed) it cuts along.
struct TriangleForm {
    std::uint16_t bits;
    Sixth where;
    const TriangleVertex* vertex;
    int line;
};
const TriangleForm k_triangle_forms[6] = {
    {0x120, Sixth::BelowBoth, &k_origin, -1},    {0x140, Sixth::LeftOfMiddle, &k_apex, 1},
    {0x210, Sixth::BelowBoth, &k_right, -2},     {0x240, Sixth::RightOfMiddle, &k_apex, 2},
    {0x410, Sixth::LeftOfMiddle, &k_right, 3},   {0x420, Sixth::RightOfMiddle, &k_origin, -3}};

// Triangle cells: edges 0x01 (left, origin to apex), 0x02 (right, apex to (1, 0)) and 0x04 (the base) are a paver's
// boundary; the vertices are inner corners as TriangleVertex says; 0x10..0x400 mark the corners form shapes.
double triangle_value(const scene::PavementParams& pv, const Paving& paving, const Vec3& p, bool with_exterior) {
    const TrianglePoint t = locate_triangle(p);
    const std::uint16_t code = cell_code(paving, t.xv, t.zv);
    const double x = t.x;
    const double z = t.z;
    // The edges: 0 at the triangle's centre, 1 on the edge.
    double value = 0.0;
    if (code & 0x01) value = std::max(value, 1.0 - std::fabs(kSqrt3 * x - z) * kSqrt3);
    if (code & 0x02) value = std::max(value, 1.0 - std::fabs(kSqrt3 * (1.0 - x) - z) * kSqrt3);
    if (code & 0x04) value = std::max(value, 1.0 - z * 2.0 * kSqrt3);
    // Lines through the centre and a vertex: their signs tell the sixths of the triangle.
    const double d1 = 1.0 - std::fabs(kSqrt3 * z + x);
    const double d2 = 1.0 - std::fabs(kSqrt3 * z - x + 1.0);
    const double d3 = 1.0 - x * 2.0;
    // Inner corners, shaped by `interior`: 0 square, 1 cut, 2 round.
    const bool apex = is_inner(code, k_apex);
    const bool origin = is_inner(code, k_origin);
    const bool right = is_inner(code, k_right);
    if (pv.interior == 1) {
        if (apex && d1 < 0.0 && d2 < 0.0)
            value = std::max(value, std::min(1.5 * std::fabs(kSqrt3 * z + x) - 2.0,
                                             1.5 * std::fabs(kSqrt3 * z - x + 1.0) - 2.0));
        if (origin && d1 > 0.0 && d3 > 0.0)
            value = std::max(value, std::min(1.0 - 1.5 * std::fabs(kSqrt3 * z + x), 1.0 - x * 3.0));
        if (right && d3 < 0.0 && d2 > 0.0)
            value = std::max(value, std::min(1.0 - 1.5 * std::fabs(kSqrt3 * z - x + 1.0), x * 3.0 - 2.0));
    } else if (pv.interior == 2) {
        if (apex) value = std::max(value, 1.0 - distance_to(t, k_apex) * 3.0);
        if (origin) value = std::max(value, 1.0 - distance_to(t, k_origin) * 3.0);
        if (right) value = std::max(value, 1.0 - distance_to(t, k_right) * 3.0);
    } else {
        if (apex) value = std::max(value, 1.0 - (kHalfSqrt3 - z) * 2.0 * kSqrt3);
        if (origin) value = std::max(value, 1.0 - std::fabs(kSqrt3 * x + z) * kSqrt3);
        if (right) value = std::max(value, 1.0 - std::fabs(kSqrt3 * (x - 1.0) - z) * kSqrt3);
    }
    // Outer corners (two boundary edges), shaped by `exterior` about the centre (triangle pavings only); POV-Ray
    // compat: the value is replaced, not raised.
    if (with_exterior && pv.exterior == 2) {
        if (((code & 0x03) == 0x03 && d1 <= 0.0 && d2 <= 0.0) || ((code & 0x06) == 0x06 && d2 >= 0.0 && d3 <= 0.0) ||
            ((code & 0x05) == 0x05 && d1 >= 0.0 && d3 >= 0.0)) {
            const double a = x - 0.5;
            const double b = z - kHalfSqrt3 / 3.0;
            value = std::min(1.0, 2.0 * kSqrt3 * std::sqrt(a * a + b * b));
        }
    } else if (with_exterior && pv.exterior == 1) {
        const double e1 = 1.0 - std::fabs(kSqrt3 * x - z) * kSqrt3;
        const double e2 = 1.0 - std::fabs(kSqrt3 * (1.0 - x) - z) * kSqrt3;
        const double e3 = 1.0 - z * 2.0 * kSqrt3;
        const double a = x - 0.5;
        const double b = z - kHalfSqrt3 / 3.0;
        if ((code & 0x03) == 0x03 && e1 >= 0.0 && e2 >= 0.0) value = std::min(1.0, std::fabs(b * 2.0 * kSqrt3));
        if ((code & 0x06) == 0x06 && e2 >= 0.0 && e3 >= 0.0) value = std::min(1.0, std::fabs(kSqrt3 * a - b) * kSqrt3);
        if ((code & 0x05) == 0x05 && e1 >= 0.0 && e3 >= 0.0) value = std::min(1.0, std::fabs(kSqrt3 * a + b) * kSqrt3);
    }
    // form 1 cuts a paver's outer corners along a line, form 2 rounds them; the first that applies decides.
    if (pv.form == 1 || pv.form == 2) {
        const double lines[3] = {d1, d2, d3};
        for (const TriangleForm& f : k_triangle_forms) {
            if ((code & f.bits) != f.bits) continue;
            const bool inside = f.where == Sixth::BelowBoth      ? d1 < 0.0 && d2 < 0.0
                                : f.where == Sixth::LeftOfMiddle ? d1 > 0.0 && d3 > 0.0
                                                                 : d3 < 0.0 && d2 > 0.0;
            if (!inside) continue;
            if (pv.form == 1) {
                const double d = lines[std::abs(f.line) - 1];
                return std::min((f.line < 0 ? -d : d) * 2.0, 1.0);
            }
            const double r = 2.0 * kSqrt3 * (distance_to(t, *f.vertex) - kSqrt3 / 3.0);
            return std::min(std::max(r, 0.0), 1.0);
        }
    }
    return value;
}

}  // namespace

double pavement_pattern(const scene::Pattern& pat, const Vec3& p, int /*generator*/) {
    // POV-Ray compat: the parser wraps these (a texture_map's pattern is not checked there, so here too).
    scene::PavementParams pv = pat.params->pavement;
    pv.exterior %= 3;
    pv.interior %= 3;
    pv.form %= pv.sides == 4 ? 4 : 3;
    if (pv.sides == 4) return square_value(pv, p);
    const bool hexagons = pv.sides == 6;
    const Paving* paving = find_paving(hexagons ? hexagon_pavings() : triangle_pavings(), pv);
    if (paving == nullptr) return 0.0;
    return triangle_value(pv, *paving, p, !hexagons);
}

}  // namespace wardray::texture
