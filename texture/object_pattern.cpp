// object: the inside test of the pattern's object, placed once per thread and object.
#include "texture/object_pattern.h"

#include <memory>
#include <optional>
#include <vector>

#include "geometry/instance.h"
#include "scene/object.h"

namespace wardray::texture {

namespace {

struct PlacedObject {
    std::weak_ptr<const scene::Object> object;
    std::optional<geometry::ShapeInstance> instance;
};

// The objects this thread has placed: a pattern's object is placed once, not at every point.
const std::optional<geometry::ShapeInstance>& placed(const std::shared_ptr<const scene::Object>& object) {
    thread_local std::vector<PlacedObject> cache;
    for (const PlacedObject& p : cache)
        if (!p.object.owner_before(object) && !object.owner_before(p.object) && !p.object.expired()) return p.instance;
    std::erase_if(cache, [](const PlacedObject& p) { return p.object.expired(); });
    cache.push_back({object, geometry::ShapeInstance::create(*object, 0)});
    return cache.back().instance;
}

}  // namespace

double object_pattern(const scene::Pattern& pat, const Vec3& p, int) {
    if (!pat.params->object) return 0.0;
    const std::optional<geometry::ShapeInstance>& instance = placed(pat.params->object);
    return instance && instance->inside(p) ? 1.0 : 0.0;
}

}  // namespace wardray::texture
