// The tiling pattern, part one: the dispatch over POV-Ray 3.7's 27 tilings and its tilings of squares, rectangles,
// triangles, lozenges and hexagons (1 to 12, 15 and 18). Each tiling folds the plane into a small cell by its
// periods and mirror symmetries, then measures how far the point is from its tile's middle; tiles of different
// kinds own different bands of values. Re-derived from POV-Ray's documented tilings and checked against its renders.
#include "texture/tiling.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "texture/tiling_shapes.h"

namespace wardray::texture {

namespace tiling {

double triangle_in_strip(double x, double z, int& flip) {
    // Above the edge from the origin at 60 degrees lies the neighbouring triangle, pointing the other way: turn
    // the strip half over onto it.
    if (x == 0.0 || z / x > kSqrt3) {
        z = kHalfSqrt3 - z;
        x = 0.5 - x;
        flip = 1 - flip;
    }
    const double bottom = 1.0 - (z * 2 * kSqrt3);
    const double slant = 1.0 - ((kSqrt3 * x - z) * kSqrt3);
    return std::max(bottom, slant);
}

double triangle_in_cell(double x, double z, int& flip) {
    x = wrap(x, 1.0);
    z = wrap(z, kSqrt3);
    if (z > kHalfSqrt3) {  // the upper row of triangles mirrors the lower one, pointing the other way
        z = kSqrt3 - z;
        flip = 1 - flip;
    }
    if (x > 0.5) x = 1.0 - x;
    return triangle_in_strip(x, z, flip);
}

namespace {

// Tiling 1: unit squares.
double square(double x, double z) {
    x = std::fabs(x);
    z = std::fabs(z);
    return std::max(across_unit(x - std::floor(x)), across_unit(z - std::floor(z)));
}

// Tiling 2: hexagons of side 1, one centred at the origin with two sides parallel to x.
double hexagon(double x, double z) {
    x = wrap(x + 0.5, 3.0);
    z = wrap(z, kSqrt3);
    if (z > kHalfSqrt3) z = kSqrt3 - z;
    if (x > 1.5) {  // the right half repeats the left half, upside down
        x -= 1.5;
        z = kHalfSqrt3 - z;
    }
    if ((kSqrt3 * x + z) < kHalfSqrt3) {  // the corner of the neighbouring hexagon
        x = 0.5 - x;
        z = kHalfSqrt3 - z;
    }
    if (x > 1.0) x = 2.0 - x;
    const double flat = 1.0 - (z / kHalfSqrt3);
    const double slant = 1.0 - (((kSqrt3 * x + z - kHalfSqrt3)) / kSqrt3);
    return std::clamp(std::max(flat, slant), 0.0, 1.0);
}

// Tiling 3: triangles of side 1, the point-up ones in [0, 0.5) and the point-down ones in [0.5, 1].
double triangle(double x, double z) {
    int flip = 0;
    const double v = triangle_in_cell(x, z, flip);
    return flip / 2.0 + 0.5 * v;
}

// The 60-degree lozenges of side 1 folded into [-0.25, 0.75] x [0, sqrt(3)/4]: their edge value.
double lozenge_in_strip(double x, double z) {
    if ((2.0 * z) > kHalfSqrt3) {
        z = kHalfSqrt3 - z;
        x = 1.5 - x;
    }
    if (x > 0.75) x -= 1.0;
    if (x != 0.0 && z / x > kSqrt3) {
        z = kHalfSqrt3 - z;
        x = 0.5 - x;
    }
    const double along = 1.0 - (z * 4.0 * kSqrt3 / 3.0);
    const double across = 1.0 - (std::fabs(kSqrt3 * x - z) * kSqrt3 * 2.0 / 3.0);
    return std::max(along, across);
}

// Tiling 4: 60-degree lozenges of side 1, all lying the same way.
double lozenge(double x, double z) {
    x = wrap(x, 1.0);
    z = wrap(z, kSqrt3);
    if (z > kHalfSqrt3) {  // the upper row is the lower one shifted by half a lozenge
        z -= kHalfSqrt3;
        x += 0.5;
    }
    return lozenge_in_strip(x, z);
}

// Tiling 5: the same lozenges in their three directions (cubes seen along a diagonal), a band of values each.
double rhombus(double x, double z) {
    x = wrap(x + 0.5, 3.0);
    z = wrap(z, kSqrt3);
    int kind = 0;
    if (z > kHalfSqrt3) {
        z = kSqrt3 - z;
        kind = 2 - kind;
    }
    if (x > 1.5) {
        x -= 1.5;
        z = kHalfSqrt3 - z;
        kind = 2 - kind;
    }
    if (x < 0.5) {
        x = 1.0 - x;
        kind = 2 - kind;
    }
    x -= 0.5;
    if (x == 0.0 || z / x > kSqrt3) {
        // The upright lozenge: turned by 60 degrees onto the lying ones.
        const double tx = (x / 2.0) + (z * kHalfSqrt3);
        const double tz = (z / 2.0) - (x * kHalfSqrt3);
        x = tx;
        z = tz;
        kind = 1;
    }
    double v = lozenge_in_strip(x, z) / 3.0;
    v += kind / 3.0;
    return std::clamp(v, 0.0, 1.0);
}

// One tile of a tiling of 1x1, 1x2 and 2x2 tiles laid on the unit grid: the grid square (column + row * n of
// the cell) tells the tile's origin and its shape.
enum class Tile : unsigned char { Unit, AlongX, AlongZ, Double };
struct GridTile {
    signed char dx = 0, dz = 0;  // the tile's reference corner in the cell
    Tile shape = Tile::Unit;
};

// A tile's edge value: 0 over its middle, 1 on its edges.
double grid_tile_value(const GridTile& t, double x, double z) {
    x -= t.dx;
    z -= t.dz;
    switch (t.shape) {
        case Tile::Unit:
            return std::max(across_unit(x), across_unit(z));
        case Tile::AlongX:  // 2 long in x, centred on the reference corner's x
            return std::max(along_double(x), across_unit(z));
        case Tile::AlongZ:
            return std::max(across_unit(x), along_double(z));
        case Tile::Double:
            return std::max(along_double(x), along_double(z));
    }
    return 0.0;
}

constexpr GridTile ux(int dx, int dz) { return {static_cast<signed char>(dx), static_cast<signed char>(dz), Tile::AlongX}; }
constexpr GridTile uz(int dx, int dz) { return {static_cast<signed char>(dx), static_cast<signed char>(dz), Tile::AlongZ}; }
constexpr GridTile u1(int dx, int dz) { return {static_cast<signed char>(dx), static_cast<signed char>(dz), Tile::Unit}; }
constexpr GridTile u2(int dx, int dz) { return {static_cast<signed char>(dx), static_cast<signed char>(dz), Tile::Double}; }

// Tiling 6: 1x2 rectangles in a 4x4 pinwheel; those along z take [0.5, 1], those along x [0, 0.5].
constexpr std::array<GridTile, 16> k_rectangles = {
    uz(0, 1), ux(2, 0), ux(2, 0), uz(3, 0),   // row 0
    uz(0, 1), uz(1, 2), ux(3, 1), ux(3, 1),   // row 1
    ux(0, 2), uz(1, 2), uz(2, 3), ux(4, 2),   // row 2
    ux(1, 3), ux(1, 3), uz(2, 3), uz(3, 4)};  // row 3

// Tiling 18: pairs of 1x2 rectangles in a 4x4 basket weave; along z [0.5, 1], along x [0, 0.5].
constexpr std::array<GridTile, 16> k_rectangle_pairs = {
    uz(0, 1), uz(1, 1), ux(3, 0), ux(3, 0),
    uz(0, 1), uz(1, 1), ux(3, 1), ux(3, 1),
    ux(1, 2), ux(1, 2), uz(2, 3), uz(3, 3),
    ux(1, 3), ux(1, 3), uz(2, 3), uz(3, 3)};

// The tile of grid square `index` of a cell's table; POV-Ray compat: a point on the cell's far edge (where the
// wrapping rounds up to the period) falls outside the table and is measured from the cell's origin as `outside`.
template <std::size_t N>
GridTile grid_tile(const std::array<GridTile, N>& tiles, int index, GridTile outside) {
    return index >= 0 && static_cast<std::size_t>(index) < N ? tiles[static_cast<std::size_t>(index)] : outside;
}

double rectangle_grid(const std::array<GridTile, 16>& tiles, double x, double z) {
    x = wrap(x, 4.0);
    z = wrap(z, 4.0);
    const GridTile t = grid_tile(tiles, static_cast<int>(x) + static_cast<int>(z) * 4, uz(0, 0));
    const double along_z = t.shape == Tile::AlongZ ? 1.0 : 0.0;
    return std::fabs((grid_tile_value(t, x, z) + along_z) / 2.0);
}

// Tilings 11 and 12: a unit square ringed by four 1x2 rectangles in a 3x3 cell; the square takes [0, 1/3], the
// rectangles along x [1/3, 2/3] and those along z [2/3, 1].
constexpr std::array<GridTile, 9> k_square_rectangles = {
    uz(0, 1), ux(2, 0), ux(2, 0),
    uz(0, 1), u1(1, 1), uz(2, 2),
    ux(1, 2), ux(1, 2), uz(2, 2)};

double square_rectangle_cell(double x, double z) {
    const GridTile t = grid_tile(k_square_rectangles, static_cast<int>(x) + static_cast<int>(z) * 3, uz(0, 0));
    const double band = t.shape == Tile::Unit ? 0.0 : t.shape == Tile::AlongX ? 1.0 : 2.0;
    return (grid_tile_value(t, x, z) + band) / 3.0;
}

// Tiling 11: the ring turning the same way in every cell.
double square_rectangle(double x, double z) { return square_rectangle_cell(wrap(x, 3.0), wrap(z, 3.0)); }

// Tiling 12: the ring turning both ways, the 6x6 cell folded in four.
double rectangle_square(double x, double z) {
    return square_rectangle_cell(std::fabs(wrap(x, 6.0) - 3.0), std::fabs(wrap(z, 6.0) - 3.0));
}

// Tiling 15: unit squares (values [0, 0.5]) and 2x2 squares (values [0.5, 1]) in a 5x5 cell.
constexpr std::array<GridTile, 25> k_square_doubles = {
    u1(0, 0), u2(2, 0), u2(2, 0), u2(4, 1), u2(4, 1),
    u2(1, 2), u2(1, 2), u1(2, 1), u2(4, 1), u2(4, 1),
    u2(1, 2), u2(1, 2), u2(3, 3), u2(3, 3), u1(4, 2),
    u2(0, 4), u1(1, 3), u2(3, 3), u2(3, 3), u2(5, 4),
    u2(0, 4), u2(2, 5), u2(2, 5), u1(3, 4), u2(5, 4)};

double square_double(double x, double z) {
    x = wrap(x, 5.0);
    z = wrap(z, 5.0);
    const GridTile t = grid_tile(k_square_doubles, static_cast<int>(x) + static_cast<int>(z) * 5, u2(0, 0));
    // POV-Ray compat: the large squares' band starts just above 0.5.
    const double band = t.shape == Tile::Double ? 0.50000001 : 0.0;
    return std::fabs(grid_tile_value(t, x, z) / 2.0 + band);
}

// Tiling 7: octagons of side 1 (values (0.5, 1]) with unit squares turned 45 degrees between them ([0, 0.5]).
double octa_square(double x, double z) {
    const double period = kSqrt2 + 1.0;
    const double middle = kHalfSqrt2 + 0.5;
    z = std::fabs(wrap(z, period) - middle);
    x = std::fabs(wrap(x, period) - middle);
    if (z > x) std::swap(x, z);
    if ((x + z) < kHalfSqrt2) return (x + z) / kSqrt2;  // the square, at the cell's corner
    const double straight = 1.0 - z;
    const double slant = (kSqrt2 + kHalfSqrt2 - (x + z)) / kSqrt2;
    // POV-Ray compat: the octagon's band starts just above 0.5.
    return std::max(0.500000000001, std::max(straight, slant));
}

// Tiling 8: rows of unit squares between rows of triangles; point-up triangles [0, 1/3], point-down [1/3, 2/3],
// squares (2/3, 1].
double square_triangle(double x, double z) {
    x = wrap(x, 1.0);
    z = wrap(z, 2.0 + kSqrt3);
    if (z > kHalfSqrt3 + 1.0) {  // every other row of squares and triangles is shifted by half a square
        z -= kHalfSqrt3 + 1.0;
        x += (x > 0.5) ? -0.5 : 0.5;
    }
    if (x > 0.5) x = 1.0 - x;
    z -= 1.0;
    if (z > 0.0) {
        int flip = 0;
        const double v = triangle_in_strip(x, z, flip);
        return (flip + v) / 3.0;
    }
    if (z < -0.5) z = -1.0 - z;
    const double across = std::min(2 + 2 * kSqrt3 * std::fabs(x), 3.0);
    const double along = std::min(2 + 2 * kSqrt3 * std::fabs(z), 3.0);
    // POV-Ray compat: the squares' band starts just above 2/3.
    return (5.0000001 - std::min(across, along)) / 3.0;
}

// Tiling 9: hexagons of side 1 with triangles between them (trihexagonal); point-up triangles [0, 1/3],
// point-down [1/3, 2/3], hexagons (2/3, 1].
double hexa_triangle(double x, double z) {
    x = wrap(x + 0.5, 2.0);
    z = wrap(z, 2.0 * kSqrt3);
    if (z > kSqrt3) {  // the upper half of the cell is the lower one shifted by a hexagon
        z -= kSqrt3;
        x += (x < 1.0) ? 1.0 : -1.0;
    }
    int flip = 0;
    if (z > kHalfSqrt3) {
        z = kSqrt3 - z;
        flip = 1 - flip;
    }
    if (x > 1.0) x = 2.0 - x;
    if ((kSqrt3 * x + z) < kHalfSqrt3) {
        const double bottom = 1.0 - (z * 2 * kSqrt3);
        const double slant = 1.0 + ((kSqrt3 * x + z) - kHalfSqrt3) * kSqrt3;
        return (flip + std::max(bottom, slant)) / 3.0;
    }
    const double flat = 2 + 2 * (z * kSqrt3);
    const double slant = 2 + 2 * ((kSqrt3 * x + z - kHalfSqrt3)) * kHalfSqrt3;
    // POV-Ray compat: the hexagons' band starts just above 2/3.
    return std::max(5.0 - std::min(flat, slant), 2.0000001) / 3.0;
}

// Tiling 10: unit squares, every other row shifted by half a square (a running bond).
double square_offset(double x, double z) {
    z = wrap(z, 2.0);
    if (z > 1.0) {
        x += 0.5;
        z -= 1.0;
    }
    x -= std::floor(x);
    return std::max(across_unit(x), across_unit(z));
}

}  // namespace

}  // namespace tiling

double tiling_value(int type, double x, double z) {
    using namespace tiling;
    switch (type) {
        case 2: return hexagon(x, z);
        case 3: return triangle(x, z);
        case 4: return lozenge(x, z);
        case 5: return rhombus(x, z);
        case 6: return rectangle_grid(k_rectangles, x, z);
        case 7: return octa_square(x, z);
        case 8: return square_triangle(x, z);
        case 9: return hexa_triangle(x, z);
        case 10: return square_offset(x, z);
        case 11: return square_rectangle(x, z);
        case 12: return rectangle_square(x, z);
        case 13: return square_internal(x, z);
        case 14: return square_internal_5(x, z);
        case 15: return square_double(x, z);
        case 16: return hexa_square_triangle(x, z, false);
        case 17: return hexa_square_triangle(x, z, true);
        case 18: return rectangle_grid(k_rectangle_pairs, x, z);
        case 19: return hexa_triangle_twisted(x, z, true);
        case 20: return hexa_triangle_twisted(x, z, false);
        case 21: return square_triangle_twisted(x, z);
        case 22: return dodeca_triangle(x, z);
        case 23: return dodeca_hexagon(x, z, false);
        case 24: return dodeca_hexagon(x, z, true);
        case 25: return penrose_pentagons(x, z);
        case 26: return penrose_kites(x, z, false);
        case 27: return penrose_kites(x, z, true);
        default: return square(x, z);
    }
}

double tiling_pattern(const scene::Pattern& pat, const Vec3& p, int) { return tiling_value(pat.params->tiling_type, p.x, p.z); }

}  // namespace wardray::texture
