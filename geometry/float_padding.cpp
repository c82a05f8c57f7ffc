// Float padding: the scene-wide pad of the boxes in Embree's BVH, and the smaller one for rays from near the objects.
#include "geometry/float_padding.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace wardray::geometry {

namespace {

Bounds grown(const Bounds& b, double pad) {
    const Vec3 v{pad, pad, pad};
    return {b.lower - v, b.upper + v};
}

}  // namespace

std::vector<Bounds> padded_for_scene(const std::vector<Bounds>& boxes, double scene_magnitude) {
    const double scene_pad = 1e-6 * scene_magnitude;
    std::vector<Bounds> out;
    out.reserve(boxes.size());
    for (const Bounds& b : boxes) out.push_back(grown(b, scene_pad + 1e-6 * max_abs_component(b.upper - b.lower)));
    return out;
}

std::vector<Bounds> padded_for_origins(const std::vector<Bounds>& boxes, const std::vector<Bounds>& loose,
                                       double origin_magnitude) {
    std::vector<Bounds> out;
    out.reserve(boxes.size());
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        const Bounds& b = boxes[i];
        const double near = 1e-6 * (origin_magnitude + b.magnitude()) + 1e-6 * max_abs_component(b.upper - b.lower);
        out.push_back(near < loose[i].upper.x - b.upper.x ? grown(b, near) : loose[i]);
    }
    return out;
}

double near_origin_magnitude(const std::vector<Bounds>& boxes, double scene_magnitude) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    if (boxes.empty()) return inf;
    std::vector<double> m;
    m.reserve(boxes.size());
    for (const Bounds& b : boxes) m.push_back(b.magnitude());
    const auto mid = m.begin() + static_cast<std::ptrdiff_t>(m.size() / 2);
    std::nth_element(m.begin(), mid, m.end());
    const double limit = 1e3 * std::fmax(*mid, 1e-300);
    double near = 0.0;
    for (const double x : m)
        if (x <= limit) near = std::fmax(near, x);
    if (!(near > 0.0) || !(16.0 * near < scene_magnitude)) return inf;
    return near;
}

}  // namespace wardray::geometry
