// SceneBuilder: what the statement readers write into; it holds the scene until the parse hands it over.
#pragma once

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "parser/namespaces.h"

namespace wardray::parser {

/// The target of the statement readers, in the spirit of pbrt-v4's ParserTarget: one call per entity the
/// scene file places, and the finished scene at the end.
class SceneBuilder {
public:
    /// Places an object at the top level of the scene.
    void add_object(Object object) { m_scene.objects.push_back(std::move(object)); }
    /// Makes room for `count` more objects: exactly, when one statement brings more than doubling would (a
    /// union of 20,000 parts would otherwise leave the list up to twice too large while its parts are still held),
    /// else by doubling.
    void reserve_objects(std::size_t count) {
        std::vector<Object>& objects = m_scene.objects;
        const std::size_t needed = objects.size() + count;
        if (needed > objects.capacity()) objects.reserve(std::max(needed, 2 * objects.capacity()));
    }
    /// Adds a light source.
    void add_light(Light light) { m_scene.lights.push_back(std::move(light)); }
    /// Sets the camera; a later camera statement replaces it.
    void set_camera(const Camera& camera) { m_scene.camera = camera; }
    /// Sets the background colour.
    void set_background(const Color& color, bool legacy = false) {
        m_scene.background = color;
        m_scene.background_given = true;
        m_scene.background_legacy = legacy;
    }
    /// Sets the sky sphere; a later one replaces it.
    void set_sky_sphere(SkySphere sky) { m_scene.sky_sphere = std::move(sky); }
    /// True once a sky_sphere statement was read.
    bool has_sky_sphere() const { return m_scene.sky_sphere.has_value(); }
    /// Adds a fog layer.
    void add_fog(Fog fog) { m_scene.fogs.push_back(std::move(fog)); }
    /// Adds a rainbow.
    void add_rainbow(Rainbow rainbow) { m_scene.rainbows.push_back(std::move(rainbow)); }
    /// POV-Ray compat: an effective #version below 3.7 (none given counts as 3.62) layers sky pigments the 3.6 way.
    void set_legacy_sky(bool legacy) {
        m_scene.legacy_version = legacy;
        if (m_scene.sky_sphere) m_scene.sky_sphere->legacy_layering = legacy;
    }
    /// A scene-level media block: part of the atmosphere.
    void add_media(Media media) { m_scene.media.push_back(std::move(media)); }
    /// The global settings, which global_settings blocks change item by item.
    GlobalSettings& global() { return m_scene.global; }

    /// The scene built, for the main file `path`, with the language version at its end and its warnings.
    Scene finish(std::string path, double version, std::vector<Diagnostic> warnings) {
        m_scene.path = std::move(path);
        m_scene.version = version;
        m_scene.warnings = std::move(warnings);
        return std::move(m_scene);
    }

private:
    Scene m_scene;
};

}  // namespace wardray::parser
