// Transform: construction, composition and inversion of affine maps.
#include "core/transform.h"

#include <cmath>
#include <numbers>

namespace wardray {

namespace {

Transform::Matrix34 multiply(const Transform::Matrix34& a, const Transform::Matrix34& b) {
    // (a ∘ b): apply b first, then a.
    Transform::Matrix34 r{};
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 4; ++j) {
            double s = 0.0;
            for (int k = 0; k < 3; ++k) s += a[i][k] * b[k][j];
            r[i][j] = s + (j == 3 ? a[i][3] : 0.0);
        }
    }
    return r;
}

// Inverts the affine matrix by cofactors; returns false when the linear part is singular relative to its scale.
bool invert(const Transform::Matrix34& m, Transform::Matrix34& out) {
    const double c00 = m[1][1] * m[2][2] - m[1][2] * m[2][1];
    const double c01 = m[1][2] * m[2][0] - m[1][0] * m[2][2];
    const double c02 = m[1][0] * m[2][1] - m[1][1] * m[2][0];
    const double det = m[0][0] * c00 + m[0][1] * c01 + m[0][2] * c02;
    double norm = 0.0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) norm = std::fmax(norm, std::fabs(m[i][j]));
    // Scale-free singularity test: compare det with the cube of the largest entry.
    if (!std::isfinite(det) || norm == 0.0 || std::fabs(det) <= 1e-14 * norm * norm * norm) return false;
    const double inv_det = 1.0 / det;
    out[0][0] = c00 * inv_det;
    out[0][1] = (m[0][2] * m[2][1] - m[0][1] * m[2][2]) * inv_det;
    out[0][2] = (m[0][1] * m[1][2] - m[0][2] * m[1][1]) * inv_det;
    out[1][0] = c01 * inv_det;
    out[1][1] = (m[0][0] * m[2][2] - m[0][2] * m[2][0]) * inv_det;
    out[1][2] = (m[0][2] * m[1][0] - m[0][0] * m[1][2]) * inv_det;
    out[2][0] = c02 * inv_det;
    out[2][1] = (m[0][1] * m[2][0] - m[0][0] * m[2][1]) * inv_det;
    out[2][2] = (m[0][0] * m[1][1] - m[0][1] * m[1][0]) * inv_det;
    for (int i = 0; i < 3; ++i)
        out[i][3] = -(out[i][0] * m[0][3] + out[i][1] * m[1][3] + out[i][2] * m[2][3]);
    return true;
}

}  // namespace

Transform::Matrix34 Transform::identity_matrix() {
    return {{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}}};
}

Transform::Transform(const Matrix34& forward, const Matrix34& inverse, bool invertible)
    : m_forward(forward), m_inverse(inverse), m_identity(forward == identity_matrix()), m_invertible(invertible) {}

Transform Transform::translation(const Vec3& v) {
    Matrix34 f = identity_matrix();
    Matrix34 i = identity_matrix();
    for (int k = 0; k < 3; ++k) {
        f[k][3] = v[k];
        i[k][3] = -v[k];
    }
    return Transform(f, i, true);
}

Transform Transform::scaling(const Vec3& s) {
    Matrix34 f = identity_matrix();
    Matrix34 i = identity_matrix();
    bool invertible = true;
    for (int k = 0; k < 3; ++k) {
        f[k][k] = s[k];
        if (s[k] == 0.0 || !std::isfinite(s[k])) {
            invertible = false;
            i[k][k] = 0.0;
        } else {
            i[k][k] = 1.0 / s[k];
        }
    }
    return Transform(f, i, invertible);
}

Transform Transform::rotation(const Vec3& degrees) {
    // POV-Ray compat: rotate about x, then y, then z; each is the usual right-handed formula applied to
    // left-handed coordinates, which makes positive angles turn clockwise seen from the positive axis.
    Transform result;
    for (int axis = 0; axis < 3; ++axis) {
        if (degrees[axis] == 0.0) continue;
        const double a = degrees[axis] * std::numbers::pi / 180.0;
        const double c = std::cos(a);
        const double s = std::sin(a);
        Matrix34 f = identity_matrix();
        const int u = (axis + 1) % 3;
        const int v = (axis + 2) % 3;
        f[u][u] = c;
        f[u][v] = -s;
        f[v][u] = s;
        f[v][v] = c;
        Matrix34 inv = identity_matrix();
        inv[u][u] = c;
        inv[u][v] = s;
        inv[v][u] = -s;
        inv[v][v] = c;
        result = result.then(Transform(f, inv, true));
    }
    return result;
}

std::optional<Transform> Transform::from_pov_matrix(const std::array<double, 12>& m) {
    // POV-Ray's rows are images of the basis vectors (row-vector convention): transpose into column form.
    Matrix34 f{};
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) f[i][j] = m[j * 3 + i];
        f[i][3] = m[9 + i];
    }
    Matrix34 inv{};
    if (!invert(f, inv)) return Transform(f, identity_matrix(), false);
    return Transform(f, inv, true);
}

Transform Transform::then(const Transform& next) const {
    if (m_identity) return next;
    if (next.m_identity) return *this;
    // POV-Ray compat: the inverse is composed from the two inverses, (next ∘ this)^-1 = this^-1 ∘ next^-1, as
    // POV-Ray composes its transforms, never re-inverted: re-inverting judged woods.inc's `bozo scale
    // <0.01, 0.01, 100000>` under `rotate x*90` singular (det 10 against a largest entry of 1e5) and dropped it.
    const Matrix34 f = multiply(next.m_forward, m_forward);
    const bool invertible = m_invertible && next.m_invertible;
    if (!invertible) return Transform(f, identity_matrix(), false);
    return Transform(f, multiply(m_inverse, next.m_inverse), true);
}

Transform Transform::inverse() const {
    return Transform(m_inverse, m_forward, m_invertible);
}

Vec3 Transform::point(const Vec3& p) const { return point_through(m_forward, p); }

Vec3 Transform::vector(const Vec3& v) const { return vector_through(m_forward, v); }

Vec3 Transform::normal(const Vec3& n) const { return normal_through(m_inverse, n); }

}  // namespace wardray
