// The tiling pattern's parts shared by its source files: the constants its tilings are measured in, and one
// function per tiling (texture/tiling.cpp dispatches to them).
#pragma once

#include <cmath>

namespace wardray::texture::tiling {

// POV-Ray compat: the tilings are measured with these constants, as POV-Ray's pattern code writes them.
inline constexpr double kSqrt2 = 1.4142135623730950488;
inline constexpr double kHalfSqrt2 = 0.70710678118654752440;
inline constexpr double kSqrt3 = 1.7320508075688772935;
inline constexpr double kHalfSqrt3 = 0.86602540378443864676;

/// `v` taken into [0, period): v - period * floor(v / period).
inline double wrap(double v, double period) { return v - period * std::floor(v / period); }

/// Within a unit span [0, 1]: 0 in the middle, 1 at both ends.
inline double across_unit(double u) { return 2.0 * std::fabs(u - 0.5); }

/// Along a span [-1, 1] of length 2: 0 over its middle half, rising to 1 at both ends.
inline double along_double(double u) { return 2.0 * (std::fmax(std::fabs(u), 0.5) - 0.5); }

/// The triangles of side 1 folded into the half strip x in [0, 0.5], z in [0, sqrt(3)/2] with a point-up
/// triangle's left half at the origin: the triangle's own edge value (0 in its middle, 1 on its edges), and
/// `flip` toggled when the point is in the point-down neighbour.
double triangle_in_strip(double x, double z, int& flip);

/// The triangle tiling's cell [0, 1) x [0, sqrt(3)) folded into that strip (tilings 3, 19 and 20).
double triangle_in_cell(double x, double z, int& flip);

double square_internal(double x, double z);     // tiling 13
double square_internal_5(double x, double z);   // tiling 14
double hexa_square_triangle(double x, double z, bool six);  // tilings 16 (three kinds) and 17 (six)
double hexa_triangle_twisted(double x, double z, bool right);  // tilings 19 (right-handed) and 20 (left)
double square_triangle_twisted(double x, double z);  // tiling 21
double dodeca_triangle(double x, double z);     // tiling 22
double dodeca_hexagon(double x, double z, bool five);  // tilings 23 (three kinds) and 24 (five)
double penrose_kites(double x, double z, bool rhombs);  // tilings 26 (kite and dart) and 27 (rhombs)
double penrose_pentagons(double x, double z);   // tiling 25

}  // namespace wardray::texture::tiling
