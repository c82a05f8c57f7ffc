// ObjectQuery: the geometry layer's answers to the parser's trace(), inside(), min_extent() and max_extent().
#pragma once

#include "parser/scene_query.h"

namespace wardray::geometry {

/// Answers parse-time questions about one object at a time, in double precision, without building an
/// acceleration structure (each call places the object and tests it directly).
class ObjectQuery final : public parser::SceneQuery {
public:
    std::optional<parser::QueryHit> trace(const parser::Object& object, const Vec3& origin,
                                          const Vec3& direction) const override;
    bool inside(const parser::Object& object, const Vec3& point) const override;
    std::optional<std::pair<Vec3, Vec3>> extent(const parser::Object& object) const override;
};

}  // namespace wardray::geometry
