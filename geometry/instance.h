// ShapeInstance: one scene object ready for intersection (shape, transform, inverse, clipping, visibility flags).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <variant>
#include <vector>

#include "geometry/blob.h"
#include "geometry/box.h"
#include "geometry/cone.h"
#include "geometry/csg.h"
#include "geometry/disc.h"
#include "geometry/height_field.h"
#include "geometry/isosurface.h"
#include "geometry/julia_fractal.h"
#include "geometry/lathe.h"
#include "geometry/linear_prism.h"
#include "geometry/mesh.h"
#include "geometry/ovus.h"
#include "geometry/parametric.h"
#include "geometry/plane.h"
#include "geometry/quadric.h"
#include "geometry/poly.h"
#include "geometry/scene_geometry.h"
#include "geometry/sor.h"
#include "geometry/sphere.h"
#include "geometry/sphere_sweep.h"
#include "geometry/spline_prism.h"
#include "geometry/superellipsoid.h"
#include "geometry/text.h"
#include "geometry/torus.h"
#include "scene/scene.h"

namespace wardray::geometry {

/// Any shape in object space (cylinders are cones, triangles and polygons are meshes).
using AnyShape = std::variant<SphereShape, BoxShape, PlaneShape, ConeShape, DiscShape, TorusShape, BlobShape, MeshShape,
                              QuadricShape, PolyShape, SuperellipsoidShape, LatheShape, SorShape, SplinePrismShape,
                              LinearPrismShape, SphereSweepShape, TextShape, IsosurfaceShape, HeightFieldShape,
                              JuliaFractalShape, CsgShape, OvusShape, ParametricShape>;

/// The reason of the last ShapeInstance::create on this thread that returned nothing (cleared by the next top-level
/// create that succeeds).
const SkipReason& last_skip_reason();

/// A scene object placed in its parent's space (the world for top-level objects); every query is in double
/// precision on the parent-space ray. The scene::Object must outlive the instance (hits point at it).
class ShapeInstance {
public:
    /// Returns nothing for objects that cannot be drawn without NaN: singular transforms, degenerate shapes,
    /// non-finite parameters or bounds. `index` is the object's position in scene::Scene::objects;
    /// `flip_inverse` inverts the object once more (the subtracted children of a difference). With `lifetime`
    /// Outlives the instance points at the object's transform, else it keeps a copy.
    static std::optional<ShapeInstance> create(const scene::Object& object, std::uint32_t index,
                                               bool flip_inverse = false,
                                               ObjectLifetime lifetime = ObjectLifetime::MayEnd);

    /// Surface crossings of the ray with t in (t_min, t_max); normals are unit, in the parent's space, pointing
    /// out of the object (inverse objects flip them and the entering flags); `leaf` names the primitive hit.
    SurfaceHits intersect_all(const Vec3& origin, const Vec3& direction, double t_min, double t_max) const;
    /// intersect_all's crossings before their normals are mapped: object-space normals (not unit, inverse not
    /// applied), for callers that keep only some crossings (CSG) and map those with to_parent().
    SurfaceHits object_crossings(const Vec3& origin, const Vec3& direction, double t_min, double t_max) const;
    /// An object_crossings() crossing as intersect_all gives it, or nothing when its normal is not finite.
    std::optional<SurfaceHit> to_parent(const SurfaceHit& h) const;
    /// The nearest crossing with t in (t_min, t_max), as a Hit.
    std::optional<Hit> nearest(const Vec3& origin, const Vec3& direction, double t_min, double t_max) const;
    /// True when intersect_all would find a crossing (shadow rays), without mapping every normal.
    bool crosses(const Vec3& origin, const Vec3& direction, double t_min, double t_max) const;
    /// For meshes: the crossing with one face that Embree found in float, recomputed in double, as a Hit.
    std::optional<Hit> face_hit(const Vec3& origin, const Vec3& direction, std::size_t face, double t_min,
                                double t_max) const;
    /// face_hit() written into `out` (every field), without a copy of the Hit; false, and `out` untouched, where
    /// face_hit() returns nothing. `flat_normals`, when given, holds face_world_normal() of every face (all flat).
    bool face_hit_into(const Vec3& origin, const Vec3& direction, std::size_t face, double t_min, double t_max,
                       Hit& out, const Vec3* flat_normals = nullptr) const;
    /// For meshes: the unit world normal face_hit() gives at a crossing of a face (`inverse` applied), not finite
    /// where it refuses the face for want of one; on a flat face the same at every crossing.
    Vec3 face_world_normal(std::size_t face, const MeshShape::FaceCrossing& crossing) const;
    /// For meshes: false when face_hit() finds no crossing for want of one in (t_min, t_max), true when it finds one
    /// or refuses it only for a normal that maps to no finite one; cheaper, without the normal.
    bool face_crossed(const Vec3& origin, const Vec3& direction, std::size_t face, double t_min, double t_max) const;
    /// True when a ray of this kind sees the object (inline: Embree's callbacks ask it of every candidate hit).
    bool visible_to(RayKind kind) const {
        switch (kind) {
            case RayKind::Camera: return !m_no_image;
            case RayKind::Reflection: return !m_no_reflection;
            case RayKind::Shadow: return !m_no_shadow;
            // POV-Ray compat: no_radiosity makes an object invisible to radiosity (gather) rays.
            case RayKind::Gather: return !m_no_radiosity;
        }
        return true;
    }
    /// True for points inside the object (after `inverse`, and within every clipping object).
    bool inside(const Vec3& p_world) const;
    /// POV-Ray compat (Find_Intersection): a top-level object is tested only on rays that meet its bounding box,
    /// which changes the picture only where a clipped surface leaves its clip's box (a cylinder clipped by a
    /// height field, whose inside reaches down without end); set for the clipped top-level objects.
    void cull_by_bounds();
    /// Bounds of the surface, or nothing when the surface is unbounded (planes, quadrics).
    std::optional<Bounds> world_bounds() const {
        return m_has_world_bounds ? std::optional<Bounds>(m_world_bounds) : std::nullopt;
    }
    /// Bounds of the inside region, or nothing when it is unbounded (inverse objects, planes, discs).
    std::optional<Bounds> region_bounds() const {
        return m_has_region_bounds ? std::optional<Bounds>(m_region_bounds) : std::nullopt;
    }
    /// Signed implicit function in object space at the world point (0 on the surface, negative inside the
    /// shape before `inverse`); for tests and diagnostics.
    double object_implicit(const Vec3& p_world) const;
    /// POV-Ray compat (IS_CHILD_OBJECT): shapes that report only their first crossing on their own (julia_fractal)
    /// report every crossing as CSG children and clipped objects.
    void keep_all_crossings() {
        std::visit([](auto& s) {
            if constexpr (requires { s.keep_all_crossings(); }) s.keep_all_crossings();
        }, m_shape);
    }
    /// The object's index in scene::Scene::objects and its object-to-world transform.
    std::uint32_t index() const { return m_index; }
    const Transform& transform() const;
    /// The shape in object space.
    const AnyShape& shape() const { return m_shape; }
    /// True when its inside and outside are swapped (`inverse`, or a subtracted child of a difference).
    bool inverse() const { return m_inverse; }
    /// True when the object is a mesh without clipping or bounds, which Embree can trace as native triangles.
    bool is_plain_mesh() const;

private:
    /// The ray in object space, or nothing where the instance's bounds (its box, its `bounded_by`) say it misses.
    std::optional<LocalRay> bounded_local_ray(const Vec3& origin, const Vec3& direction) const;
    /// object_crossings()'s crossings, in order, to `take` (returning true to stop): shapes that can find theirs
    /// one at a time stop finding them there.
    template <typename Take>
    void crossings_until(const Vec3& origin, const Vec3& direction, double t_min, double t_max, Take&& take) const;
    struct Parts;
    ShapeInstance(AnyShape shape, const scene::Object& object, std::uint32_t index);
    /// POV-Ray's Ray_In_Bound on the object-space ray: it meets every bound ahead or starts inside it.
    bool ray_in_bounds(const LocalRay& ray) const;

    AnyShape m_shape;
    /// The inverse of the object-to-parent transform (which is the scene object's, or a copy in m_parts), held
    /// here: every ray and inside test maps through it, and reaching it in the scene object cost 5-8 % of truchet's
    /// render.
    Transform::Matrix34 m_to_object{};
    Bounds m_world_bounds;   ///< when m_has_world_bounds
    Bounds m_region_bounds;  ///< when m_has_region_bounds
    /// What few instances have, shared by copies: clipping objects, `bounded_by` objects, the copy of the
    /// transform; nothing for most instances of a scene.
    std::shared_ptr<const Parts> m_parts;
    const scene::Object* m_object = nullptr;
    std::uint32_t m_index = 0;
    bool m_inverse = false;
    bool m_no_shadow = false;
    bool m_no_image = false;
    bool m_no_reflection = false;
    bool m_no_radiosity = false;
    bool m_cull_by_bounds = false;
    bool m_has_world_bounds = false;
    bool m_has_region_bounds = false;
};

/// ShapeInstance's rarer parts.
struct ShapeInstance::Parts {
    std::vector<ShapeInstance> clips;  ///< in object space; all must contain a point
    /// `bounded_by`, in object space: POV-Ray compat, the shape is hit only by rays that meet (or start in) all.
    std::vector<ShapeInstance> bounds;
    std::optional<Transform> transform;  ///< the copy of an instance made with ObjectLifetime::MayEnd
};

}  // namespace wardray::geometry
