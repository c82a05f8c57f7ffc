// Opacity: whether a pigment, texture or object can let light through (filter or transmit), as shadow rays ask.
#pragma once

#include <algorithm>
#include <variant>

#include "scene/object.h"
#include "scene/texture.h"

namespace wardray::scene {

/// Whether a pigment never lets light through (no filter or transmit anywhere in it).
inline bool pigment_opaque(const Pigment& p) {
    if (p.is_solid()) return p.color.filter == 0.0 && p.color.transmit == 0.0;
    // An image map lets light through with filter or transmit all, an alpha channel, and where `once` leaves no
    // image.
    if (p.image_map) {
        if (p.image_map->image && !p.image_map->image->alpha.empty()) return false;
        for (const PaletteFT& ft : p.image_map->palette_ft)
            if (ft.filter != 0.0f || ft.transmit != 0.0f) return false;
        return !p.image_map->once && p.image_map->filter_all == 0.0 && p.image_map->transmit_all == 0.0;
    }
    for (const auto& e : p.color_map)
        if (e.color.filter != 0.0 || e.color.transmit != 0.0) return false;
    for (const auto& e : p.pigment_map)
        if (!pigment_opaque(e.pigment)) return false;
    return true;
}

/// Whether a texture never lets light through.
inline bool texture_opaque(const Texture& t) {
    if (!t.texture_map.empty()) {
        for (const auto& e : t.texture_map)
            if (!texture_opaque(e.texture)) return false;
        return true;
    }
    // POV-Ray compat: only the layers' pigments decide whether light passes.
    if (!pigment_opaque(t.pigment)) return false;
    for (const auto& layer : t.layers)
        if (!texture_opaque(layer)) return false;
    return true;
}

/// Whether an object (its textures, inside and out, and every CSG part) never lets light through.
inline bool object_opaque(const Object& o) {
    if (!texture_opaque(o.texture)) return false;
    for (const Texture& inside : o.interior_texture)
        if (!texture_opaque(inside)) return false;
    if (const auto* csg = std::get_if<Csg>(&o.shape))
        for (const Object& child : csg->children)
            if (!object_opaque(child)) return false;
    return true;
}

/// Whether anything behind or inside a surface of this texture may show through it: every layer lets some light
/// through (an opaque layer hides those below it and the object's inside), or some entry of its texture_map does.
inline bool texture_may_show_through(const Texture& t) {
    if (!t.texture_map.empty())
        return std::any_of(t.texture_map.begin(), t.texture_map.end(),
                           [](const auto& e) { return texture_may_show_through(e.texture); });
    if (pigment_opaque(t.pigment)) return false;
    return std::all_of(t.layers.begin(), t.layers.end(),
                       [](const Texture& layer) { return texture_may_show_through(layer); });
}

}  // namespace wardray::scene
