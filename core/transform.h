// Transform: an affine map with its inverse, composed in the order POV-Ray applies `translate rotate scale matrix`.
#pragma once

#include <array>
#include <optional>

#include "core/vec3.h"

namespace wardray {

/// Affine transform stored as a 3x4 row-major matrix (rotation/scale part and translation) plus its inverse.
/// Points map as p' = M p + t, so `then(b)` applies this transform first and `b` second, as POV-Ray composes
/// successive transform keywords.
class Transform {
public:
    using Matrix34 = std::array<std::array<double, 4>, 3>;

    Transform() = default;

    static Transform translation(const Vec3& v);
    static Transform scaling(const Vec3& s);  ///< scale 0 components give a singular map: see is_invertible().
    /// POV-Ray's `rotate <a,b,c>`: degrees, about x, then y, then z, left-handed (positive angles turn clockwise
    /// when looking down the axis toward the origin).
    static Transform rotation(const Vec3& degrees);
    /// POV-Ray's `matrix <m00,m01,m02, m10,m11,m12, m20,m21,m22, m30,m31,m32>` (row vectors: p' = p M).
    static std::optional<Transform> from_pov_matrix(const std::array<double, 12>& m);

    /// This transform followed by `next`.
    Transform then(const Transform& next) const;
    Transform inverse() const;
    bool is_identity() const { return m_identity; }
    bool is_invertible() const { return m_invertible; }

    Vec3 point(const Vec3& p) const;
    Vec3 vector(const Vec3& v) const;
    /// Transforms a surface normal (inverse transpose); the result is not normalized.
    Vec3 normal(const Vec3& n) const;
    /// Inline: every shape test of every ray maps the ray into object space through these two.
    Vec3 inverse_point(const Vec3& p) const { return point_through(m_inverse, p); }
    Vec3 inverse_vector(const Vec3& v) const { return vector_through(m_inverse, v); }

    /// The arithmetic of point(), vector() and normal() on a matrix of their kind (a forward or an inverse matrix),
    /// for a copy of one kept elsewhere: the same operations in the same order, so the same bits.
    static Vec3 point_through(const Matrix34& m, const Vec3& p) {
        return {m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z + m[0][3],
                m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z + m[1][3],
                m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z + m[2][3]};
    }
    static Vec3 vector_through(const Matrix34& m, const Vec3& v) {
        return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z, m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
                m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
    }
    /// A normal through the transform whose inverse matrix is `inverse`: (M^-1)^T n, not normalized.
    static Vec3 normal_through(const Matrix34& inverse, const Vec3& n) {
        const auto& m = inverse;
        return {m[0][0] * n.x + m[1][0] * n.y + m[2][0] * n.z, m[0][1] * n.x + m[1][1] * n.y + m[2][1] * n.z,
                m[0][2] * n.x + m[1][2] * n.y + m[2][2] * n.z};
    }

    const Matrix34& matrix() const { return m_forward; }
    bool operator==(const Transform&) const = default;
    const Matrix34& inverse_matrix() const { return m_inverse; }

private:
    Transform(const Matrix34& forward, const Matrix34& inverse, bool invertible);
    static Matrix34 identity_matrix();

    Matrix34 m_forward = identity_matrix();
    Matrix34 m_inverse = identity_matrix();
    bool m_identity = true;
    bool m_invertible = true;
};

}  // namespace wardray
