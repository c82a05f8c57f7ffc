// SuperellipsoidShape: POV-Ray's `superellipsoid { <e, n> }` inside the box [-1, 1]³, in object space.
#pragma once

#include <optional>

#include "geometry/shape.h"
#include "scene/scene.h"

namespace wardray::geometry {

/// The surface (|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n) = 1, found by marching the ray through the unit box
/// with sign-change bracketing and bisection (POV-Ray also solves it numerically).
class SuperellipsoidShape {
public:
    /// Returns nothing for non-positive or non-finite exponents.
    static std::optional<SuperellipsoidShape> create(const scene::Superellipsoid& s);

    /// Crossings with t in (t_min, t_max), sorted.
    SurfaceHits intersect_all(const LocalRay& ray, double t_min, double t_max) const;
    /// The unit box.
    std::optional<Bounds> bounds() const { return Bounds{{-1, -1, -1}, {1, 1, 1}}; }
    /// True where the implicit function is negative.
    bool inside(const Vec3& p) const { return level(p) < 0.0; }
    /// A normalised form of the implicit function: zero on the surface, negative inside.
    double implicit(const Vec3& p) const;
    /// Whether intersect_all() samples the implicit function's sign four points at a time (glibc's vector pow, where
    /// the CPU has AVX2; chosen once). Tests turn it off to compare with the scalar sampling. Returns whether it is
    /// now used.
    static bool use_vector_pow(bool wanted);

private:
    SuperellipsoidShape(double e, double n) : m_e(e), m_n(n) {}
    Vec3 gradient(const Vec3& p) const;
    /// (|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n) - 1: the implicit function's sign at less cost.
    double level(const Vec3& p) const;

    double m_e;
    double m_n;
};

}  // namespace wardray::geometry
