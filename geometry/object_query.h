// ObjectQuery: the geometry layer's answers to the parser's trace(), inside(), min_extent() and max_extent().
#pragma once

#include "scene/scene_query.h"

namespace wardray::geometry {

/// Answers parse-time questions about one object at a time, in double precision, without building an
/// acceleration structure (each call places the object and tests it directly).
class ObjectQuery final : public scene::SceneQuery {
public:
    std::optional<scene::QueryHit> trace(const scene::Object& object, const Vec3& origin,
                                          const Vec3& direction) const override;
    bool inside(const scene::Object& object, const Vec3& point) const override;
    std::optional<std::pair<Vec3, Vec3>> extent(const scene::Object& object) const override;
};

}  // namespace wardray::geometry
