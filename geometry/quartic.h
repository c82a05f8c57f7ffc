// QuarticShape: POV-Ray's general fourth-degree surface `quartic { <a0, ..., a34> }` in object space.
#pragma once

#include <array>
#include <optional>

#include "geometry/shape.h"
#include "scene/scene.h"

namespace wardray::geometry {

/// The surface f(p) = 0 of a polynomial of degree at most 4 in x, y, z; inside where f < 0. Unbounded unless
/// clipped or intersected. Along a ray f is a quartic in t, solved by root isolation within Cauchy's root bound.
class QuarticShape {
public:
    /// Returns nothing when a coefficient is not finite or all but the constant vanish.
    static std::optional<QuarticShape> create(const scene::Quartic& quartic);

    /// Up to four crossings with t in (t_min, t_max), sorted.
    SurfaceHits intersect_all(const LocalRay& ray, double t_min, double t_max) const;
    /// Quartics are treated as unbounded.
    std::optional<Bounds> bounds() const { return std::nullopt; }
    /// True where the polynomial is negative.
    bool inside(const Vec3& p) const { return implicit(p) < 0.0; }
    /// The polynomial's value.
    double implicit(const Vec3& p) const;

private:
    /// One monomial a x^i y^j z^k.
    struct Term {
        double a;
        int i, j, k;
    };

    QuarticShape() = default;
    Vec3 gradient(const Vec3& p) const;

    std::array<Term, 35> m_terms{};
    int m_count = 0;
};

}  // namespace wardray::geometry
