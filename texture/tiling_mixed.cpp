// The tiling pattern, part two: POV-Ray 3.7's tilings that mix kinds of tiles in larger cells (13, 14, 16, 17 and
// 19 to 24): squares split by their diagonals, hexagons with squares and triangles, twisted hexagon and square
// tilings, dodecagons. Each folds the plane into a cell, then measures the point in its tile.
#include <algorithm>
#include <cmath>
#include <utility>

#include "texture/tiling_shapes.h"

namespace wardray::texture::tiling {

namespace {

// Rotates (x, z) by 60 degrees about (cx, cz), as the hexagon tilings turn a triangle or square onto another.
void turn_60(double& x, double& z, double cx, double cz) {
    x -= cx;
    z -= cz;
    const double tx = (x / 2.0) - (z * kHalfSqrt3);
    const double tz = (z / 2.0) + (x * kHalfSqrt3);
    x = tx + cx;
    z = tz + cz;
}

double min4(double a, double b, double c, double d) { return std::min(std::min(a, b), std::min(c, d)); }

}  // namespace

// Tiling 13: a 4x4 grid of squares of side 1/sqrt(2), the middle ones whole ([0, 1/3]) and the ring around them
// cut along the diagonals into two kinds of pieces ([1/3, 2/3] and [2/3, 1]), folded in four about the middle.
double square_internal(double x, double z) {
    x = std::fabs(wrap(x * kSqrt2, 4.0) - 2.0);
    z = std::fabs(wrap(z * kSqrt2, 4.0) - 2.0);
    switch (static_cast<int>(x) + static_cast<int>(z) * 2) {
        case 0:
            return std::max(std::max(x - 0.5, 0.0) * 2.0, std::max(z - 0.5, 0.0) * 2.0) / 3.0;
        case 1: {
            double v = (2.0 + std::fabs(1.5 - x) * 2.0) / 3.0;
            if (z > 0.5) v = std::max(v, (3.0 - kSqrt2 * std::fabs(x - z)) / 3.0);
            return v;
        }
        case 2: {
            double v = (1.0 + std::fabs(1.5 - z) * 2.0) / 3.0;
            if (x > 0.5) v = std::max(v, (2.0 - kSqrt2 * std::fabs(x - z)) / 3.0);
            return v;
        }
        case 3:
            if (x > z)
                return std::max((2.0 + std::fabs(1.5 - x) * 2.0) / 3.0, (3.0 - kSqrt2 * std::fabs(z - x)) / 3.0);
            return std::max((1.0 + std::fabs(1.5 - z) * 2.0) / 3.0, (2.0 - kSqrt2 * std::fabs(x - z)) / 3.0);
        default:
            return 0.0;
    }
}

// Tiling 14: tiling 13 with the ring's pieces told apart by the side of the middle they lie on, five bands: the
// pieces left and right of the middle [0, 1/5] and [1/5, 2/5], below and above [2/5, 3/5] and [3/5, 4/5], the
// middle squares (4/5, 1].
double square_internal_5(double x, double z) {
    x = wrap(x * kSqrt2, 4.0) - 2.0;
    const int side_x = x < 0 ? 1 : 0;
    x = std::fabs(x);
    z = wrap(z * kSqrt2, 4.0) - 2.0;
    const int side_z = z < 0 ? 2 : 3;
    z = std::fabs(z);
    switch (static_cast<int>(x) + static_cast<int>(z) * 2) {
        case 0: {
            const double v = std::max(std::max(x - 0.5, 0.0) * 2.0, std::max(z - 0.5, 0.0) * 2.0);
            return (4.000001 + v) / 5.0;  // POV-Ray compat: the band starts just above 4/5
        }
        case 1: {
            double v = std::fabs(1.5 - x) * 2.0;
            if (z > 0.5) v = std::max(v, 1.0 - kSqrt2 * std::fabs(x - z));
            return (v + side_x) / 5.0;
        }
        case 2: {
            double v = std::fabs(1.5 - z) * 2.0;
            if (x > 0.5) v = std::max(v, 1.0 - kSqrt2 * std::fabs(x - z));
            return (v + side_z) / 5.0;
        }
        case 3:
            if (x > z) return (std::max(std::fabs(1.5 - x) * 2.0, 1.0 - kSqrt2 * std::fabs(z - x)) + side_x) / 5.0;
            return (std::max(std::fabs(1.5 - z) * 2.0, 1.0 - kSqrt2 * std::fabs(x - z)) + side_z) / 5.0;
        default:
            return 0.0;
    }
}

// Tilings 16 and 17: hexagons of side 1 ringed by squares and triangles (rhombitrihexagonal). Tiling 16 gives
// squares, triangles and hexagons a third of the values each; tiling 17 tells each square and triangle by its
// orientation: three kinds of squares, two of triangles, the hexagons last.
double hexa_square_triangle(double x, double z, bool six) {
    const double h = kHalfSqrt3;
    int mirror_x = 0, mirror_z = 0, turned = 0;
    x = wrap(x + 0.5, 3.0 + kSqrt3);
    z = wrap(z, 2.0 * (1.0 + kSqrt3));
    if (x > (h + 1.5)) {  // the right half of the cell is the left half moved up by half a hexagon row
        x -= (h + 1.5);
        z += (z < kSqrt3 + 1.0) ? (h + 0.5) : (-1 * (h + 0.5));
    }
    if (z > (kSqrt3 + 1.0)) z -= kSqrt3 + 1.0;
    if (z > (0.5 + h)) {
        z = kSqrt3 + 1.0 - z;
        mirror_z = 1 - mirror_z;
    }
    if (x > (1.0 + h)) {
        x = kSqrt3 + 2.0 - x;
        mirror_x = 1 - mirror_x;
    }
    // Left of the hexagon: a piece turned by 60 degrees about the cell's corner lands on the lower row.
    if (((kSqrt3 * x + z) < (h + 2.0)) && (x < 0.5 + h)) {
        turn_60(x, z, 1.0 + h, 0.5 + h);
        turned = 1 - turned;
        if (z < 0) z *= -1;
        if (x > (1.0 + h)) {
            x = kSqrt3 + 2.0 - x;
            mirror_x = 1 - mirror_x;
            mirror_z = 1 - mirror_z;
        }
    }
    if (!((kSqrt3 * x + z) < (h + 2.0)) && !(z < 0.5)) {
        z = std::fabs(z - 0.5);
        x = std::fabs(x - h);
        const double flat = 2 * z * kSqrt3;
        const double slant = ((kSqrt3 * x + z)) * kSqrt3 - 1.5;
        // POV-Ray compat: the hexagons' band starts just above its bottom.
        if (six) return std::max(6.0 - std::min(flat, slant), 5.000001) / 6.0;
        return std::max(3.0 - std::min(flat, slant), 2.0000001) / 3.0;
    }
    if (!(z < 0.5)) return 0.0;
    if (x > h + 0.5) {  // a square
        x -= h + 0.5;
        z -= 0.5;
        const double side = std::max(1.0 + z * 2 * kSqrt3, 0.0);
        const double top = std::max(1.0 - x * 2 * kSqrt3, 0.0);
        if (!six) return std::max(side, top) / 3.0;
        return (std::max(side, top) + turned * (1.000001 + ((mirror_x + mirror_z) % 2))) / 6.0;
    }
    x = std::fabs(x - (h + 0.5));  // a triangle
    const double slant = ((kSqrt3 * z + x)) * kSqrt3 + 0.5;
    const double upright = 2.0 - (x * 2.0 * kSqrt3);
    const double v = std::max(upright, slant);
    if (!six) return v / 3.0;
    return (((turned + mirror_x) % 2 ? 2.0 : 3.0) + v) / 6.0;
}

// Tilings 19 and 20: hexagons of side 1 in a triangle tiling, each row of hexagons shifted by half a triangle
// to the right (19) or the left (20): point-up triangles [0, 1/3], point-down [1/3, 2/3], hexagons (2/3, 1].
double hexa_triangle_twisted(double x, double z, bool right) {
    const double h = kHalfSqrt3;
    // Every third row of triangles shifts the pattern by half a triangle.
    int rows = static_cast<int>(z / h);
    rows /= 3;
    if (z < 0) rows -= 1;
    x += (right ? 1.0 : -1.0) * (rows / 2.0);
    z = wrap(z, 3 * h);
    x += 7.0;
    x = wrap(x, 7.0);
    // The cell's three rows hold the same hexagon shifted along x: bring them onto the one at x in [0, 2].
    if (right) {
        if ((x > 4.5) && (z > kSqrt3)) {
            x -= 4.5;
            z -= h;
        }
        if ((x > 5.0) && (z < h)) {
            x -= 5;
            z += kSqrt3;
        }
        if ((x > 2.5) && (z < kSqrt3)) {
            x -= 2.5;
            z += h;
        }
    } else {
        if ((x > 2.0) && (z < h)) {
            x -= 2.0;
            z += kSqrt3;
        }
        if ((x > 4.5) && (z < kSqrt3)) {
            x -= 4.5;
            z += h;
        }
        if ((x > 2.5) && (z > kSqrt3)) {
            x -= 2.5;
            z -= h;
        }
    }
    int flip = 0;
    int row = static_cast<int>(z / h);
    if (row == 2) {
        row = 1;
        z = 2 * kSqrt3 - z;
        flip = 1 - flip;
    }
    if (!row || (x > 2.0) || ((z + kSqrt3 * x < kSqrt3) || (kSqrt3 * x - z > kSqrt3))) {
        const double v = triangle_in_cell(x, z, flip);
        return (flip + v) / 3.0;
    }
    z -= h;
    if (x > 1.0) x = 2.0 - x;
    const double flat = 2 + 2 * (z * kSqrt3);
    const double slant = 2 + 2 * ((kSqrt3 * x + z - h)) * h;
    // POV-Ray compat: the hexagons' band starts just above 2/3.
    return std::max(5.0 - std::min(flat, slant), 2.000001) / 3.0;
}

// Tiling 21: squares and triangles of side 1 in a twisted square pattern (snub square): the triangles in four
// bands by orientation ([0, 2/3]), the squares in two ([2/3, 5/6] and (5/6, 1]).
double square_triangle_twisted(double x, double z) {
    const double half = 0.5 + kHalfSqrt3;
    int other = 0;    // toggled by each mirror: which of the two squares' orientations
    int turn = 0;     // the triangles' band
    int mirrored = 0;
    x = wrap(x, 1.0 + kSqrt3);
    z = wrap(z, 1.0 + kSqrt3);
    if (z > half) {
        z = 1.0 + kSqrt3 - z;
        other = 1 - other;
    }
    if (x > half) {
        x = 1.0 + kSqrt3 - x;
        other = 1 - other;
        mirrored = 1;
    }
    // The quarter cell still holds four turns of one square and its triangles: bring them onto one.
    const bool past_x = (2.0 * x + (kSqrt3 - 1.0) * 2.0 * z / (kSqrt3 + 1.0)) > kSqrt3;
    const bool past_z = (2.0 * z * kSqrt3 + (kSqrt3 - 3.0) * 2.0 * x / (kSqrt3 + 1.0)) > kSqrt3;
    switch ((past_x ? 1 : 0) + (past_z ? 2 : 0)) {
        case 0:
            turn = 2 * mirrored;
            break;
        case 1: {  // a quarter turn clockwise
            turn = mirrored ? 1 + 2 * other : 3 - 2 * other;
            const double t = x;
            x = z;
            z = kHalfSqrt3 + 0.5 - t;
            break;
        }
        case 2: {  // a quarter turn the other way
            turn = mirrored ? 3 - 2 * other : 1 + 2 * other;
            const double t = z;
            z = x;
            x = kHalfSqrt3 + 0.5 - t;
            break;
        }
        default:  // a half turn
            turn = mirrored ? 0 : 2;
            x = kHalfSqrt3 + 0.5 - x;
            z = kHalfSqrt3 + 0.5 - z;
            break;
    }
    if (x == 0.0) z = 0.0;
    double edge = (z * 2 * kSqrt3) - kSqrt3 + x * 2;
    if (edge < 0) {  // a triangle
        const double across = -1.5 / kSqrt3 * edge;
        const double side = 2.0 * x * kSqrt3;
        return (turn + 1.0 - std::min(across, side)) / 6.0;
    }
    edge *= 1.5 / kSqrt3;
    edge = std::min(edge, 1.0);
    // POV-Ray compat: each square band starts just above its bottom.
    if (other) return std::min(std::max((-edge + 6.0) / 6.0, 5.000001 / 6.0), 1.0);
    return std::max(std::min((-edge + 5.0) / 6.0, 5.0 / 6.0), 4.000001 / 6.0);
}

// Tiling 22: dodecagons of side 1 with triangles between them (truncated hexagonal): the two orientations of
// triangles [0, 1/3] and [1/3, 2/3], the dodecagons (2/3, 1].
double dodeca_triangle(double x, double z) {
    const double h = kHalfSqrt3;
    int flip = 0;
    x = wrap(x, 2.0 + kSqrt3);
    z = wrap(z, 3.0 + 2.0 * kSqrt3);
    if (z > kSqrt3 + 1.5) {  // the upper half of the cell is the lower one shifted by half a dodecagon row
        z -= kSqrt3 + 1.5;
        x += (x < (1.0 + h) ? 1.0 : -1.0) * (1.0 + h);
    }
    if (x > 1.0 + h) x = 2.0 + kSqrt3 - x;
    if (z > 1.0 + h) {
        z = 2.0 + kSqrt3 - z;
        flip = 1 - flip;
    }
    double slant = x - h - 0.5 + z * kSqrt3;
    if (slant < 0.0) {  // below the slanted edge: a half turn onto the other side of the triangle
        const double tx = x;
        const double tz = z;
        x = (1.0 + kSqrt3) / 4.0 + 0.5 * tx - h * tz;
        z = (3.0 + kSqrt3) / 4.0 - h * tx - 0.5 * tz;
        slant *= -1.0;
    }
    const double bottom = (z * 3.0);
    double corner = z - h - 0.5 + x * kSqrt3;
    corner *= kSqrt3;
    slant *= kSqrt3;
    const double upright = (x * 3.0);
    if (corner < 0.0) return (std::max(corner, -1.0) + (1 + flip)) / 3.0;
    const double v = std::min(min4(bottom, slant, corner, upright), 1.0);
    return (3.0000001 - v) / 3.0;  // POV-Ray compat: the dodecagons' band starts just above 2/3
}

// Tilings 23 and 24: dodecagons of side 1 with hexagons and squares between them (truncated trihexagonal): 23
// gives hexagons, squares and dodecagons a third each; 24 tells two orientations of squares apart, in fifths.
double dodeca_hexagon(double x, double z, bool five) {
    const double h = kHalfSqrt3;
    int mirror_x = 0, mirror_z = 0;
    x = wrap(x, 3.0 + kSqrt3);
    z = wrap(z, 3.0 + 3.0 * kSqrt3);
    if (z > 1.5 * kSqrt3 + 1.5) {
        z -= 1.5 * kSqrt3 + 1.5;
        x += (x < (1.5 + h) ? 1.0 : -1.0) * (1.5 + h);
    }
    if (x > 1.5 + h) {
        x = 3.0 + kSqrt3 - x;
        mirror_x = 1 - mirror_x;
    }
    if (z > 1.0 + kSqrt3) {
        z = 2.0 + 2.0 * kSqrt3 - z;
        mirror_z = 1 - mirror_z;
    }
    if (x - h - 1.5 + z * kSqrt3 < 0.0) {  // a half turn about the middle of the slanted square
        const double tx = x;
        const double tz = z;
        x = (3.0 + kSqrt3) / 4.0 + 0.5 * tx - h * tz;
        z = (3.0 + 3.0 * kSqrt3) / 4.0 - h * tx - 0.5 * tz;
    }
    // Signed distances (scaled) from the dodecagon's four nearby edges, positive inside it.
    double slant = x - h - 2.5 + z * kSqrt3;
    double bottom = (z * 2.0) - kSqrt3;
    double steep = z - 1.5 * kSqrt3 - 0.5 + x * kSqrt3;
    double upright = ((x - 0.5) * 2.0);
    double v;
    if ((slant >= 0.0) && (bottom >= 0.0) && (steep >= 0.0) && (upright >= 0.0)) {
        v = std::min(min4(bottom, slant, steep, upright), 1.0);
        v = (five ? 5.000001 : 3.000001) - v;  // POV-Ray compat: the band starts just above its bottom
    } else {
        double top = 2 * z - 2 * kSqrt3 - 1.0;
        if (top >= 0) {  // the upright square on the cell's left edge
            v = 2.0 - std::min(top, -upright);
        } else {
            double left = kSqrt3 * x - z - h + 0.5;
            double right = left - 2.0;
            switch ((left >= 0 ? 0 : 1) + (right >= 0.0 ? 2 : 0)) {
                case 1:  // the hexagon on the left
                    v = 1.0 - std::min(std::min(std::min(-left, -steep), -top), 1.0);
                    break;
                case 2:  // the hexagon below
                    v = 1.0 - std::min(std::min(right, -bottom), 1.0);
                    break;
                default:  // the slanted square
                    v = std::min(std::min(left, -slant), -right);
                    v = five ? (mirror_z + mirror_x) % 2 + 3.0 - v : 2.0 - v;
                    break;
            }
        }
    }
    return v / (five ? 5.0 : 3.0);
}

}  // namespace wardray::texture::tiling
