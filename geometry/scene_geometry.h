// SceneGeometry: the scene's shapes as one Embree scene, answering "what does this ray hit" and "is it blocked".
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "geometry/shape.h"
#include "scene/scene.h"
#include "core/vec3.h"

namespace wardray::geometry {

/// What a ray is for, which decides the objects it sees (`no_image`, `no_reflection`, `no_shadow`).
enum class RayKind : std::uint8_t { Camera, Reflection, Shadow, Gather };

/// A ray in world space; `direction` need not be unit length, t is measured in units of it.
struct Ray {
    Vec3 origin;
    Vec3 direction;
    double t_min = 0.0;
    double t_max = 1e30;
    RayKind kind = RayKind::Camera;
};

/// The nearest intersection along a ray, computed in double precision.
struct Hit {
    double t = 0.0;
    Vec3 position;        ///< world space
    Vec3 normal;          ///< unit geometric normal in world space, pointing out of the shape (inverse flips it)
    std::uint32_t object = 0;  ///< index into scene::Scene::objects (the top-level object)
    /// The primitive whose surface was hit (a CSG leaf, or the object itself): its texture applies.
    const scene::Object* leaf = nullptr;
    /// A top-level mesh's face (its index in scene::Mesh::faces, -1 otherwise) and the barycentric weights of
    /// its second and third corners at the hit, for uv coordinates and per-corner textures.
    std::int32_t face = -1;
    double bary_u = 0.0;
    double bary_v = 0.0;
    /// The surface's own parameters at the hit where a top-level shape has them (a bicubic patch's (u, v, 0)).
    bool has_params = false;
    Vec3 params;
};

/// Why ShapeInstance::create returned nothing, for the warning that names the object.
struct SkipReason {
    /// A CSG node lay more than max_csg_depth() levels below the object (else the object or a part is degenerate).
    bool too_deep = false;
    /// Where the part that was refused is written: the first node past the depth limit, or the degenerate part.
    SourceLoc where;
};

/// How deep CSG nodes may nest below a top-level object (1,000; less in sanitizer builds, whose frames are larger).
int max_csg_depth();

/// Builds and owns the Embree device and scene. Thread-safe for concurrent queries after construction.
class SceneGeometry {
public:
    /// Builds the acceleration structure for every object of `scene` (the scene must outlive this object).
    explicit SceneGeometry(const scene::Scene& scene);
    ~SceneGeometry();
    SceneGeometry(const SceneGeometry&) = delete;
    SceneGeometry& operator=(const SceneGeometry&) = delete;

    /// The nearest hit with t in (t_min, t_max) among the objects this kind of ray sees, or nothing.
    std::optional<Hit> intersect(const Ray& ray) const;
    /// True when some object that casts shadows (not `no_shadow`) blocks the ray in (t_min, t_max).
    bool occluded(const Ray& ray) const;

    /// World bounds of all bounded surfaces (planes excluded), or nothing when there are none.
    std::optional<Bounds> bounds() const;
    /// Indices of the objects left out because they cannot be intersected without NaN (singular transform,
    /// zero radius, zero plane normal, non-finite numbers) or hold CSG nested too deep; the app reports them.
    const std::vector<std::uint32_t>& skipped_objects() const;
    /// Why each of skipped_objects() was left out, in its order.
    const std::vector<SkipReason>& skip_reasons() const;
    /// Warnings the shapes have after rendering (an isosurface's max_gradient set too low or too high).
    std::vector<Diagnostic> shape_warnings() const;
    /// Like the free self_intersection_offset(), with a floor of 1e-6 of the scene's magnitude so that points
    /// at or near the origin still get an offset that matches the size of the objects around them.
    double self_intersection_offset(const Vec3& p) const;
    /// POV-Ray's MIN_ISECT_DEPTH as a ray parameter along `direction`: intersect() and occluded() see no crossing
    /// nearer than this to the ray's origin (1e-4, or 1e-4 of the scene's magnitude below one unit). A walk that
    /// goes on past a crossing along the same ray skips this much after it, as POV-Ray's new ray from there would.
    double min_isect_parameter(const Vec3& direction) const;

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

/// The distance to move a ray's origin off a surface at `p` so that it does not hit that surface again;
/// it scales with the magnitude of the coordinates, never one fixed epsilon: 1e-9 * max_abs_component(p)
/// (about 4.5e6 double ulps of the coordinates, room for the rounding of transforms and root refinement).
/// Offset along the normal, or use it as t_min for a unit direction.
double self_intersection_offset(const Vec3& p);

}  // namespace wardray::geometry
