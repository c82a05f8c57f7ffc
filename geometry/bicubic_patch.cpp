// MeshShape from a bicubic_patch: POV-Ray's subdivision into flat subpatches, two smooth triangles each.
#include <array>
#include <cmath>

#include "geometry/mesh.h"

namespace wardray::geometry {

namespace {

// POV-Ray's BEZIER_EPSILON (relative degeneracy of normals) and EPSILON (coincident corners).
constexpr double k_bezier_epsilon = 1e-10;
constexpr double k_epsilon = 1e-10;

// Control points [i][j], i along u and j along v.
using Patch = std::array<std::array<Vec3, 4>, 4>;

Vec3 midpoint(const Vec3& a, const Vec3& b) { return 0.5 * (a + b); }

// The de Casteljau halves of one cubic (four points) at its middle.
void split_curve(const std::array<Vec3, 4>& p, std::array<Vec3, 4>& lo, std::array<Vec3, 4>& hi) {
    const Vec3 a = midpoint(p[0], p[1]), m = midpoint(p[1], p[2]), c = midpoint(p[2], p[3]);
    const Vec3 b = midpoint(a, m), d = midpoint(m, c), mid = midpoint(b, d);
    lo = {p[0], a, b, mid};
    hi = {mid, d, c, p[3]};
}

// The halves in u (first index) or in v (second index).
void split(const Patch& p, bool along_u, Patch& lo, Patch& hi) {
    for (int k = 0; k < 4; ++k) {
        std::array<Vec3, 4> curve, a, b;
        for (int m = 0; m < 4; ++m) curve[m] = along_u ? p[m][k] : p[k][m];
        split_curve(curve, a, b);
        for (int m = 0; m < 4; ++m) {
            (along_u ? lo[m][k] : lo[k][m]) = a[m];
            (along_u ? hi[m][k] : hi[k][m]) = b[m];
        }
    }
}

// POV-Ray's flatness: the largest distance of a control point from the plane of three distinct corners, or -1
// when no three corners are distinct (never flat).
double flatness(const Patch& p) {
    const auto apart = [](const Vec3& a, const Vec3& b) { return length(a - b) >= k_epsilon; };
    Vec3 v0 = p[0][0], v1 = p[0][3], v2;
    if (!apart(v0, v1)) {
        v1 = p[3][3];
        v2 = p[3][0];
        if (!apart(v0, v1) || !apart(v1, v2)) return -1.0;
    } else {
        // POV-Ray compat: here it tests only the second and third corners.
        v2 = p[3][0];
        if (!apart(v1, v2)) return -1.0;
    }
    const Vec3 e1 = v0 - v1, e2 = v2 - v1;
    Vec3 n = cross(e1, e2);
    const double n2 = dot(n, n);
    if (n2 <= k_bezier_epsilon * dot(e1, e1) * dot(e2, e2)) return -1.0;
    n = n / std::sqrt(n2);
    double dist = 0.0;
    for (const auto& row : p)
        for (const Vec3& q : row) dist = std::fmax(dist, std::fabs(dot(q - v0, n)));
    return dist;
}

// The unit normal of the whole patch at (u, v): the cross product of its tangents, or x where it degenerates.
Vec3 patch_normal(const Patch& p, double u, double v) {
    const auto basis = [](double t, double b[4], double db[4]) {
        const double s = 1.0 - t;
        b[0] = s * s * s;
        b[1] = 3.0 * t * s * s;
        b[2] = 3.0 * t * t * s;
        b[3] = t * t * t;
        db[0] = -3.0 * s * s;
        db[1] = 3.0 * s * s - 6.0 * t * s;
        db[2] = 6.0 * t * s - 3.0 * t * t;
        db[3] = 3.0 * t * t;
    };
    double bu[4], dbu[4], bv[4], dbv[4];
    basis(u, bu, dbu);
    basis(v, bv, dbv);
    Vec3 du, dv;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            du += dbu[i] * bv[j] * p[i][j];
            dv += bu[i] * dbv[j] * p[i][j];
        }
    const Vec3 n = cross(du, dv);
    const double n2 = dot(n, n);
    // POV-Ray compat: a degenerate normal (a pole of the patch) is the x axis.
    if (!(n2 > k_bezier_epsilon * dot(du, du) * dot(dv, dv))) return {1.0, 0.0, 0.0};
    return n / std::sqrt(n2);
}

// Builds the triangles: world-space subdivision as POV-Ray's tree builder does, stored in object space.
struct Tessellator {
    const Patch& whole;
    const Transform& placement;
    const Transform to_object;
    int u_steps, v_steps;
    double flat;
    scene::Mesh mesh;
    std::vector<Vec3> params;  ///< each vertex's (u, v, 0)

    int vertex(const Vec3& world, double u, double v) {
        mesh.vertices.push_back(placement.inverse_point(world));
        params.push_back({u, v, 0.0});
        // Normals go back by the transpose of the placement's linear part: the inverse's normal map.
        mesh.normals.push_back(to_object.normal(patch_normal(whole, u, v)));
        return static_cast<int>(mesh.vertices.size()) - 1;
    }

    void leaf(const Patch& p, double u0, double u1, double v0, double v1) {
        const int a = vertex(p[0][0], u0, v0), b = vertex(p[0][3], u0, v1), c = vertex(p[3][3], u1, v1),
                  d = vertex(p[3][0], u1, v0);
        mesh.faces.push_back({{a, b, c}, {a, b, c}});
        mesh.faces.push_back({{a, c, d}, {a, c, d}});
    }

    void build(const Patch& p, double u0, double u1, double v0, double v1, int depth) {
        const double f = flatness(p);
        const bool split_u = depth < u_steps, split_v = depth < v_steps;
        if ((f >= 0.0 && f < flat) || (!split_u && !split_v)) return leaf(p, u0, u1, v0, v1);
        const double um = 0.5 * (u0 + u1), vm = 0.5 * (v0 + v1);
        Patch lo, hi;
        if (!split_u) {
            split(p, false, lo, hi);
            build(lo, u0, u1, v0, vm, depth + 1);
            build(hi, u0, u1, vm, v1, depth + 1);
            return;
        }
        split(p, true, lo, hi);
        if (!split_v) {
            build(lo, u0, um, v0, v1, depth + 1);
            build(hi, um, u1, v0, v1, depth + 1);
            return;
        }
        Patch ll, ul, lr, ur;
        split(lo, false, ll, ul);
        split(hi, false, lr, ur);
        build(ll, u0, um, v0, vm, depth + 1);
        build(ul, u0, um, vm, v1, depth + 1);
        build(lr, um, u1, v0, vm, depth + 1);
        build(ur, um, u1, vm, v1, depth + 1);
    }
};

}  // namespace

std::optional<MeshShape> MeshShape::create(const scene::BicubicPatch& bp) {
    if (!bp.placement->is_invertible()) return std::nullopt;
    Patch world;
    for (int i = 0; i < 16; ++i) {
        if (!is_finite(bp.points[i])) return std::nullopt;
        world[i / 4][i % 4] = bp.placement->point(bp.points[i]);
    }
    Tessellator t{world, bp.placement, bp.placement->inverse(), bp.u_steps, bp.v_steps, bp.flatness, {}, {}};
    t.mesh.kind = scene::Mesh::Kind::Mesh;
    t.build(world, 0.0, 1.0, 0.0, 1.0, 0);
    auto shape = create(t.mesh);
    // POV-Ray compat: a hit's (u, v) is the triangle's blend of its corners' (u, v), as intersect_subpatch gives.
    if (shape) {
        shape->m_params = std::move(t.params);
        // A bicubic patch is POV-Ray's own shape, which gives all its crossings, not a mesh's walk.
        shape->m_nearest_only = false;
    }
    return shape;
}

Vec3 bicubic_patch_uv(const scene::BicubicPatch& patch, const Vec3& params) {
    const auto& st = patch.uv_vectors;
    const double s = params.y, t = params.x;
    const Vec3 a = st[0] + s * (st[1] - st[0]);
    const Vec3 b = st[3] + s * (st[2] - st[3]);
    const Vec3 uv = a + t * (b - a);
    return {uv.x, uv.y, 0.0};
}

}  // namespace wardray::geometry
