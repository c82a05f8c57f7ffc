// Surface pieces: the flat faces and round surfaces of primitives, the boxes CSG keeps, convex polygons in a plane.
#include "geometry/surface_pieces.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <variant>

#include "geometry/mesh.h"

namespace wardray::geometry {

namespace {

// A flat round face (a disc, a cylinder's or cone's cap) as the octagon inside it.
void add_round(std::vector<FlatPiece>& out, const Vec3& center, const Vec3& outward, double radius, bool two_sided) {
    const double len = length(outward);
    if (!(len > 0.0) || !(radius > 0.0)) return;
    FlatPiece piece{outward / len, center, {}, two_sided};
    const auto [u, v] = plane_basis(piece.normal);
    const double h = std::numbers::sqrt2 / 2.0;
    constexpr int kCos[8] = {2, 1, 0, -1, -2, -1, 0, 1};  // in units of h, 1 for 2
    constexpr int kSin[8] = {0, 1, 2, 1, 0, -1, -2, -1};
    auto unit = [h](int k) { return k == 2 ? 1.0 : (k == -2 ? -1.0 : k * h); };
    for (int k = 0; k < 8; ++k) piece.corners.push_back(center + radius * (unit(kCos[k]) * u + unit(kSin[k]) * v));
    out.push_back(std::move(piece));
}

double cross2(const Point2& o, const Point2& a, const Point2& b) {
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

double largest_extent(const std::vector<Vec3>& points) {
    Bounds box = no_bounds();
    for (const Vec3& p : points) box = including(box, p);
    return std::max({box.upper.x - box.lower.x, box.upper.y - box.lower.y, box.upper.z - box.lower.z, 0.0});
}

}  // namespace

std::vector<FlatPiece> flat_pieces(const scene::Shape& shape) {
    std::vector<FlatPiece> out;
    if (const auto* box = std::get_if<scene::Box>(&shape)) {
        const Bounds b = including(including(no_bounds(), box->corner1), box->corner2);
        for (int axis = 0; axis < 3; ++axis) {
            const int s = (axis + 1) % 3, t = (axis + 2) % 3;
            for (int side = 0; side < 2; ++side) {
                FlatPiece piece;
                piece.point = side ? b.upper : b.lower;
                piece.normal[axis] = side ? 1.0 : -1.0;
                for (int i = 0; i < 4; ++i) {
                    Vec3 c = piece.point;
                    c[s] = (i & 1) ? b.upper[s] : b.lower[s];
                    c[t] = (i & 2) ? b.upper[t] : b.lower[t];
                    piece.corners.push_back(c);
                }
                out.push_back(std::move(piece));
            }
        }
    } else if (const auto* plane = std::get_if<scene::Plane>(&shape)) {
        const double len = length(plane->normal);
        if (len > 0.0) out.push_back({plane->normal / len, plane->normal * (plane->distance / len), {}, false});
    } else if (const auto* disc = std::get_if<scene::Disc>(&shape)) {
        add_round(out, disc->center, disc->normal, disc->radius, true);
    } else if (const auto* polygon = std::get_if<scene::Polygon>(&shape)) {
        const std::vector<Vec3>& points = polygon->points;
        if (points.size() < 3) return out;
        Vec3 n = polygon_normal(polygon_loops(points));  // the plane its mesh is built in
        const double len = length(n);
        if (!(len > 0.0)) return out;
        n = n / len;
        const double size = largest_extent(points);
        for (const Vec3& p : points)
            if (std::abs(dot(n, p - points[0])) > 1e-9 * size) return out;  // not flat: left alone
        out.push_back({n, points[0], points, true});
    } else if (const auto* cylinder = std::get_if<scene::Cylinder>(&shape)) {
        if (!cylinder->open) {
            const Vec3 axis = cylinder->cap - cylinder->base;
            add_round(out, cylinder->base, -axis, cylinder->radius, false);
            add_round(out, cylinder->cap, axis, cylinder->radius, false);
        }
    } else if (const auto* cone = std::get_if<scene::Cone>(&shape)) {
        if (!cone->open) {
            const Vec3 axis = cone->cap - cone->base;
            add_round(out, cone->base, -axis, cone->base_radius, false);
            add_round(out, cone->cap, axis, cone->cap_radius, false);
        }
    }
    return out;
}

std::vector<RoundPiece> round_pieces(const scene::Shape& shape) {
    if (const auto* sphere = std::get_if<scene::Sphere>(&shape))
        if (sphere->radius > 0.0) return {{false, sphere->center, sphere->center, sphere->radius}};
    if (const auto* cylinder = std::get_if<scene::Cylinder>(&shape))
        if (cylinder->radius > 0.0) return {{true, cylinder->base, cylinder->cap, cylinder->radius}};
    return {};
}

int canonical_sign(const Vec3& n) {
    for (int k = 0; k < 3; ++k)
        if (std::abs(n[k]) > 1e-6) return n[k] > 0.0 ? 1 : -1;
    return 1;
}


// The uniform scale of a transform's linear part when it is a similarity (rotation, mirror, uniform scale), else 0:
// only then do spheres and round cylinders stay round.
double similarity_scale(const Transform& t) {
    const auto& m = t.matrix();
    const Vec3 c[3] = {{m[0][0], m[1][0], m[2][0]}, {m[0][1], m[1][1], m[2][1]}, {m[0][2], m[1][2], m[2][2]}};
    const double s2 = dot(c[0], c[0]);
    const double slack = 1e-9 * s2;
    if (std::abs(dot(c[1], c[1]) - s2) > slack || std::abs(dot(c[2], c[2]) - s2) > slack) return 0.0;
    if (std::abs(dot(c[0], c[1])) > slack || std::abs(dot(c[0], c[2])) > slack || std::abs(dot(c[1], c[2])) > slack)
        return 0.0;
    return std::sqrt(s2);
}

// Two unit vectors perpendicular to `n` and to each other.
std::pair<Vec3, Vec3> plane_basis(const Vec3& n) {
    const Vec3 helper = std::abs(n.x) < 0.5 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    const Vec3 u = normalize(cross(n, helper));
    return {u, cross(n, u)};
}

// A world box around an object, when its shape is one this file knows the extent of (nothing: unbounded or
// unknown).
std::optional<Bounds> world_bounds(const scene::Object& o, const Transform& outer) {
    const Transform world = o.transform.then(outer);
    Bounds local = no_bounds();  // in the object's own space
    if (const auto* csg = std::get_if<scene::Csg>(&o.shape)) {
        std::optional<Bounds> out;
        for (std::size_t k = 0; k < csg->children.size(); ++k) {
            const std::optional<Bounds> b = world_bounds(csg->children[k], world);
            switch (csg->op) {
            case scene::Csg::Op::Union:
            case scene::Csg::Op::Merge:
                if (!b) return std::nullopt;
                out = out ? out->merged(*b) : *b;
                break;
            case scene::Csg::Op::Intersection:
                out = intersect_bounds(out, b);
                break;
            case scene::Csg::Op::Difference:
                if (k == 0) return b;
                break;
            }
        }
        return out;
    } else if (const auto* box = std::get_if<scene::Box>(&o.shape)) {
        local = including(local, box->corner1);
        local = including(local, box->corner2);
    } else if (const auto* sphere = std::get_if<scene::Sphere>(&o.shape)) {
        local = including(local, sphere->center - Vec3{1, 1, 1} * sphere->radius);
        local = including(local, sphere->center + Vec3{1, 1, 1} * sphere->radius);
    } else if (const auto* cylinder = std::get_if<scene::Cylinder>(&o.shape)) {
        for (const Vec3& end : {cylinder->base, cylinder->cap}) {
            local = including(local, end - Vec3{1, 1, 1} * cylinder->radius);
            local = including(local, end + Vec3{1, 1, 1} * cylinder->radius);
        }
    } else if (const auto* cone = std::get_if<scene::Cone>(&o.shape)) {
        const double r = std::max(std::abs(cone->base_radius), std::abs(cone->cap_radius));
        for (const Vec3& end : {cone->base, cone->cap}) {
            local = including(local, end - Vec3{1, 1, 1} * r);
            local = including(local, end + Vec3{1, 1, 1} * r);
        }
    } else if (const auto* polygon = std::get_if<scene::Polygon>(&o.shape)) {
        for (const Vec3& p : polygon->points) local = including(local, p);
    } else {
        return std::nullopt;
    }
    if (local.empty()) return std::nullopt;
    if (o.inverse) return std::nullopt;  // all space but the shape
    Bounds out = no_bounds();
    for (const Vec3& c : corners(local)) out = including(out, world.point(c));
    for (int k = 0; k < 3; ++k)
        if (!std::isfinite(out.lower[k]) || !std::isfinite(out.upper[k])) return std::nullopt;
    return out;
}

// The points where the plane dot(n, p) = d crosses the edges of a box: their hull is the plane's section of it.
std::array<Vec3, 8> corners(const Bounds& box) {
    std::array<Vec3, 8> out;
    for (int i = 0; i < 8; ++i)
        out[static_cast<std::size_t>(i)] = {(i & 1) ? box.upper.x : box.lower.x, (i & 2) ? box.upper.y : box.lower.y,
                                            (i & 4) ? box.upper.z : box.lower.z};
    return out;
}

std::vector<Vec3> section(const Bounds& box, const Vec3& n, double d) {
    const std::array<Vec3, 8> c = corners(box);
    std::vector<Vec3> out;
    for (int i = 0; i < 8; ++i)
        for (int bit = 1; bit < 8; bit <<= 1) {
            if (i & bit) continue;
            const Vec3& p = c[static_cast<std::size_t>(i)];
            const Vec3& q = c[static_cast<std::size_t>(i | bit)];
            const double sp = dot(n, p) - d, sq = dot(n, q) - d;
            if (sp == 0.0) out.push_back(p);
            if (sq == 0.0) out.push_back(q);
            if ((sp < 0.0 && sq > 0.0) || (sp > 0.0 && sq < 0.0)) out.push_back(p + (q - p) * (sp / (sp - sq)));
        }
    return out;
}


// The convex hull, counter-clockwise (Andrew's monotone chain).
std::vector<Point2> hull(std::vector<Point2> points) {
    std::sort(points.begin(), points.end());
    points.erase(std::unique(points.begin(), points.end()), points.end());
    if (points.size() < 3) return points;
    std::vector<Point2> h(2 * points.size());
    std::size_t k = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
        while (k >= 2 && cross2(h[k - 2], h[k - 1], points[i]) <= 0.0) --k;
        h[k++] = points[i];
    }
    for (std::size_t i = points.size() - 1, t = k + 1; i-- > 0;) {
        while (k >= t && cross2(h[k - 2], h[k - 1], points[i]) <= 0.0) --k;
        h[k++] = points[i];
    }
    h.resize(k - 1);
    return h;
}

// What of a convex polygon has a*u + b*v <= c.
std::vector<Point2> clip(const std::vector<Point2>& poly, double a, double b, double c) {
    std::vector<Point2> out;
    for (std::size_t i = 0; i < poly.size(); ++i) {
        const Point2& p = poly[i];
        const Point2& q = poly[(i + 1) % poly.size()];
        const double sp = a * p[0] + b * p[1] - c, sq = a * q[0] + b * q[1] - c;
        if (sp <= 0.0) out.push_back(p);
        if ((sp < 0.0 && sq > 0.0) || (sp > 0.0 && sq < 0.0)) {
            const double t = sp / (sp - sq);
            out.push_back({p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])});
        }
    }
    return out;
}

// Whether two convex polygons share more than a strip `tol` wide: no edge direction of either separates them.
bool overlap(const std::vector<Point2>& a, const std::vector<Point2>& b, double tol) {
    for (const std::vector<Point2>* poly : {&a, &b}) {
        for (std::size_t i = 0; i < poly->size(); ++i) {
            const Point2& p = (*poly)[i];
            const Point2& q = (*poly)[(i + 1) % poly->size()];
            const double nu = q[1] - p[1], nv = p[0] - q[0];
            const double len = std::hypot(nu, nv);
            if (!(len > 0.0)) continue;
            auto span = [&](const std::vector<Point2>& poly2) {
                double lo = kUnbounded, hi = -kUnbounded;
                for (const Point2& r : poly2) {
                    const double x = (r[0] * nu + r[1] * nv) / len;
                    lo = std::min(lo, x);
                    hi = std::max(hi, x);
                }
                return std::pair{lo, hi};
            };
            const auto [alo, ahi] = span(a);
            const auto [blo, bhi] = span(b);
            if (std::min(ahi, bhi) - std::max(alo, blo) <= tol) return false;
        }
    }
    return true;
}

double area(const std::vector<Point2>& poly) {
    double twice = 0.0;
    for (std::size_t i = 0; i < poly.size(); ++i) {
        const Point2& p = poly[i];
        const Point2& q = poly[(i + 1) % poly.size()];
        twice += p[0] * q[1] - q[0] * p[1];
    }
    return 0.5 * std::abs(twice);
}

std::vector<Point2> cut_polygon(std::vector<Point2> shape, const Vec3& origin, const std::pair<Vec3, Vec3>& basis,
                                std::vector<HalfSpace> cuts, const std::optional<Bounds>& box, double tolerance) {
    const auto& [u, v] = basis;
    if (box)
        for (int k = 0; k < 3; ++k) {
            Vec3 axis;
            axis[k] = 1.0;
            cuts.push_back({axis, box->upper[k]});
            cuts.push_back({-axis, -box->lower[k]});
        }
    // Each cut in the plane: a*u + b*v <= c for p = origin + u*U + v*V.
    for (const HalfSpace& cut : cuts) {
        const double a = dot(cut.normal, u), b = dot(cut.normal, v);
        const double c = cut.distance - dot(cut.normal, origin);
        if (std::hypot(a, b) > 1e-9) shape = clip(shape, a, b, c);
        else if (c < -tolerance) shape.clear();  // parallel, and the plane lies outside it
    }
    if (shape.size() < 3 || !(area(shape) > 0.0)) shape.clear();
    return shape;
}

}  // namespace wardray::geometry
