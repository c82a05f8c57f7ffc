// PathSequence: the random numbers of a pixel's reference paths, from one Owen-scrambled Sobol sequence per pixel.
#pragma once

#include <cstdint>

#include "core/vec3.h"

namespace wardray::lighting {

/// How many dimensions path_sample provides: the first bounce's direction, then at each hit of bounce depth g the
/// light picked there and the next direction (path_pick_dimension, path_direction_dimension), up to depth 3.
inline constexpr int kPathDimensions = 9;

/// The first of the two dimensions of the direction a path leaves a hit of bounce depth `gi_depth` along (0 at the
/// camera hit).
constexpr int path_direction_dimension(int gi_depth) { return gi_depth == 0 ? 0 : 3 * gi_depth; }
/// The dimension of the light a path picks at a hit of bounce depth `gi_depth` ≥ 1.
constexpr int path_pick_dimension(int gi_depth) { return 3 * gi_depth - 1; }

/// Coordinate `dimension` (< kPathDimensions) of point `index` of a Sobol sequence (Sobol 1967; the first
/// dimensions' direction numbers are Joe & Kuo's 2008) under a nested scrambling keyed by `seed` (Owen 1995's
/// structure, hashed as Laine & Karras 2011 do), in [0, 1). Over seeds every point is uniform on the unit cube, so
/// an average over points keeps the expectation of independent uniform samples, while the first 2^m points share
/// the cube out (a (t, m, s)-net): a pixel's paths stratify each bounce and the bounces jointly.
double path_sample(std::uint32_t index, int dimension, std::uint64_t seed);

/// A cosine-distributed direction in the local frame (z along the normal) from a point of the unit square:
/// sin²θ = u, φ = 2πv (Ward & Heckbert 1992, section 3: density cos θ / π).
Vec3 cosine_direction(double u, double v);

}  // namespace wardray::lighting
