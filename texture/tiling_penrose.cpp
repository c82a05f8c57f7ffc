// The tiling pattern, part three: POV-Ray 3.7's Penrose tilings (25: pentagons, stars, boats and diamonds; 26:
// kites and darts; 27: rhombs), centred on the origin. A point is folded by the tiling's five-fold symmetry, scaled
// down by whole inflation steps to the central patch, then followed down the substitution (deflation) of the
// half-tile it lies in, step by step, until the tile it ends in measures it.
#include <algorithm>
#include <cmath>

#include "core/constants.h"
#include "texture/tiling_shapes.h"

namespace wardray::texture::tiling {

namespace {

// POV-Ray compat: the golden ratio and the sines, cosines and tangents of multiples of 18 degrees, as POV-Ray's
// pattern code writes them.
constexpr double kPhi = 1.6180339887498948482;
constexpr double kInvPhi = 0.61803398874989484820;
constexpr double kPhiSquared = 2.6180339887498948482;
constexpr double kInvPhiSquared = 0.38196601125010515180;
constexpr double kSin18 = 0.30901699437494742410;
constexpr double kSin36 = 0.58778525229247312917;
constexpr double kSin54 = 0.80901699437494742410;
constexpr double kSin72 = 0.95105651629515357212;
constexpr double kSin108 = kSin72;
constexpr double kSin144 = kSin36;
constexpr double kSin162 = kSin18;
constexpr double kCos18 = kSin72;
constexpr double kCos36 = kSin54;
constexpr double kCos72 = kSin18;
constexpr double kCos108 = -kCos72;
constexpr double kCos144 = -kCos36;
constexpr double kCos162 = -kCos18;
constexpr double kTan18 = 0.32491969623290632616;
constexpr double kTan36 = 0.72654252800536088590;
constexpr double kTan54 = 1.3763819204711735382;
constexpr double kTan72 = 3.0776835371752534026;
constexpr double kTan108 = -kTan72;
constexpr double kTan126 = -kTan54;
constexpr double kTan144 = -kTan36;
constexpr double kTan162 = -kTan18;
constexpr double kEdgeBand = 1e-6;  // POV-Ray compat: keeps each kind of tile inside its own band

// POV-Ray compat: the widths of the darkening along tile edges, empirical factors of POV-Ray's.
constexpr double kKiteEdge = 4.46;
constexpr double kRhombEdge = 5.55;

double max3(double a, double b, double c) { return std::max(a, std::max(b, c)); }

// (x, z) turned by the angle whose cosine and sine are c and s (x' = x c + z s, z' = z c - x s).
void turn(double& x, double& z, double c, double s) {
    const double tx = x * c + z * s;
    const double tz = z * c - x * s;
    x = tx;
    z = tz;
}

// --- Kites and darts (26), rhombs (27): each half-kite and half-dart splits into smaller half-tiles.

double half_dart(double x, double z, int depth, bool rhombs);

double half_kite(double x, double z, int depth, bool rhombs) {
    z = std::fabs(z);
    if (depth > 0) {
        if (z < (x - kInvPhi) * kTan144) return half_dart(x * kPhi, z * kPhi, depth - 1, rhombs);
        x -= kCos36;
        z -= kSin36;
        const double tx = x * kCos108 - z * kSin108;
        const double tz = z * kCos108 + x * kSin108;
        return half_kite(tx * kPhi, tz * kPhi, depth - 1, rhombs);
    }
    if (rhombs) {
        if (z < (x - kInvPhi) * kTan72) {  // the wide rhomb: (0.5, 1]
            const double a = std::fabs(kSin72 * (x - kInvPhi) - kCos72 * z) * kRhombEdge;
            const double b = std::fabs(kSin108 * (x - 1) - kCos108 * z) * kRhombEdge;
            return max3(1.0 - a / 2, 1.0 - b / 2, 0.5 + kEdgeBand);
        }
        const double a = std::fabs(z) * kRhombEdge;  // the narrow rhomb: [0, 0.5)
        const double b = std::fabs(kSin72 * (x - kInvPhi) - kCos72 * z) * kRhombEdge;
        return std::min(max3(0.5 - a / 2, 0.5 - b / 2, 0.0), 0.5 - kEdgeBand);
    }
    const double a = std::fabs(kSin36 * x - kCos36 * z) * kKiteEdge;  // the kite: [0, 0.5)
    const double b = std::fabs(kSin108 * (x - 1) - kCos108 * z) * kKiteEdge;
    return std::min(max3(0.5 - a / 2, 0.5 - b / 2, 0.0), 0.5 - kEdgeBand);
}

double half_dart(double x, double z, int depth, bool rhombs) {
    z = std::fabs(z);
    if (depth > 0) {
        if (z < (x - kInvPhi) * kTan108) {
            turn(x, z, kCos36, kSin36);
            return half_kite(x * kPhi, z * kPhi, depth - 1, rhombs);
        }
        x -= 1;
        turn(x, z, kCos144, kSin144);
        return half_dart(x * kPhi, z * kPhi, depth - 1, rhombs);
    }
    if (rhombs) {  // the narrow rhomb
        const double a = std::fabs(kSin36 * x - kCos36 * z) * kRhombEdge;
        const double b = std::fabs(kSin144 * (x - 1) - kCos144 * z) * kRhombEdge;
        return std::min(max3(0.5 - a / 2, 0.5 - b / 2, 0.0), 0.5 - kEdgeBand);
    }
    const double a = std::fabs(z) * kKiteEdge;  // the dart: (0.5, 1]
    const double b = std::fabs(kSin144 * (x - 1) - kCos144 * z) * kKiteEdge;
    return max3(1.0 - a / 2, 1.0 - b / 2, 0.5 + kEdgeBand);
}

// Folds (x, z), at distance r from the origin, into the 36-degree wedge about +x by the five-fold symmetry.
void fold_five(double& x, double& z, double r) {
    z = std::fabs(z);
    if (x < r * kCos36) {
        if (x < r * kCos108)
            turn(x, z, kCos144, kSin144);
        else
            turn(x, z, kCos72, kSin72);
        z = std::fabs(z);
    }
}

void fold_five(double& x, double& z) { fold_five(x, z, std::sqrt(x * x + z * z)); }

// --- Pentagons, stars, boats and diamonds (25): six kinds of tiles in sixths of the values.

double pentagon1(double x, double z, int depth);
double pentagon2(double x, double z, int depth, bool inside_quad);
double pentagon3(double x, double z, int depth, bool inside_wedge);
double star(double x, double z, int depth);
double boat(double x, double z, int depth, bool inside_wedge);
double diamond(double x, double z, int depth, bool side_a);

// The scaled distance from a pentagon's edge facing +x.
double pentagon_edge(double x) { return std::fabs(x - 0.5 / kTan36) * kRhombEdge * kInvPhi; }

// A tile's value in its band [lo, hi] of sixths: hi minus its edge distance, kept inside the band.
double sixth_band(int band, double dist, bool open_below) {
    const double top = band / 6.0;
    const double bottom = open_below ? (band - 1) / 6.0 + kEdgeBand : 0.0;
    return std::min(std::max(top - dist / 6, bottom), top - kEdgeBand);
}

double pentagon1(double x, double z, int depth) {
    z = std::fabs(z);
    fold_five(x, z);
    if (depth > 0) {
        if (z < (x - 0.5 / kTan36) * kTan54 + 0.5)
            return pentagon2((x - 0.5 / kTan36 - kInvPhi * 0.5 * kCos72 / kSin36) * kPhi, z * kPhi, depth - 1, false);
        turn(x, z, kCos36, kSin36);
        return star(x * kPhi, z * kPhi, depth - 1);
    }
    return sixth_band(1, pentagon_edge(x), false);
}

double pentagon2(double x, double z, int depth, bool inside_quad) {
    z = std::fabs(z);
    if (depth > 0) {
        if (inside_quad) {
            if (z < (x - kInvPhiSquared * 0.5 / kSin36) * kTan54)
                return pentagon1((x - 0.5 / kSin36) * kPhi, z * kPhi, depth - 1);
            if (z < (x - kInvPhiSquared * 0.5 / kSin36) * kTan162) return diamond(-x * kPhi, z * kPhi, depth - 1, true);
            const double tx = x * kCos108 - z * kSin108 + kInvPhi * 0.5 / kSin36;
            const double tz = z * kCos108 + x * kSin108;
            return pentagon2(tx * kPhi, tz * kPhi, depth - 1, true);
        }
        if (z < (x + 0.5 / kSin36) * kTan18)
            return diamond((x + 0.5 / kSin36 - kInvPhiSquared * 0.5 / kSin36) * kPhi, z * kPhi, depth - 1, false);
        const double tx = -(x * kCos36 + z * kSin36) - kCos72 * 0.5 / kSin36;
        const double tz = (z * kCos36 - x * kSin36) - kSin72 * 0.5 / kSin36;
        return pentagon3(tx * kPhi, tz * kPhi, depth - 1, false);
    }
    fold_five(x, z);
    return sixth_band(2, pentagon_edge(x), true);
}

double pentagon3(double x, double z, int depth, bool inside_wedge) {
    z = std::fabs(z);
    if (depth > 0) {
        if (inside_wedge && (x > kInvPhiSquared * 0.5 * kCos72 / kSin36)) {
            const double tx = -(x - kInvPhiSquared * 0.5 * kCos72 / kSin36 - kInvPhi * 0.5 / kTan36);
            return pentagon2(tx * kPhi, z * kPhi, depth - 1, true);
        }
        if (!inside_wedge && (x < 0.5 * kCos108 / kSin36)) {
            const double tx = x * kCos144 + z * kSin144 - 0.5 / kSin36;
            const double tz = z * kCos144 - x * kSin144;
            return pentagon2(tx * kPhi, tz * kPhi, depth - 1, false);
        }
        if (!inside_wedge && (z > (x - kInvPhiSquared * 0.5 / kSin36) * kTan126)) {
            const double tx = -(x * kCos36 - z * kSin36) - kCos72 * 0.5 / kSin36;
            const double tz = (z * kCos36 + x * kSin36) - kSin72 * 0.5 / kSin36;
            return pentagon3(tx * kPhi, tz * kPhi, depth - 1, false);
        }
        return boat(x * kPhi, z * kPhi, depth - 1, inside_wedge);
    }
    fold_five(x, z);
    return sixth_band(3, pentagon_edge(x), true);
}

// The scaled distance from a star's or a boat's point edge.
double point_edge(double x, double z) {
    return std::fabs(kSin162 * (x - kPhi * 0.5 / kSin36) - kCos162 * z) * kRhombEdge * kInvPhi;
}

double star(double x, double z, int depth) {
    z = std::fabs(z);
    if (depth > 0) {
        if (x < kInvPhi * 0.5 / kTan36) return pentagon1(x * kPhi, z * kPhi, depth - 1);
        return pentagon3(-(x - kInvPhi / kTan36) * kPhi, z * kPhi, depth - 1, true);
    }
    return sixth_band(4, point_edge(x, z), true);
}

double boat(double x, double z, int depth, bool inside_wedge) {
    z = std::fabs(z);
    if (depth > 0) {
        if (inside_wedge && (x > kPhi * 0.5 * kCos108 / kSin36)) return pentagon1(-x * kPhi, z * kPhi, depth - 1);
        double tx = x, tz = z;
        if (!inside_wedge) {
            tx = x * kCos72 - z * kSin72;
            tz = z * kCos72 + x * kSin72;
        }
        tx += 0.5 / kSin36;
        return pentagon3(tx * kPhi, tz * kPhi, depth - 1, true);
    }
    const double back = std::fabs(x - kInvPhi * 0.5 * kCos72 / kSin36) * kRhombEdge * kInvPhi;
    x = -x;
    fold_five(x, z);
    const double point = point_edge(x, z);
    return std::min(max3(5.0 / 6 - back / 6, 5.0 / 6 - point / 6, 4.0 / 6 + kEdgeBand), 5.0 / 6 - kEdgeBand);
}

double diamond(double x, double z, int depth, bool side_a) {
    z = std::fabs(z);
    if (depth > 0) {
        if (side_a) return pentagon1(x * kPhi, z * kPhi, depth - 1);
        return pentagon3(x * kPhi, z * kPhi, depth - 1, true);
    }
    const double dist = std::fabs(kSin18 * (x + kInvPhi * 0.5 / kSin36) - kCos18 * z) * kRhombEdge * kInvPhi;
    return sixth_band(6, dist, true);
}

}  // namespace

double penrose_kites(double x, double z, bool rhombs) {
    const double r = std::sqrt(x * x + z * z);
    if (r <= kPovEpsilon) return 1.0;
    fold_five(x, z, r);
    if (rhombs) {
        x *= kInvPhi;
        z *= kInvPhi;
    }
    // Whole double inflation steps (by phi squared) out to the point, from the central star's edge.
    const double dist = std::fabs(kSin108 * x - kCos108 * z) / kCos18;
    int depth = std::max(0, static_cast<int>(std::ceil(std::log(dist) / std::log(kPhiSquared))));
    x *= std::pow(kInvPhiSquared, depth);
    z *= std::pow(kInvPhiSquared, depth);
    if (depth % 2) {  // odd steps leave the pattern turned by 36 degrees
        turn(x, z, kCos36, kSin36);
        z = std::fabs(z);
    }
    return half_kite(x, z, depth * 2, rhombs);
}

double penrose_pentagons(double x, double z) {
    const double r = std::sqrt(x * x + z * z);
    if (r <= kPovEpsilon) return 1.0;
    fold_five(x, z, r);
    const double dist = x * 2 * kTan36;
    const int depth = std::max(0, static_cast<int>(std::ceil(std::log(dist) / std::log(kPhiSquared * kPhiSquared))));
    x *= std::pow(kInvPhiSquared * kInvPhiSquared, depth);
    z *= std::pow(kInvPhiSquared * kInvPhiSquared, depth);
    return pentagon1(x, z, depth * 4);
}

}  // namespace wardray::texture::tiling
