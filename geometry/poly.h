// PolyShape: POV-Ray's polynomial surfaces `quartic`, `cubic`, `poly` and `polynomial` of any order in object space.
#pragma once

#include <optional>
#include <vector>

#include "geometry/shape.h"
#include "scene/scene.h"

namespace wardray::geometry {

/// The surface f(p) = 0 of a polynomial of degree at most 35 in x, y, z; inside where f is below POV-Ray's
/// tolerance. Unbounded unless clipped or intersected. Orders 3 and 4: POV-Ray compat, the polynomial in the
/// distance along the unit direction from the ray's own origin, expanded and solved as POV-Ray 3.7 does (closed
/// form unless `sturm`), so that where its closed forms invent roots (the thin stray lines of lemnisc2.pov) or lose
/// them, this draws the same. Other orders: the polynomial in the distance from the ray's point nearest the
/// origin, isolated within Cauchy's root bound (POV-Ray's Sturm sequences find the same roots, less precisely).
class PolyShape {
public:
    /// Returns nothing when a coefficient is not finite or all but the constant vanish.
    static std::optional<PolyShape> create(const scene::Quartic& quartic);
    static std::optional<PolyShape> create(const scene::Poly& poly);

    /// The crossings with t in (t_min, t_max), sorted.
    SurfaceHits intersect_all(const LocalRay& ray, double t_min, double t_max) const;
    /// Polynomials are treated as unbounded.
    std::optional<Bounds> bounds() const { return std::nullopt; }
    /// True where the polynomial is below the tolerance (POV-Ray's Inside, for quartic 0).
    bool inside(const Vec3& p) const { return implicit(p) < m_inside_tolerance; }
    /// The polynomial's value.
    double implicit(const Vec3& p) const;
    /// The polynomial's gradient.
    Vec3 gradient(const Vec3& p) const;

private:
    /// One monomial a x^i y^j z^k.
    struct Term {
        double a;
        int i, j, k;
    };

    PolyShape() = default;
    static std::optional<PolyShape> from_coefficients(const double* coefficients, int order);
    /// Orders other than 3 and 4: the crossings by root isolation on the centred line.
    SurfaceHits intersect_centred(const LocalRay& ray, double t_min, double t_max) const;
    /// Orders 3 and 4: the crossings POV-Ray finds.
    SurfaceHits intersect_pov(const LocalRay& ray, double t_min, double t_max) const;

    std::vector<Term> m_terms;
    int m_order = 4;
    double m_inside_tolerance = 0.0;
    bool m_sturm = false;
};

}  // namespace wardray::geometry
