// Parser: the recursive-descent reader of POV-Ray SDL, the top of the reader layers, with the shape and
// pattern readers.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "parser/scene_reader.h"

namespace wardray::parser {

class TrueTypeFont;

/// Parses one scene; use once. Internal to parser/: other layers call parse_file / parse_string.
/// The layers, bottom up: SourceStream (files, diagnostics), TokenStream (directives run, macros, symbols),
/// Preprocessor (directives, deferred declarations), Evaluator (values), AppearanceReader, ObjectReader and
/// SceneReader (statements into a SceneBuilder); this class adds the shape reader (shapes.cpp) and the pattern
/// reader (patterns.cpp).
class Parser final : public SceneReader {
public:
    /// A parser reading with `options` (library paths, declares, image size, error limit).
    explicit Parser(const ParseOptions& options) : SceneReader(options) {}

    /// Parses `text` as the main scene file named `path`; never throws.
    ParseResult run(std::string text, const std::string& path);

private:
    /// run() on the thread it made.
    ParseResult run_here(std::string text, const std::string& path);
    // --- shapes (shapes.cpp) ---
    /// Reads a primitive's parameters after its '{' (the modifiers follow) with the keyword's reader.
    Shape parse_shape_parameters(const Token& kw) final;
    /// One reader per keyword of WARDRAY_SHAPES (scene/shapes.h): `Sphere read_sphere(const Token& kw)`, ...
#define WARDRAY_SHAPE_READER(keyword, Type) Type read_##keyword(const Token& kw);
    WARDRAY_SHAPES(WARDRAY_SHAPE_READER)
#undef WARDRAY_SHAPE_READER
    /// Reads one triangle (or smooth_triangle when `smooth`) of a mesh.
    void parse_triangle(Mesh& mesh, bool smooth);
    /// The order of `poly` and `polynomial` (2 to 35) and its comma; the coefficient vector of `cubic` and `poly`:
    /// as many floats as the order has monomials, in `< >`.
    void parse_poly_order(Poly& p);
    void parse_poly_coefficients(Poly& p);
    /// Reads `ttf "font" "string" thickness, offset` and lays the glyphs out (the font through the library path).
    Text parse_text_parameters(const Token& kw);
    /// Reads a lathe's spline type and points.
    Lathe parse_lathe_parameters(const Token& kw);
    /// Reads a surface of revolution's points.
    Sor parse_sor_parameters(const Token& kw);
    /// Reads `mesh { ... }` up to its modifiers.
    Mesh parse_mesh_body(const Token& kw);
    /// Reads `mesh2 { ... }` up to its modifiers.
    Mesh parse_mesh2_body(const Token& kw);
    /// Reads `{ count, item, item, ... }` calling `read_item` for each item.
    template <typename F>
    void parse_counted_list(const Token& kw, F read_item);
    std::optional<Object> as_single_object(ObjectValue& ov) final;
    void make_union_node(ObjectValue& ov) final;
    std::vector<Object> parse_object_list(const Token& kw, const std::vector<Object>* bounded_by) final;

    // --- patterns (patterns.cpp) ---
    bool starts_value(const Token& t) final;
    void skip_to_close(const Token& kw, const char* close, std::size_t depth) final;
    int parse_pattern_keyword(const Token& t, Pattern& pat) final;
    bool parse_pattern_modifier(const Token& t, Pattern& pat) final;
    bool take_pattern_list_open() final;
    /// Reads the object of an `object { ... }` pattern after its '{'.
    Object parse_pattern_object(const Token& kw);
    // --- pattern parameters and warps (pattern_params.cpp) ---
    int parse_pattern_parameters(const Token& t, Pattern& pat);
    bool parse_pattern_extra(const Token& t, Pattern& pat);
    // --- the pavement pattern (pattern_pavement.cpp) ---
    /// Reads a pavement modifier of `pat` (number_of_sides, number_of_tiles, pattern, exterior, interior, form).
    bool parse_pavement_modifier(const Token& t, Pattern& pat);
    /// POV-Ray's checks of a pavement pattern once its block is read (kw: the block's keyword).
    void check_pavement(const Token& kw, Pattern& pat);
    // --- the slope pattern (pattern_slope.cpp) ---
    /// Reads what follows `slope` into `pat.slope`.
    void parse_slope_parameters(const Token& kw, Pattern& pat);
    /// Reads `[, lo, hi]` after a slope or altitude vector: the range's start and width (0 for none).
    void parse_slope_range(double& lo, double& range, const char* what);
    void parse_warp(const Token& kw, Pattern& pat);
    void check_black_hole(const Token& at, Warp& w);
    std::vector<SlopeMapEntry> parse_slope_map();
    std::vector<ColorMapEntry> parse_color_map(const Token& kw) final;
    /// Reads a pigment map after its keyword.
    std::vector<PigmentMapEntry> parse_pigment_map(const Token& kw, bool optional_values = false);
    /// Takes a leading pigment identifier or array element, when one comes next.
    bool parse_pigment_start(Pigment& p);
    /// Reads the list of `count` colours or pigments after a list pattern (checker, brick, hexagon).
    void parse_pigment_list(Pigment& p, int count);
    /// Reads pigment items up to `close` ('}' of a pigment block or ']' of a pigment_map entry).
    void parse_pigment_items(Pigment& p, const Token& kw, const char* close);
    Pigment parse_pigment_body(const Token& kw, const Pigment* base = nullptr) final;
    Pigment parse_function_pigment(const Token& kw) final { return parse_pigment_body(kw); }
    Normal parse_normal_body(const Token& kw, const Normal* base = nullptr) final;
    Pigment parse_density_body(const Token& kw) final;
    /// With an array element next: whether the array holds colours (its first assigned element is a number).
    bool is_colour_array_next();
    /// Reads `image_map { ... }` after its keyword into `p` (parser/image_map.cpp).
    void parse_image_map(const Token& kw, Pigment& p);
    /// Reads `image_pattern { ... }` after its keyword into `pat` (an image read like a bump map's).
    void parse_image_pattern(const Token& kw, Pattern& pat);
    /// Reads `bump_map { ... }` after its keyword into `n`.
    void parse_bump_map(const Token& kw, Normal& n);
    /// Reads `material_map { ... }` after its keyword: `tx` becomes the material map.
    void parse_material_map(const Token& kw, Texture& tx) final;
    /// The blocks that read an image: their items differ a little.
    enum class ImageBlock { ImageMap, BumpMap, MaterialMap };
    /// Reads an image block's file and items after its '{' up to its '}'; `item` takes the block's own items
    /// (true when it read one).
    ImageMap parse_image_block(const Token& kw, ImageBlock block, const std::function<bool(const Token&)>& item);
    /// An image file found like an include file (a name without extension also with those of its `type`, e.g.
    /// "png"), its texels in the working gamma (`colour`, image_map) or as stored (bump_map, material_map); read
    /// once per gamma.
    std::shared_ptr<const ImageData> read_image_file(const Token& at, const std::string& name,
                                                     const std::optional<GammaCurve>& file_gamma, bool colour,
                                                     std::string_view type = {});
    /// A df3 file found like an include file (density_file), read once.
    std::shared_ptr<const DensityFile> read_density_file(const Token& at, const std::string& name);
    /// Takes a leading normal identifier or array element, when one comes next.
    void parse_normal_start(Normal& n);
    /// Reads normal items up to `close`.
    void parse_normal_items(Normal& n, const Token& kw, const char* close);

    /// Fonts read so far, by resolved path; POV-Ray keeps each font's glyph cache for the whole scene.
    std::map<std::string, std::shared_ptr<TrueTypeFont>> m_fonts;
    /// Images read so far, by resolved path and gamma.
    std::map<std::string, std::shared_ptr<const ImageData>> m_images;
    /// Density files read so far, by resolved path.
    std::map<std::string, std::shared_ptr<const DensityFile>> m_density_files;
    /// An object pattern's list is being read: its '}' follows the list.
    bool m_pattern_list_open = false;
    /// Height field images read so far, by file (height_field.cpp).
    std::map<std::string, std::shared_ptr<const HeightGrid>> m_height_grids;
};

}  // namespace wardray::parser
