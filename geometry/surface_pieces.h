// Surface pieces: the flat faces and round surfaces of primitives, the boxes CSG keeps, and convex polygons in a
// plane: the geometry geometry/coincident_surfaces.cpp compares.
#pragma once

#include <array>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

#include "core/transform.h"
#include "core/vec3.h"
#include "geometry/csg_bounds.h"
#include "geometry/shape.h"
#include "scene/object.h"

namespace wardray::geometry {

inline constexpr double kUnbounded = std::numeric_limits<double>::infinity();

/// The smallest box holding `box` and `p` (`box` may be empty(): then {p, p}).
inline Bounds including(const Bounds& box, const Vec3& p) { return box.merged({p, p}); }
/// An empty box, for including() points into.
inline Bounds no_bounds() { return {{kUnbounded, kUnbounded, kUnbounded}, {-kUnbounded, -kUnbounded, -kUnbounded}}; }
/// The eight corners of a box.
std::array<Vec3, 8> corners(const Bounds& box);

/// A flat face of a primitive in its own space: a point of its plane, its outward unit normal, and corners whose
/// convex hull covers it (none for a plane).
struct FlatPiece {
    Vec3 normal;
    Vec3 point;
    std::vector<Vec3> corners;
    bool two_sided = false;  ///< a disc or polygon: both sides are its surface
};

/// A sphere (centre `base`) or a cylinder's side (axis from `base` to `cap`) in the primitive's own space.
struct RoundPiece {
    bool cylinder = false;
    Vec3 base;
    Vec3 cap;
    double radius = 0.0;
};

/// The flat faces of a box, plane, disc, polygon (when flat), or a cylinder's or cone's caps; round faces as the
/// octagon inside them, so that round faces that only touch do not overlap.
std::vector<FlatPiece> flat_pieces(const scene::Shape& shape);
/// A sphere, or a cylinder's side.
std::vector<RoundPiece> round_pieces(const scene::Shape& shape);

/// +1 or -1: the sign that makes the first clearly nonzero component of `n` positive.
int canonical_sign(const Vec3& n);
/// The uniform scale of a transform's linear part when it is a similarity (rotation, mirror, uniform scale), else
/// 0: only then do spheres and round cylinders stay round.
double similarity_scale(const Transform& t);
/// Two unit vectors perpendicular to the unit vector `n` and to each other.
std::pair<Vec3, Vec3> plane_basis(const Vec3& n);
/// A world box around an object, when its shape is one this file knows the extent of (nothing: unbounded or
/// unknown); an intersection's is the meet of its parts', a difference's its first part's.
std::optional<Bounds> world_bounds(const scene::Object& o, const Transform& outer);
/// The points where the plane dot(n, p) = d crosses the edges of a box: their hull is the plane's section of it.
std::vector<Vec3> section(const Bounds& box, const Vec3& n, double d);

/// A point in a plane's (u, v) coordinates.
using Point2 = std::array<double, 2>;
/// The convex hull, counter-clockwise (Andrew's monotone chain).
std::vector<Point2> hull(std::vector<Point2> points);
/// What of a convex polygon has a*u + b*v <= c.
std::vector<Point2> clip(const std::vector<Point2>& poly, double a, double b, double c);
/// Whether two convex polygons share more than a strip `tol` wide: no edge direction of either separates them.
bool overlap(const std::vector<Point2>& a, const std::vector<Point2>& b, double tol);
/// The area of a simple polygon.
double area(const std::vector<Point2>& poly);
/// What of a convex polygon lies in every half-space of `cuts` and within `box` (when given): the polygon drawn in
/// (u, v) = `basis` of a plane through `origin`; a half-space parallel to the plane keeps all or, when it lies more
/// than `tolerance` beyond it, nothing. Empty when nothing of positive area is left.
std::vector<Point2> cut_polygon(std::vector<Point2> shape, const Vec3& origin, const std::pair<Vec3, Vec3>& basis,
                                std::vector<HalfSpace> cuts, const std::optional<Bounds>& box, double tolerance);

}  // namespace wardray::geometry
