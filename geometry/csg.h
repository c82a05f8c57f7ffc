// CsgShape: POV-Ray's union, intersection, difference and merge over child objects, as interval operations.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "geometry/shape.h"
#include "scene/scene.h"

namespace wardray::geometry {

class ShapeInstance;

/// Whether the scene objects an instance is made from outlive it (SceneGeometry's scene does): it then points at
/// their transforms rather than holding a copy (200 bytes each, a third of an instance).
enum class ObjectLifetime : unsigned char { MayEnd, Outlives };

/// A CSG node in its own object space; children are ShapeInstances placed relative to it.
/// POV-Ray's rules: a union keeps every child surface; an intersection keeps a child's crossing where the point
/// is inside all other children; a difference is the intersection of the first child with the others inverted;
/// a merge keeps a child's crossing where the point is inside no other child.
class CsgShape {
public:
    /// Returns nothing when a child cannot be built (the whole node is then skipped and reported).
    static std::optional<CsgShape> create(const scene::Csg& csg) { return create(csg, false); }
    /// The CSG with `inverse` applied as POV-Ray applies it: every child inverted and the operation turned into
    /// its dual (a union or merge becomes an intersection, an intersection or difference a merge), so an inverted
    /// union keeps no surface that lies inside another of its children.
    static std::optional<CsgShape> create(const scene::Csg& csg, bool inverted,
                                          ObjectLifetime lifetime = ObjectLifetime::MayEnd);

    /// Crossings with t in (t_min, t_max), sorted, each naming the leaf primitive hit.
    SurfaceHits intersect_all(const LocalRay& ray, double t_min, double t_max) const;
    /// Bounds of the kept surfaces, or nothing when unbounded.
    std::optional<Bounds> bounds() const { return m_bounds; }
    /// Bounds of the inside region, or nothing when unbounded.
    std::optional<Bounds> region_bounds() const { return m_region; }
    /// POV-Ray's inside test of the combination.
    bool inside(const Vec3& p) const;
    /// Smallest distance-like value of the children at the point (zero on some child's surface).
    double implicit(const Vec3& p) const;

private:
    enum class Rule { All, Inside, Outside };  // which crossings survive: all, inside others, outside others

    CsgShape() = default;
    /// POV-Ray's rule for a crossing of `child` at p; `rejecter` is the child that rejected the previous crossing
    /// (the scan starts there; updated), or any value past the last child.
    bool keeps(std::size_t child, const Vec3& p, std::size_t& rejecter) const;

    Rule m_rule = Rule::All;
    bool m_inside_all = false;  ///< inside needs all children (intersection, difference) or any (union, merge)
    std::shared_ptr<const std::vector<ShapeInstance>> m_children;
    std::optional<Bounds> m_bounds;
    std::optional<Bounds> m_region;
};

}  // namespace wardray::geometry
