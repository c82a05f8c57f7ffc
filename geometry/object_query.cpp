// ObjectQuery: parse-time geometry queries answered with ShapeInstance, the same code that renders.
#include "geometry/object_query.h"

#include <limits>

#include "geometry/instance.h"

namespace wardray::geometry {

struct ObjectQuery::Placed {
    scene::Object object;
    std::optional<ShapeInstance> instance;
};

std::optional<scene::QueryHit> ObjectQuery::trace(const scene::Object& object, const Vec3& origin,
                                                   const Vec3& direction) const {
    if (!m_traced || !(m_traced->object == object)) {
        auto placed = std::make_shared<Placed>();
        placed->object = object;
        placed->instance = ShapeInstance::create(placed->object, 0);  // built from the copy it points at
        // POV-Ray's trace() goes through Find_Intersection, which tests the object's bounding box first.
        if (placed->instance) placed->instance->cull_by_bounds();
        m_traced = std::move(placed);
    }
    const std::optional<ShapeInstance>& instance = m_traced->instance;
    if (!instance || !is_finite(origin) || !is_finite(direction) || direction == Vec3{}) return std::nullopt;
    const auto hit = instance->nearest(origin, direction, 0.0, std::numeric_limits<double>::infinity());
    if (!hit) return std::nullopt;
    return scene::QueryHit{hit->position, hit->normal};
}

bool ObjectQuery::inside(const scene::Object& object, const Vec3& point) const {
    const auto instance = ShapeInstance::create(object, 0);
    return instance && is_finite(point) && instance->inside(point);
}

std::optional<std::pair<Vec3, Vec3>> ObjectQuery::extent(const scene::Object& object) const {
    const auto instance = ShapeInstance::create(object, 0);
    if (!instance || !instance->world_bounds()) return std::nullopt;
    return std::pair{instance->world_bounds()->lower, instance->world_bounds()->upper};
}

}  // namespace wardray::geometry
