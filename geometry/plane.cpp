// PlaneShape: normalisation of POV-Ray's plane parameters and the ray-plane crossing.
#include "geometry/plane.h"

#include <cmath>

namespace wardray::geometry {

std::optional<PlaneShape> PlaneShape::create(const scene::Plane& plane) {
    if (!is_finite(plane.normal) || !std::isfinite(plane.distance)) return std::nullopt;
    const double len = length(plane.normal);
    if (!(len > 0.0) || !std::isfinite(len)) return std::nullopt;
    // POV-Ray compat: `plane { <A,B,C>, D }` is A x + B y + C z - D sqrt(A²+B²+C²) = 0, so the distance is
    // measured along the unit normal whatever the normal's length (povray 3.7 puts plane { 2*y, 1 } at y = 1).
    return PlaneShape(plane.normal / len, plane.distance);
}

SurfaceHits PlaneShape::intersect_all(const LocalRay& ray, double t_min, double t_max) const {
    SurfaceHits hits;
    const double denom = dot(m_normal, ray.direction);
    if (denom == 0.0 || !std::isfinite(denom)) return hits;
    const double t = (m_distance - dot(m_normal, ray.origin)) / denom;
    if (t > t_min && t < t_max) hits.push({t, m_normal, denom < 0.0});
    return hits;
}

}  // namespace wardray::geometry
