// The geometry questions the parser asks at parse time (trace, inside, extents), answered by the geometry layer.
#pragma once

#include <optional>
#include <utility>

#include "scene/scene.h"

namespace wardray::scene {

/// Where a ray met an object, in world space.
struct QueryHit {
    Vec3 point;
    Vec3 normal;  ///< unit surface normal at `point`, as POV-Ray's trace() reports it (facing the ray's origin side
                  ///< is not guaranteed; POV-Ray returns the geometric normal)
};

/// Answers trace(), inside(), min_extent() and max_extent() for one object (its transform included).
/// Implemented by geometry/ and handed to the parser through ParseOptions::query; the parser combines the
/// parts of a union itself. Implementations must not throw.
class SceneQuery {
public:
    virtual ~SceneQuery() = default;
    /// The nearest intersection of the ray `origin + t * direction`, t > 0, with `object`; none when it misses.
    /// `direction` need not be normalised.
    virtual std::optional<QueryHit> trace(const Object& object, const Vec3& origin, const Vec3& direction) const = 0;
    /// Whether `point` lies inside `object` (POV-Ray's inside(): false for objects without an inside).
    virtual bool inside(const Object& object, const Vec3& point) const = 0;
    /// The world-space bounding box as (min, max), or none when the object is unbounded.
    virtual std::optional<std::pair<Vec3, Vec3>> extent(const Object& object) const = 0;
};

}  // namespace wardray::scene
