// ConeShape: the side as a quadratic in t (one Newton step for far origins) and the two end discs.
#include "geometry/cone.h"

#include <algorithm>
#include <cmath>

#include "core/constants.h"

namespace wardray::geometry {

namespace {

using Matrix4 = std::array<std::array<double, 4>, 4>;

/// The first three columns of a matrix whose last column is (0, 0, 0, 1), and back.
std::array<std::array<double, 3>, 4> rows3(const Matrix4& m) {
    std::array<std::array<double, 3>, 4> r{};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 3; ++j) r[i][j] = m[i][j];
    return r;
}
Matrix4 full4(const std::array<std::array<double, 3>, 4>& r) {
    Matrix4 m{};
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 3; ++j) m[i][j] = r[i][j];
        m[i][3] = i == 3 ? 1.0 : 0.0;
    }
    return m;
}

Matrix4 identity4() { return {{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}}; }

// a × b, each entry summed in the order of its index (POV-Ray's MTimesB).
Matrix4 product(const Matrix4& a, const Matrix4& b) {
    Matrix4 r{};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            r[i][j] = a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j] + a[i][3] * b[3][j];
    return r;
}

// POV-Ray compat (Compute_Cylinder_Data, Compute_Coordinate_Transform): the inverse of the transform that takes
// the unit cylinder (radius 1, z from 0 to 1) to the one from `base` along the unit `axis` of length `len`: scale,
// then a turn about an axis across z by acos(axis.z), then the move to `base`; each inverse composed as POV-Ray's
// Compose_Transforms does (additional inverse times original inverse).
Matrix4 unit_cylinder_inverse(const Vec3& base, Vec3 axis, double radius, double len) {
    Matrix4 scale = identity4();
    scale[0][0] = 1.0 / radius;
    scale[1][1] = 1.0 / radius;
    scale[2][2] = 1.0 / len;
    Vec3 turn_axis;
    if (std::fabs(axis.z) > 1.0 - kPovEpsilon) {
        turn_axis = {1.0, 0.0, 0.0};
        axis.z = axis.z < 0.0 ? -1.0 : 1.0;
    } else {
        turn_axis = {-axis.y, axis.x, 0.0};
    }
    // Compute_Axis_Rotation_Transform: its matrix about the normalised axis; the inverse is the transpose.
    const double inv_len = 1.0 / std::sqrt(turn_axis.x * turn_axis.x + turn_axis.y * turn_axis.y +
                                           turn_axis.z * turn_axis.z);
    const Vec3 v{turn_axis.x * inv_len, turn_axis.y * inv_len, turn_axis.z * inv_len};
    const double angle = std::acos(axis.z);
    const double c = std::cos(angle), s = std::sin(angle);
    Matrix4 m = identity4();
    m[0][0] = v.x * v.x + c * (1.0 - v.x * v.x);
    m[0][1] = v.x * v.y * (1.0 - c) + v.z * s;
    m[0][2] = v.x * v.z * (1.0 - c) - v.y * s;
    m[1][0] = v.x * v.y * (1.0 - c) - v.z * s;
    m[1][1] = v.y * v.y + c * (1.0 - v.y * v.y);
    m[1][2] = v.y * v.z * (1.0 - c) + v.x * s;
    m[2][0] = v.x * v.z * (1.0 - c) + v.y * s;
    m[2][1] = v.y * v.z * (1.0 - c) - v.x * s;
    m[2][2] = v.z * v.z + c * (1.0 - v.z * v.z);
    Matrix4 turn = identity4();
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) turn[i][j] = m[j][i];
    Matrix4 move = identity4();
    move[3][0] = -base.x;
    move[3][1] = -base.y;
    move[3][2] = -base.z;
    return product(move, product(turn, scale));
}

}  // namespace

ConeShape::ConeShape(const Vec3& base, const Vec3& cap, double r0, double r1, bool open)
    : m_base(base), m_r0(r0), m_r1(r1), m_open(open) {
    const Vec3 d = cap - base;
    m_height = length(d);
    m_axis = d / m_height;
    m_slope = (r1 - r0) / m_height;
    if (r0 == r1) {
        // POV-Ray compat: its apex is the first point (our base), its base the second (our cap); the unit
        // cylinder's axis runs from the second to the first.
        const Vec3 axis{base.x - cap.x, base.y - cap.y, base.z - cap.z};
        const double len = std::sqrt(axis.x * axis.x + axis.y * axis.y + axis.z * axis.z);
        const double inv = 1.0 / len;
        const Vec3 unit_axis{axis.x * inv, axis.y * inv, axis.z * inv};
        auto matrices = std::make_shared<CylinderMatrices>();
        matrices->unit_inverse = rows3(unit_cylinder_inverse(cap, unit_axis, r0, len));
        m_matrices = std::move(matrices);
    }
}

Vec3 ConeShape::cylinder_normal(const Vec3& p) const {
    // Cone::Normal: the point into unit space (MInvTransPoint), its z dropped, back as a normal (MTransNormal),
    // normalised by the reciprocal of its length (VNormalize).
    if (!m_matrices) return Vec3{NAN, NAN, NAN};
    const Rows& m = m_matrices->unit_inverse;
    const double x = p.x * m[0][0] + p.y * m[1][0] + p.z * m[2][0] + m[3][0];
    const double y = p.x * m[0][1] + p.y * m[1][1] + p.z * m[2][1] + m[3][1];
    const double z = 0.0;
    const Vec3 n{x * m[0][0] + y * m[0][1] + z * m[0][2], x * m[1][0] + y * m[1][1] + z * m[1][2],
                 x * m[2][0] + y * m[2][1] + z * m[2][2]};
    const double inv = 1.0 / std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
    return {n.x * inv, n.y * inv, n.z * inv};
}

Vec3 ConeShape::object_normal(double x, double y, double z) const {
    // MTransNormal through the unit cylinder's inverse, then VNormalize.
    const Rows& m = m_matrices->unit_inverse;
    const Vec3 n{x * m[0][0] + y * m[0][1] + z * m[0][2], x * m[1][0] + y * m[1][1] + z * m[1][2],
                 x * m[2][0] + y * m[2][1] + z * m[2][2]};
    const double inv = 1.0 / std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
    return {n.x * inv, n.y * inv, n.z * inv};
}

void ConeShape::place(const Transform& object_to_parent) {
    if (!m_matrices) return;
    // The object's inverse in POV-Ray's layout (row vectors), composed before the unit cylinder's inverse as
    // Compose_Transforms composes an additional transform's inverse (MTimesB).
    const Transform::Matrix34& c = object_to_parent.inverse_matrix();
    Matrix4 object_inverse = identity4();
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) object_inverse[i][j] = c[j][i];
        object_inverse[3][i] = c[i][3];
    }
    auto matrices = std::make_shared<CylinderMatrices>(*m_matrices);
    matrices->placed = rows3(product(object_inverse, full4(m_matrices->unit_inverse)));
    matrices->is_placed = true;
    m_matrices = std::move(matrices);
}

SurfaceHits ConeShape::intersect_parent(const Vec3& origin, const Vec3& direction, double t_min,
                                        double t_max) const {
    // POV-Ray compat (Cone::Intersect for a cylinder): the ray into unit space (MInvTransPoint,
    // MInvTransDirection), its direction normalised, the side's quadratic and the caps solved there, each depth
    // divided by the direction's length; Cone_Tolerance, MAX_DISTANCE and EPSILON as POV-Ray has them.
    constexpr double k_cone_tolerance = 1e-9;
    constexpr double k_max_distance = 1e7;
    const Rows& m = m_matrices->placed;
    double p[3], d[3];
    for (int i = 0; i < 3; ++i) {
        p[i] = origin.x * m[0][i] + origin.y * m[1][i] + origin.z * m[2][i] + m[3][i];
        d[i] = direction.x * m[0][i] + direction.y * m[1][i] + direction.z * m[2][i];
    }
    const double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    const double inv_len = 1.0 / len;
    for (double& v : d) v *= inv_len;
    struct Found {
        double t;
        int kind;  // 0 side, 1 the cap at unit z = 1, 2 the one at z = 0
    };
    Found found[4];
    int n = 0;
    const double a = d[0] * d[0] + d[1] * d[1];
    if (a > kPovEpsilon) {
        const double b = p[0] * d[0] + p[1] * d[1];
        const double c = p[0] * p[0] + p[1] * p[1] - 1.0;
        double disc = b * b - a * c;
        if (disc >= 0.0) {
            disc = std::sqrt(disc);
            for (const double t : {(-b + disc) / a, (-b - disc) / a}) {
                const double z = p[2] + t * d[2];
                if (t > k_cone_tolerance && t < k_max_distance && z >= 0.0 && z <= 1.0) found[n++] = {t / len, 0};
            }
        }
    }
    if (!m_open && std::fabs(d[2]) > kPovEpsilon) {
        for (int e = 0; e < 2; ++e) {
            const double t = ((e == 0 ? 1.0 : 0.0) - p[2]) / d[2];
            const double x = p[0] + t * d[0], y = p[1] + t * d[1];
            if (x * x + y * y <= 1.0 && t > k_cone_tolerance && t < k_max_distance) found[n++] = {t / len, 1 + e};
        }
    }
    SurfaceHits hits;
    for (int i = 1; i < n; ++i)
        for (int j = i; j > 0 && found[j].t < found[j - 1].t; --j) std::swap(found[j], found[j - 1]);
    for (int i = 0; i < n; ++i) {
        const double t = found[i].t;
        if (!(t > t_min && t < t_max)) continue;
        if (found[i].kind != 0) {
            // The cap at unit z = 1 is the first point's end (our base), its normal -axis; the other +axis.
            const Vec3 normal = found[i].kind == 1 ? -m_axis : m_axis;
            hits.push({t, normal, (found[i].kind == 1 ? d[2] : -d[2]) < 0.0});
            continue;
        }
        // Cone::Normal: the hit point (VEvaluateRay in the parent's space) back into unit space, its z dropped.
        const Vec3 at{origin.x + t * direction.x, origin.y + t * direction.y, origin.z + t * direction.z};
        const double x = at.x * m[0][0] + at.y * m[1][0] + at.z * m[2][0] + m[3][0];
        const double y = at.x * m[0][1] + at.y * m[1][1] + at.z * m[2][1] + m[3][1];
        // Entering where the unit normal opposes the unit direction (a linear map keeps the sign of n·d).
        hits.push({t, object_normal(x, y, 0.0), x * d[0] + y * d[1] < 0.0});
    }
    return hits;
}

bool ConeShape::inside_parent(const Vec3& q) const {
    // POV-Ray compat (Cone::Inside): in unit space, EPSILON inward for a closed cylinder and outward for an open one.
    const Rows& m = m_matrices->placed;
    const double x = q.x * m[0][0] + q.y * m[1][0] + q.z * m[2][0] + m[3][0];
    const double y = q.x * m[0][1] + q.y * m[1][1] + q.z * m[2][1] + m[3][1];
    const double z = q.x * m[0][2] + q.y * m[1][2] + q.z * m[2][2] + m[3][2];
    const double offset = m_open ? kPovEpsilon : -kPovEpsilon;
    const double w2 = x * x + y * y;
    return !(w2 > 1.0 + offset || z < 0.0 - offset || z > 1.0 + offset);
}

std::optional<ConeShape> ConeShape::create(const scene::Cone& c) {
    if (!is_finite(c.base) || !is_finite(c.cap) || !std::isfinite(c.base_radius) || !std::isfinite(c.cap_radius))
        return std::nullopt;
    const double h = length(c.cap - c.base);
    if (!(h > 0.0) || !std::isfinite(h)) return std::nullopt;
    // POV-Ray compat: radii are taken by absolute value; a cone needs a non-zero radius at one end.
    const double r0 = std::fabs(c.base_radius);
    const double r1 = std::fabs(c.cap_radius);
    if (r0 == 0.0 && r1 == 0.0) return std::nullopt;
    return ConeShape(c.base, c.cap, r0, r1, c.open);
}

std::optional<ConeShape> ConeShape::create(const scene::Cylinder& c) {
    if (c.radius == 0.0) return std::nullopt;
    return create(scene::Cone{c.base, c.radius, c.cap, c.radius, c.open});
}

SurfaceHits ConeShape::intersect_all(const LocalRay& ray, double t_min, double t_max) const {
    SurfaceHit found[4];
    int n = 0;
    const Vec3 o = ray.origin - m_base;
    const Vec3& d = ray.direction;
    const double os = dot(o, m_axis);
    const double ds = dot(d, m_axis);
    const Vec3 op = o - os * m_axis;
    const Vec3 dp = d - ds * m_axis;
    // Side: |o⊥ + t d⊥|² = (r0 + k (os + t ds))², as a t² + 2 b t + c = 0.
    const double k = m_slope;
    const double r_o = m_r0 + k * os;
    const double a = dot(dp, dp) - k * k * ds * ds;
    const double b = dot(op, dp) - k * ds * r_o;
    const double c = dot(op, op) - r_o * r_o;
    auto side = [&](double t) {
        // One Newton step on the quadratic removes most of the cancellation error of far origins.
        const double f = (a * t + 2.0 * b) * t + c;
        const double df = 2.0 * (a * t + b);
        if (df != 0.0) t -= f / df;
        const double s = os + t * ds;
        if (!(s > 0.0 && s < m_height) || !(t > t_min && t < t_max)) return;
        const Vec3 p = o + t * d;
        const Vec3 pp = p - s * m_axis;
        Vec3 normal = pp - (k * (m_r0 + k * s)) * m_axis;
        if (m_matrices) {
            // POV-Ray compat: a cylinder's normal in POV-Ray's arithmetic, at the point POV-Ray evaluates.
            const Vec3 at{ray.origin.x + t * ray.direction.x, ray.origin.y + t * ray.direction.y,
                          ray.origin.z + t * ray.direction.z};
            const Vec3 pov = cylinder_normal(at);
            if (is_finite(pov)) normal = pov;
        }
        found[n++] = {t, normal, dot(normal, d) < 0.0};
    };
    if (a != 0.0) {
        const double disc = b * b - a * c;
        if (disc >= 0.0) {
            const double q = -(b + std::copysign(std::sqrt(disc), b));
            if (q != 0.0) {
                side(c / q);
                side(q / a);
            }
        }
    } else if (b != 0.0) {
        side(-c / (2.0 * b));
    }
    // Caps: the planes s = 0 and s = height within their radii.
    if (!m_open && ds != 0.0) {
        const double ends[2] = {0.0, m_height};
        const double radii[2] = {m_r0, m_r1};
        for (int e = 0; e < 2; ++e) {
            const double t = (ends[e] - os) / ds;
            if (!(t > t_min && t < t_max)) continue;
            const Vec3 pp = op + t * dp;
            if (dot(pp, pp) > radii[e] * radii[e]) continue;
            const Vec3 normal = e == 0 ? -m_axis : m_axis;
            found[n++] = {t, normal, dot(normal, d) < 0.0};
        }
    }
    // At most four crossings: an insertion sort (std::sort here trips GCC 12's -Warray-bounds false positive).
    for (int i = 1; i < n; ++i)
        for (int j = i; j > 0 && found[j].t < found[j - 1].t; --j) std::swap(found[j], found[j - 1]);
    SurfaceHits hits;
    for (int i = 0; i < n; ++i) hits.push(found[i]);
    return hits;
}

std::optional<Bounds> ConeShape::bounds() const {
    // Each end disc spans r * sqrt(1 - axis_k²) along world axis k.
    Bounds b{m_base, m_base};
    const Vec3 ends[2] = {m_base, m_base + m_height * m_axis};
    const double radii[2] = {m_r0, m_r1};
    for (int e = 0; e < 2; ++e) {
        Vec3 half;
        for (int k = 0; k < 3; ++k) half[k] = radii[e] * std::sqrt(std::fmax(0.0, 1.0 - m_axis[k] * m_axis[k]));
        b = b.merged({ends[e] - half, ends[e] + half});
    }
    return b;
}

bool ConeShape::inside(const Vec3& p) const {
    const Vec3 o = p - m_base;
    const double s = dot(o, m_axis);
    const Vec3 pp = o - s * m_axis;
    const double r = m_r0 + m_slope * s;
    if (m_open) {
        // POV-Ray compat: an open cone's inside reaches EPSILON beyond its ends and side, measured in its unit
        // space (a cylinder's length and radius; a cone's apex-to-wide-end distance and wide radius), so a
        // surface lying on an open end's plane is inside it (a bowl cut by an open cone keeps no lid).
        const double wide = std::fmax(m_r0, m_r1);
        const double axial = m_slope == 0.0 ? m_height : m_height * wide / std::fabs(m_r1 - m_r0);
        const double radial_sq = m_slope == 0.0 ? kPovEpsilon * r * r : kPovEpsilon * wide * wide;
        const double e = kPovEpsilon * axial;
        if (s < -e || s > m_height + e) return false;
        return dot(pp, pp) <= std::fmax(r, 0.0) * std::fmax(r, 0.0) + radial_sq;
    }
    if (!(s > 0.0 && s < m_height)) return false;
    return dot(pp, pp) < r * r;
}

double ConeShape::implicit(const Vec3& p) const {
    const Vec3 o = p - m_base;
    const double s = dot(o, m_axis);
    const double side = length(o - s * m_axis) - (m_r0 + m_slope * s);
    return std::fmax(side, std::fmax(-s, s - m_height));
}

}  // namespace wardray::geometry
