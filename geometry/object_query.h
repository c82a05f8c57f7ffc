// ObjectQuery: the geometry layer's answers to the parser's trace(), inside(), min_extent() and max_extent().
#pragma once

#include <memory>

#include "scene/scene_query.h"

namespace wardray::geometry {

/// Answers parse-time questions about one object at a time, in double precision, without building an
/// acceleration structure (each call places the object and tests it directly; trace() keeps the last one).
class ObjectQuery final : public scene::SceneQuery {
public:
    std::optional<scene::QueryHit> trace(const scene::Object& object, const Vec3& origin,
                                          const Vec3& direction) const override;
    bool inside(const scene::Object& object, const Vec3& point) const override;
    std::optional<std::pair<Vec3, Vec3>> extent(const scene::Object& object) const override;

private:
    /// The object trace() placed last, kept with its own copy of the object: a #while loop that traces one
    /// object hundreds of times (landscape.pov's trees on a 500x500 height field) places it once, not per call.
    struct Placed;
    mutable std::shared_ptr<Placed> m_traced;
};

}  // namespace wardray::geometry
