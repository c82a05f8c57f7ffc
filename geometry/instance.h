// ShapeInstance: one scene object ready for intersection (shape, transform, inverse flag, visibility flags).
#pragma once

#include <cstdint>
#include <optional>
#include <variant>

#include "geometry/box.h"
#include "geometry/plane.h"
#include "geometry/scene_geometry.h"
#include "geometry/sphere.h"
#include "parser/scene.h"

namespace wardray::geometry {

/// Any primitive shape in object space.
using AnyShape = std::variant<SphereShape, BoxShape, PlaneShape>;

/// A scene object placed in the world; every query is in double precision on the world ray.
class ShapeInstance {
public:
    /// Returns nothing for objects that cannot be drawn without NaN: singular transforms, degenerate shapes,
    /// non-finite parameters or bounds. `index` is the object's position in parser::Scene::objects.
    static std::optional<ShapeInstance> create(const parser::Object& object, std::uint32_t index);

    /// Surface crossings of the world ray with t in (t_min, t_max); normals are unit, world space, pointing
    /// out of the object (inverse objects flip them and the entering flags).
    SurfaceHits intersect_all(const Vec3& origin, const Vec3& direction, double t_min, double t_max) const;
    /// The nearest crossing with t in (t_min, t_max), as a Hit.
    std::optional<Hit> nearest(const Vec3& origin, const Vec3& direction, double t_min, double t_max) const;
    /// True when a ray of this kind sees the object.
    bool visible_to(RayKind kind) const;
    /// True for points inside the object (after `inverse`).
    bool inside(const Vec3& p_world) const;
    /// World-space bounds of the surface, or nothing when the surface is unbounded (planes).
    const std::optional<Bounds>& world_bounds() const { return m_world_bounds; }
    /// Signed implicit function in object space at the world point (0 on the surface, negative inside the
    /// shape before `inverse`); for tests and diagnostics.
    double object_implicit(const Vec3& p_world) const;
    /// The object's index in parser::Scene::objects and its object-to-world transform.
    std::uint32_t index() const { return m_index; }
    const Transform& transform() const { return m_transform; }

private:
    ShapeInstance(const AnyShape& shape, const parser::Object& object, std::uint32_t index);

    AnyShape m_shape;
    Transform m_transform;
    std::optional<Bounds> m_world_bounds;
    std::uint32_t m_index = 0;
    bool m_inverse = false;
    bool m_no_shadow = false;
    bool m_no_image = false;
    bool m_no_reflection = false;
    bool m_no_radiosity = false;
};

}  // namespace wardray::geometry
