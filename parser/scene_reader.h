// SceneReader: the top-level statements of a scene file (objects, lights, camera, global settings, ...).
#pragma once

#include <array>
#include <cstddef>
#include <optional>

#include "parser/object_reader.h"
#include "parser/scene_builder.h"

namespace wardray::parser {

/// Reads one statement at a time through a keyword table and writes what it places into the SceneBuilder.
class SceneReader : public ObjectReader {
protected:
    using ObjectReader::ObjectReader;

    /// Reads one top-level statement.
    void parse_statement();
    int scene_noise_generator() final { return m_builder.global().noise_generator; }
    /// Places an object statement's parts and lights in the scene, with the default texture where none is given.
    void place_object(ObjectValue ov);
    /// Gives `o` (when `own_texture`: its texture was given on it) and its CSG children with textures of their own
    /// a recently placed texture of equal value in place of their own copy.
    void share_equal_textures(Object& o, bool own_texture);
    void warn_uv_unsupported(const Object& o, bool in_csg);
    /// Reads `camera { ... }` after its keyword.
    CameraSpec parse_camera_body(const Token& kw);
    /// The `mesh_camera { ... }` block after its keyword (parser/mesh_camera.cpp).
    void parse_mesh_camera(CameraSpec& spec, const Token& kw);
    /// A focal blur item: aperture, blur_samples, confidence, variance or focal_point.
    static bool focal_blur(SceneReader& r, CameraSpec& spec, const Token& item, const Token& kw);
    /// `assumed_gamma G | srgb`: the working gamma; POV-Ray compat: the first one stays in force.
    static void read_assumed_gamma(SceneReader& r, GlobalSettings& g, const Token& item);
    /// radiosity save_file / load_file (not supported): warns and reads the file name.
    static void radiosity_file(SceneReader& r, RadiositySettings& rad, const Token& item);
    /// Reads `global_settings { ... }` after its keyword.
    void parse_global_settings(const Token& kw);
    /// Reads `radiosity { ... }` of the global settings into `rad`.
    void parse_radiosity(const Token& kw, RadiositySettings& rad);
    /// global_settings' `photons { }` block (parser/photons.cpp).
    void parse_photons(const Token& kw, PhotonSettings& ph);
    std::optional<Value> parse_item_value(const Token& t) final;
    /// A declared colour map, kept as a pigment holding only that map.
    Pigment color_map_value(const Token& kw);

    SceneBuilder m_builder;
    bool m_charset_utf8 = false;  ///< global_settings { charset utf8 }: text strings are decoded as UTF-8
    /// The last few distinct textures placed, which equal textures of the next objects share.
    std::array<scene::Cow<Texture>, 4> m_recent_textures;
    std::size_t m_recent_next = 0;
};

}  // namespace wardray::parser
