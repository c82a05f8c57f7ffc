// Bounds of a CSG intersection whose children are unbounded one by one (planes, quadrics) but bounded together.
#pragma once

#include <optional>
#include <vector>

#include "geometry/shape.h"

namespace wardray::geometry {

/// The points p with dot(normal, p) <= distance (in the CSG's space).
struct HalfSpace {
    Vec3 normal;
    double distance = 0.0;
};

/// The points p with Σ_k (squares_k p_k² + linear_k p_k) + constant <= 0: a quadric without mixed terms.
struct AxisQuadric {
    Vec3 squares;
    Vec3 linear;
    double constant = 0.0;
};

/// Constraints every point of an intersection's inside lies within, and what is left of `box` under them.
class IntersectionBounds {
public:
    void add(const HalfSpace& h) { m_planes.push_back(h); }
    void add(const AxisQuadric& q) { m_quadrics.push_back(q); }
    bool empty() const { return m_planes.empty() && m_quadrics.empty(); }

    /// A box holding every point of `box` (nothing: all space) that meets all the constraints, found by narrowing
    /// each axis in turn by each constraint over the others' current ranges; padded for rounding. Nothing when some
    /// axis stays unbounded (or beyond 1e9, POV-Ray's scale of the unbounded).
    std::optional<Bounds> narrow(const std::optional<Bounds>& box) const;

private:
    std::vector<HalfSpace> m_planes;
    std::vector<AxisQuadric> m_quadrics;
};

}  // namespace wardray::geometry
