// ConeShape: POV-Ray's `cone` and `cylinder` (a cone with equal radii), capped or `open`, in object space.
#pragma once

#include <array>
#include <memory>
#include <optional>

#include "core/transform.h"
#include "geometry/shape.h"
#include "scene/scene.h"

namespace wardray::geometry {

/// A truncated cone between two points, radius varying linearly along the axis; a cylinder when both are equal.
class ConeShape {
public:
    /// Returns nothing for coincident end points or non-finite numbers.
    static std::optional<ConeShape> create(const scene::Cone& cone);
    /// The cylinder as a cone with equal radii.
    static std::optional<ConeShape> create(const scene::Cylinder& cylinder);

    /// Surface crossings (side and caps) with t in (t_min, t_max), sorted.
    SurfaceHits intersect_all(const LocalRay& ray, double t_min, double t_max) const;
    /// Object-space bounding box.
    std::optional<Bounds> bounds() const;
    /// True for points strictly inside the solid (also for `open` ones, as POV-Ray's CSG treats them).
    bool inside(const Vec3& p) const;
    /// Zero on the surface, negative inside.
    double implicit(const Vec3& p) const;

    /// POV-Ray compat (Cone::Normal): a cylinder's side normal at object-space point `p`, as POV-Ray computes it
    /// through its unit-cylinder transform (whose rounding leaves parts of order 1e-17 across the axis); NaN for a
    /// cone whose radii differ.
    Vec3 cylinder_normal(const Vec3& p) const;

    /// POV-Ray compat (Cone::Intersect, Cone::Inside): a cylinder under `object_to_parent` (its object's transform)
    /// also keeps POV-Ray's single matrix from the parent's space to the unit cylinder, the object's transform
    /// composed onto the unit cylinder's, so that its crossings and inside tests in the parent's space are computed
    /// as POV-Ray computes them: a ray grazing a cylinder (qtvrpanorama.pov's camera rays along the plane that the
    /// gazebo's bores touch) then hits or misses as in POV-Ray. Cones are left as they are.
    void place(const Transform& object_to_parent);
    /// True for a cylinder placed by place().
    bool placed() const { return m_matrices && m_matrices->is_placed; }
    /// A placed cylinder's crossings with a ray in the parent's space (t the same parameter), object-space normals.
    SurfaceHits intersect_parent(const Vec3& origin, const Vec3& direction, double t_min, double t_max) const;
    /// A placed cylinder's inside test at a point in the parent's space (POV-Ray's EPSILON margins).
    bool inside_parent(const Vec3& p) const;

private:
    ConeShape(const Vec3& base, const Vec3& cap, double r0, double r1, bool open);
    /// The object-space normal of the unit cylinder's normal (x, y, z) (MTransNormal through the unit transform).
    Vec3 object_normal(double x, double y, double z) const;

    Vec3 m_base;
    Vec3 m_axis;  ///< unit, from base to cap
    double m_height = 0.0;
    double m_r0 = 0.0;
    double m_r1 = 0.0;
    double m_slope = 0.0;  ///< (r1 - r0) / height
    bool m_open = false;
    /// POV-Ray's row-vector matrices without their constant last column (0, 0, 0, 1): four rows of three.
    using Rows = std::array<std::array<double, 3>, 4>;
    struct CylinderMatrices {
        Rows unit_inverse;  ///< the inverse of POV-Ray's transform of the unit cylinder
        Rows placed;        ///< for a placed cylinder: POV-Ray's inverse from the parent's space to the unit cylinder
        bool is_placed = false;
    };
    /// For a cylinder, one allocation shared by the shape's copies (every shape alternative stays small, and a scene
    /// of 84,000 cylinders pays one block each).
    std::shared_ptr<const CylinderMatrices> m_matrices;
};

}  // namespace wardray::geometry
