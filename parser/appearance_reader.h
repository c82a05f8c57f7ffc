// AppearanceReader: colours, finishes, textures, interiors, the sky sphere, fog and rainbow, and #default.
#pragma once

#include <optional>
#include <vector>

#include "core/gamma.h"
#include "parser/evaluator.h"

namespace wardray::parser {

/// Reads the blocks that say how a surface looks. Pigments, normals and their patterns and maps are read by
/// the pattern reader (patterns.cpp), which this layer reaches through the hooks below.
class AppearanceReader : public Evaluator {
protected:
    using Evaluator::Evaluator;

    Color parse_color() final;
    /// Reads the items that may follow a colour expression (`filter .5`, `red 1`, ...) into `c`.
    Color parse_color_modifiers(Color c);
    /// Reads `finish { ... }` after its keyword. POV-Ray modifies the finish in place: the items change `base`
    /// (the finish of the texture being modified) when given, else the default finish.
    Finish parse_finish_body(const Token& kw, const Finish* base = nullptr);
    /// Reads one finish item `item` (already consumed) into `f`.
    void parse_finish_item(Finish& f, const Token& item);
    /// Reads `reflection { ... }` into the finish.
    void parse_reflection_block(Finish& f);
    /// Reads `texture { ... }` after its keyword.
    Texture parse_texture_body(const Token& kw);
    /// Reads texture items up to `close` ('}' of a texture block or ']' of a texture_map entry).
    void parse_texture_items(Texture& tx, const Token& kw, const char* close);
    /// Reads `texture { } texture { } ...`: the first texture with the others as layers over it.
    Texture parse_texture_list(const Token& kw);
    /// Reads `tiles { texture { } tile2 texture { } }` after its keyword (a checker of two textures).
    Texture parse_tiles(const Token& kw);
    /// Reads the pigment, normal and finish identifiers that may open a plain texture's items.
    void parse_texture_part_identifiers(Texture& tx);
    /// Reads `interior { ... }` after its keyword. Its items change `base` (POV-Ray's Parse_Interior changes the
    /// object's interior in place), unless it opens with a declared interior, which replaces it.
    Interior parse_interior_body(const Token& kw, const Interior& base = {});
    /// Reads `media { ... }` after its keyword (media.cpp).
    Media parse_media_body(const Token& kw);
    /// Reads `scattering { type, colour ... }` into the media.
    void parse_media_scattering(Media& m, const Token& kw);
    /// Reads `sky_sphere { ... }` after its keyword.
    SkySphere parse_sky_sphere(const Token& kw);
    /// Reads `fog { ... }` after its keyword.
    Fog parse_fog(const Token& kw);
    /// Reads `rainbow { ... }` after its keyword.
    Rainbow parse_rainbow(const Token& kw);
    /// Reads the declared `T` that may open a sky_sphere, fog or rainbow block into `item`; false when none does.
    template <typename T>
    bool read_declared(T& item, const char* kind);
    void directive_default(const Token& tok) final;

    /// Reads `pigment { ... }` after its keyword (the pattern reader's).
    virtual Pigment parse_pigment_body(const Token& kw, const Pigment* base = nullptr) = 0;
    /// Reads `density { ... }` after its keyword, a pigment that scales a media (the pattern reader's, media.cpp).
    virtual Pigment parse_density_body(const Token& kw) = 0;
    /// Reads `normal { ... }` after its keyword (the pattern reader's).
    virtual Normal parse_normal_body(const Token& kw, const Normal* base = nullptr) = 0;
    /// Reads `material_map { ... }` after its keyword: `tx` becomes the material map (the image reader's).
    virtual void parse_material_map(const Token& kw, Texture& tx) = 0;
    /// Reads a colour map after its keyword (the pattern reader's).
    virtual std::vector<ColorMapEntry> parse_color_map(const Token& kw) = 0;
    /// True when `t` can start a float, vector or colour expression (the pattern reader's).
    virtual bool starts_value(const Token& t) = 0;
    /// Consumes tokens up to and including `close` at brace depth `depth` (the pattern reader's).
    virtual void skip_to_close(const Token& kw, const char* close, std::size_t depth) = 0;
    /// Reads a pattern keyword and its own parameters into `pat`: -1 when `t` is not one, else the length of the
    /// list of colours/pigments/textures that may follow it (the pattern reader's).
    virtual int parse_pattern_keyword(const Token& t, Pattern& pat) = 0;
    /// Reads one pattern modifier; false when `t` is none (the pattern reader's).
    virtual bool parse_pattern_modifier(const Token& t, Pattern& pat) = 0;
    /// True (once) when the pattern just read takes its list inside its braces (object): the caller reads the '}'
    /// after the list.
    virtual bool take_pattern_list_open() = 0;

    /// Reads a colour's keywords and components into `c`; `any` when a colour was already read.
    Color read_color(Color c, bool any);

    /// A texture made of the current #default pigment, normal and finish.
    Texture default_texture() const {
        Texture t;
        t.pigment = m_default_pigment;
        t.finish = m_default_finish;
        t.normal = default_normal();
        return t;
    }
    /// default_texture() as one shared value, made again only when a #default has changed it since.
    scene::Cow<Texture> shared_default_texture() const {
        Texture t = default_texture();
        if (!(m_default_shared.get() == t)) m_default_shared = std::move(t);
        return m_default_shared;
    }
    /// The normal a `normal { }` block starts from where there is none to modify: the #default normal, if any
    /// (POV-Ray's Parse_Tnormal copies Default_Texture's), else no perturbation.
    Normal default_normal() const { return m_default_normal.value_or(Normal{}); }
    Pigment m_default_pigment;
    Finish m_default_finish;
    std::optional<Normal> m_default_normal;
    mutable scene::Cow<Texture> m_default_shared;
    /// Finish items given with `albedo` in the block being read (bits: diffuse, phong, specular).
    unsigned m_finish_albedo = 0;
    /// The working gamma, once global_settings' assumed_gamma is read: sRGB colours are re-encoded into it.
    std::optional<GammaCurve> m_working_gamma;
};

}  // namespace wardray::parser
