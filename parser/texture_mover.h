// Textures that objects share: TextureMover moves textures by one transform, keeping shared ones shared, and
// interchangeable() says when an equal texture may stand in for another.
#pragma once

#include <unordered_map>

#include "core/transform.h"
#include "scene/cow.h"
#include "scene/texture.h"

namespace wardray::parser {

/// True when `b` may stand in for `a`: equal, and without a `function` pattern anywhere (a function compares its
/// calls of declared pigment and pattern functions by count only, so two equal-looking ones may differ).
bool interchangeable(const scene::Texture& a, const scene::Texture& b);

/// Moves textures by one transform so that objects that shared a texture before it share one after it (the parts
/// of a textured union, copies of one declared object): a shared texture is moved and copied once, not per object.
class TextureMover {
public:
    explicit TextureMover(const Transform& tr) : m_tr(tr) {}

    /// Moves an object's texture: in place when no other object shares it, else a copy shared by every object
    /// that shared it.
    void move(scene::Cow<scene::Texture>& t);
    /// Moves a mesh's texture list, likewise.
    void move(scene::SharedVector<scene::Texture>& textures);
    /// Moves a texture of the object's own.
    void move(scene::Texture& t) { scene::transform_texture(t, m_tr); }

private:
    // The value before the move is kept alive, so no other texture can later take its address and be mistaken
    // for it.
    struct Moved {
        scene::Cow<scene::Texture> before, after;
    };
    struct MovedList {
        scene::SharedVector<scene::Texture> before, after;
    };
    const Transform& m_tr;
    std::unordered_map<const void*, Moved> m_moved;
    std::unordered_map<const void*, MovedList> m_moved_lists;
};

}  // namespace wardray::parser
