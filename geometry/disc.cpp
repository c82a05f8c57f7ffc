// DiscShape: a plane crossing accepted between the hole radius and the outer radius.
#include "geometry/disc.h"

#include <cmath>

namespace wardray::geometry {

std::optional<DiscShape> DiscShape::create(const scene::Disc& d) {
    if (!is_finite(d.center) || !is_finite(d.normal) || !std::isfinite(d.radius) || !std::isfinite(d.hole_radius))
        return std::nullopt;
    const double len = length(d.normal);
    if (!(len > 0.0) || d.radius == 0.0) return std::nullopt;
    return DiscShape(d.center, d.normal / len, std::fabs(d.radius), std::fabs(d.hole_radius));
}

SurfaceHits DiscShape::intersect_all(const LocalRay& ray, double t_min, double t_max) const {
    SurfaceHits hits;
    const double denom = dot(m_normal, ray.direction);
    if (denom == 0.0 || !std::isfinite(denom)) return hits;
    const double t = dot(m_normal, m_center - ray.origin) / denom;
    if (!(t > t_min && t < t_max)) return hits;
    const Vec3 v = ray.origin + t * ray.direction - m_center;
    const double r2 = dot(v, v);
    if (r2 > m_r2 || r2 < m_h2) return hits;
    hits.push({t, m_normal, denom < 0.0});
    return hits;
}

std::optional<Bounds> DiscShape::bounds() const {
    const double r = std::sqrt(m_r2);
    Vec3 half;
    for (int k = 0; k < 3; ++k) half[k] = r * std::sqrt(std::fmax(0.0, 1.0 - m_normal[k] * m_normal[k]));
    return Bounds{m_center - half, m_center + half};
}

}  // namespace wardray::geometry
