// Textures that objects share: TextureMover moves textures by one transform, keeping shared ones shared, and
// interchangeable() says when an equal texture may stand in for another.
#include "parser/texture_mover.h"

#include <utility>

namespace wardray::parser {

namespace {

bool has_function(const scene::Pigment& p);

bool has_function(const scene::Pattern& p) {
    return static_cast<bool>(p.params->function) || (p.params->pigment.pigment && has_function(*p.params->pigment.pigment));
}

bool has_function(const scene::Pigment& p) {
    if (has_function(p.pattern)) return true;
    for (const scene::PigmentMapEntry& e : p.pigment_map)
        if (has_function(e.pigment)) return true;
    return false;
}

bool has_function(const scene::Normal& n) {
    if (has_function(n.pattern)) return true;
    for (const scene::NormalMapEntry& e : n.normal_map)
        if (has_function(e.normal)) return true;
    return false;
}

bool has_function(const scene::Texture& t) {
    if (has_function(t.pigment) || has_function(t.normal) || has_function(t.map_pattern)) return true;
    for (const scene::TextureMapEntry& e : t.texture_map)
        if (has_function(e.texture)) return true;
    for (const scene::Texture& layer : t.layers)
        if (has_function(layer)) return true;
    return false;
}

}  // namespace

bool interchangeable(const scene::Texture& a, const scene::Texture& b) {
    return a == b && !has_function(a);
}

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
