// ShapeInstance: world-to-object mapping of rays, normals by the inverse transpose, and world bounds.
#include "geometry/instance.h"

#include <cmath>
#include <type_traits>

namespace wardray::geometry {

namespace {

std::optional<AnyShape> make_shape(const parser::Shape& shape) {
    return std::visit(
        [](const auto& s) -> std::optional<AnyShape> {
            using T = std::decay_t<decltype(s)>;
            if constexpr (std::is_same_v<T, parser::Sphere>) {
                if (auto r = SphereShape::create(s)) return AnyShape(*r);
            } else if constexpr (std::is_same_v<T, parser::Box>) {
                if (auto r = BoxShape::create(s)) return AnyShape(*r);
            } else if constexpr (std::is_same_v<T, parser::Plane>) {
                if (auto r = PlaneShape::create(s)) return AnyShape(*r);
            }
            return std::nullopt;
        },
        shape);
}

bool matrix_is_finite(const Transform::Matrix34& m) {
    for (const auto& row : m)
        for (double v : row)
            if (!std::isfinite(v)) return false;
    return true;
}

// World bounds of the object-space box under the transform: the hull of its eight transformed corners.
Bounds transform_bounds(const Bounds& b, const Transform& xf) {
    Bounds out{xf.point(b.lower), xf.point(b.lower)};
    for (int i = 1; i < 8; ++i) {
        const Vec3 corner{(i & 1) ? b.upper.x : b.lower.x, (i & 2) ? b.upper.y : b.lower.y,
                          (i & 4) ? b.upper.z : b.lower.z};
        const Vec3 p = xf.point(corner);
        out.lower = min(out.lower, p);
        out.upper = max(out.upper, p);
    }
    return out;
}

// Exact world bounds of a transformed sphere (an ellipsoid): the half extent along world axis i is
// r times the length of row i of the linear part.
Bounds ellipsoid_bounds(const SphereShape& s, const Transform& xf) {
    const Vec3 c = xf.point(s.center());
    const auto& m = xf.matrix();
    Vec3 half;
    for (int i = 0; i < 3; ++i)
        half[i] = s.radius() * std::sqrt(m[i][0] * m[i][0] + m[i][1] * m[i][1] + m[i][2] * m[i][2]);
    return {c - half, c + half};
}

}  // namespace

ShapeInstance::ShapeInstance(const AnyShape& shape, const parser::Object& object, std::uint32_t index)
    : m_shape(shape),
      m_transform(object.transform),
      m_index(index),
      m_inverse(object.inverse),
      m_no_shadow(object.no_shadow),
      m_no_image(object.no_image),
      m_no_reflection(object.no_reflection),
      m_no_radiosity(object.no_radiosity) {}

std::optional<ShapeInstance> ShapeInstance::create(const parser::Object& object, std::uint32_t index) {
    // Degenerate objects are skipped here and reported by the parser; they must never reach Embree.
    const Transform& xf = object.transform;
    if (!xf.is_invertible() || !matrix_is_finite(xf.matrix()) || !matrix_is_finite(xf.inverse_matrix()))
        return std::nullopt;
    auto shape = make_shape(object.shape);
    if (!shape) return std::nullopt;
    ShapeInstance inst(*shape, object, index);
    if (const auto* sphere = std::get_if<SphereShape>(&inst.m_shape)) {
        inst.m_world_bounds = ellipsoid_bounds(*sphere, xf);
    } else {
        const auto local = std::visit([](const auto& s) { return s.bounds(); }, inst.m_shape);
        if (local) inst.m_world_bounds = transform_bounds(*local, xf);
    }
    if (inst.m_world_bounds &&
        (!is_finite(inst.m_world_bounds->lower) || !is_finite(inst.m_world_bounds->upper)))
        return std::nullopt;
    return inst;
}

SurfaceHits ShapeInstance::intersect_all(const Vec3& origin, const Vec3& direction, double t_min,
                                         double t_max) const {
    // An affine map keeps the ray parameter: M⁻¹(o + t d) = M⁻¹o + t M⁻¹d.
    const LocalRay local{m_transform.inverse_point(origin), m_transform.inverse_vector(direction)};
    const SurfaceHits object_hits =
        std::visit([&](const auto& s) { return s.intersect_all(local, t_min, t_max); }, m_shape);
    SurfaceHits hits;
    for (const SurfaceHit& h : object_hits) {
        Vec3 n = normalize(m_transform.normal(h.normal));
        if (!is_finite(n) || !std::isfinite(h.t)) continue;
        hits.push({h.t, m_inverse ? -n : n, m_inverse ? !h.entering : h.entering});
    }
    return hits;
}

std::optional<Hit> ShapeInstance::nearest(const Vec3& origin, const Vec3& direction, double t_min,
                                          double t_max) const {
    const SurfaceHits hits = intersect_all(origin, direction, t_min, t_max);
    if (hits.empty()) return std::nullopt;
    const SurfaceHit& h = hits[0];
    return Hit{h.t, origin + h.t * direction, h.normal, m_index};
}

bool ShapeInstance::visible_to(RayKind kind) const {
    switch (kind) {
        case RayKind::Camera: return !m_no_image;
        case RayKind::Reflection: return !m_no_reflection;
        case RayKind::Shadow: return !m_no_shadow;
        // POV-Ray compat: no_radiosity makes an object invisible to radiosity (gather) rays.
        case RayKind::Gather: return !m_no_radiosity;
    }
    return true;
}

bool ShapeInstance::inside(const Vec3& p_world) const {
    const Vec3 p = m_transform.inverse_point(p_world);
    const bool in = std::visit([&](const auto& s) { return s.inside(p); }, m_shape);
    return in != m_inverse;
}

double ShapeInstance::object_implicit(const Vec3& p_world) const {
    const Vec3 p = m_transform.inverse_point(p_world);
    return std::visit([&](const auto& s) { return s.implicit(p); }, m_shape);
}

}  // namespace wardray::geometry
