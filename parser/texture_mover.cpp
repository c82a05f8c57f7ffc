// TextureMover: moves textures by one transform, keeping textures that objects shared shared.
#include "parser/texture_mover.h"

#include <utility>

namespace wardray::parser {

void TextureMover::move(scene::Cow<scene::Texture>& t) {
    if (t.unique()) {
        scene::transform_texture(*t, m_tr);
        return;
    }
    const void* before = &t.get();
    if (const auto it = m_moved.find(before); it != m_moved.end()) {
        t = it->second.after;
        return;
    }
    Moved moved{t, {}};
    scene::transform_texture(*t, m_tr);
    moved.after = t;
    m_moved.emplace(before, std::move(moved));
}

void TextureMover::move(scene::SharedVector<scene::Texture>& textures) {
    if (textures.unique()) {
        for (scene::Texture& t : textures) scene::transform_texture(t, m_tr);
        return;
    }
    const void* before = &textures.get();
    if (const auto it = m_moved_lists.find(before); it != m_moved_lists.end()) {
        textures = it->second.after;
        return;
    }
    MovedList moved{textures, {}};
    for (scene::Texture& t : textures) scene::transform_texture(t, m_tr);
    moved.after = textures;
    m_moved_lists.emplace(before, std::move(moved));
}

}  // namespace wardray::parser
