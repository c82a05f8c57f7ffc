// Scene description, textures: patterns, pigments, normals, finishes and textures with their maps.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "core/color.h"
#include "core/diagnostics.h"
#include "core/transform.h"
#include "core/vec3.h"
#include "scene/image_map.h"
#include "function/function_vm.h"
#include "scene/cow.h"
#include "scene/kind_list.h"

namespace wardray::scene {

/// POV-Ray's wave types: how a pattern's value is shaped before the map lookup.
enum class WaveType { Ramp, Triangle, Sine, Scallop, Cubic, Poly };

/// POV-Ray's classic `turbulence` (a displacement by vector fBm) with its octaves, omega and lambda.
struct Turbulence {
    Vec3 amount;
    int octaves = 6;
    double omega = 0.5;
    double lambda = 2.0;
    bool operator==(const Turbulence&) const = default;
};

/// One `warp { ... }` of a pattern, or a transform given after one (POV-Ray's WARP list entries).
struct Warp {
    enum class Type { Transform, Turbulence, Repeat, BlackHole, Cylindrical, Spherical, Toroidal, Planar, Cubic };
    Type type = Type::Transform;
    Transform transform;    ///< Transform: pattern space to the enclosing space
    Turbulence turbulence;  ///< Turbulence
    int axis = 0;           ///< repeat: the axis (0, 1, 2) and the block width along it
    double width = 0.0;
    Vec3 offset;            ///< repeat: offset per block
    Vec3 flip{1.0, 1.0, 1.0};  ///< repeat: -1 on the flipped axes
    Vec3 center;            ///< black_hole
    double radius = 1.0;
    double strength = 1.0;
    double falloff = 2.0;
    bool inverse = false;
    int hole_type = 0;
    bool repeat = false;    ///< black_hole repeat: the repeat vector and its turbulence (uncertainty)
    Vec3 repeat_vector;
    bool uncertain = false;
    Vec3 uncertainty;
    Vec3 orientation{0.0, 0.0, 1.0};  ///< cylindrical, spherical, toroidal, planar
    double dist_exp = 0.0;
    double major_radius = 1.0;  ///< toroidal
    double plane_offset = 0.0;  ///< planar
    bool operator==(const Warp&) const = default;
};

/// The patterns the renderer evaluates, listed once: X(keyword, Enumerator). Pattern::Type, the parser's pattern
/// keywords and reserved words, and texture/'s evaluation table (one `<keyword>_pattern` function each, so a
/// missing one fails to compile) all come from this list.
#define WARDRAY_PATTERNS(X)       \
    X(checker, Checker)           \
    X(gradient, Gradient)         \
    X(hexagon, Hexagon)           \
    X(brick, Brick)               \
    X(bozo, Bozo)                 \
    X(spotted, Spotted)           \
    X(granite, Granite)           \
    X(marble, Marble)             \
    X(wood, Wood)                 \
    X(agate, Agate)               \
    X(radial, Radial)             \
    X(onion, Onion)               \
    X(leopard, Leopard)           \
    X(ripples, Ripples)           \
    X(waves, Waves)               \
    X(wrinkles, Wrinkles)         \
    X(bumps, Bumps)               \
    X(dents, Dents)               \
    X(crackle, Crackle)           \
    X(cells, Cells)               \
    X(boxed, Boxed)               \
    X(spherical, Spherical)       \
    X(planar, Planar)             \
    X(cylindrical, Cylindrical)   \
    X(average, Average)           \
    X(mandel, Mandel)             \
    X(julia, Julia)               \
    X(magnet, Magnet)             \
    X(quilted, Quilted)           \
    X(spiral1, Spiral1)           \
    X(spiral2, Spiral2)           \
    X(square, Square)             \
    X(triangular, Triangular)     \
    X(cubic, Cubic)               \
    X(pavement, Pavement)         \
    X(pigment_pattern, PigmentPattern) \
    X(function, Function)         \
    X(density_file, DensityFile)  \
    X(object, Object)             \
    X(slope, Slope)               \
    X(aoi, Aoi)                   \
    X(facets, Facets)             \
    X(tiling, Tiling)             \
    X(image_pattern, ImagePattern)

struct Pigment;
struct Object;

/// `slope { [point_at] <slope>, lo, hi altitude <altitude>, lo, hi }` as POV-Ray 3.7 keeps it (Vals.Slope): unit
/// vectors, each part's weight (slope_len + altitude_len = 1) and each range's start and width (0: no range).
struct SlopeParams {
    Vec3 slope_vector;     ///< unit; with point_at, the point the slope is measured towards
    Vec3 altitude_vector;  ///< unit, or zero without altitude
    double slope_len = 1.0;
    double altitude_len = 0.0;
    double slope_lo = 0.0;
    double slope_range = 0.0;
    double altitude_lo = 0.0;
    double altitude_range = 0.0;
    bool point_at = false;
    bool operator==(const SlopeParams&) const = default;
};

/// `pavement`'s parameters as POV-Ray 3.7 keeps them (Vals.Pavement): the cell shape, the tiles a paver covers,
/// which of POV-Ray's pavings of that many tiles, and how its corners are drawn.
struct PavementParams {
    int sides = 3;   ///< number_of_sides: 3 (triangles), 4 (squares) or 6 (hexagons)
    int tiles = 1;   ///< number_of_tiles: 1 to 6 (1 to 5 for hexagons)
    int number = 1;  ///< pattern: 1 to the number of pavings with that many tiles
    int exterior = 0;
    int interior = 0;
    int form = 0;
    bool operator==(const PavementParams&) const = default;
};

/// A density_file's voxels as POV-Ray's df3 stores them (x fastest, then y, then z), each value raw / max.
struct DensityFile {
    int nx = 0, ny = 0, nz = 0;
    std::vector<std::uint32_t> raw;
    double max = 255.0;  ///< 255, 65535 or 4294967295 for 8-, 16- and 32-bit files
    double at(std::size_t x, std::size_t y, std::size_t z) const {
        return static_cast<double>(raw[(z * static_cast<std::size_t>(ny) + y) * static_cast<std::size_t>(nx) + x]) / max;
    }
};

/// A pigment held by a pattern (pigment_pattern), shared between copies and compared by value.
struct PigmentRef {
    std::shared_ptr<const Pigment> pigment;
    bool operator==(const PigmentRef& other) const;
};

/// A pattern's parameters other than its placement: the wave, turbulence and each pattern type's own values. Patterns
/// share them (copy on write) as textures are copied and moved, since only the transform differs between copies.
struct PatternParams {
    WaveType wave = WaveType::Ramp;
    double exponent = 1.0;  ///< poly_wave
    double frequency = 1.0;
    double phase = 0.0;
    int noise_generator = 0;  ///< 0: the scene's global setting
    Vec3 gradient{1.0, 0.0, 0.0};
    Vec3 brick_size{8.0, 3.0, 4.5};
    double mortar = 0.5;
    double agate_turb = 1.0;
    Vec3 crackle_form{-1.0, 1.0, 0.0};
    double crackle_metric = 2.0;
    double crackle_offset = 0.0;
    bool crackle_solid = false;
    int fractal_iterations = 0;  ///< mandel, julia, magnet
    int fractal_exponent = 2;    ///< mandel and julia: 2 to 33
    double julia_re = 0.0;       ///< julia and magnet julia: the complex parameter
    double julia_im = 0.0;
    int magnet_type = 1;         ///< magnet 1 or 2
    bool magnet_julia = false;   ///< magnet N julia (true) or magnet N mandel
    int exterior_type = 1;
    double exterior_factor = 1.0;
    int interior_type = 0;
    double interior_factor = 1.0;
    double control0 = 1.0;  ///< quilted
    double control1 = 1.0;
    int arms = 0;           ///< spiral1, spiral2
    int tiling_type = 1;    ///< `tiling N`: POV-Ray's tiling 1..27
    SlopeParams slope;      ///< slope
    double facets_size = 0.1;    ///< facets `size` (its `metric` is crackle_metric)
    double facets_coords = 0.0;  ///< facets `coords`: 0 picks by the normal, else by the point, tilting by this
    PavementParams pavement;     ///< pavement
    PigmentRef pigment;     ///< pigment_pattern: the pigment whose grey level is the value
    std::optional<Turbulence> turbulence;
    function::SharedFunction function;  ///< the `function { ... }` pattern's function
    std::shared_ptr<const DensityFile> density_file;  ///< density_file df3 "file"
    std::shared_ptr<const Object> object;             ///< object { OBJECT a, b }: the object (compared by identity)
    std::shared_ptr<const ImageMap> image;            ///< image_pattern { png "file" ... } (compared by identity)
    int density_interpolation = 0;                    ///< density_file: 0 none, 1 trilinear, 2 tricubic
    bool operator==(const PatternParams&) const = default;
};

/// A pattern: a value at each point of pattern space, with POV-Ray's modifiers (shared by pigment, normal and
/// texture maps).
struct Pattern {
#define WARDRAY_PATTERN_ENUMERATOR(keyword, Enumerator) Enumerator,
    /// None (a plain colour, no pattern), then the patterns of WARDRAY_PATTERNS in its order.
    enum class Type { None, WARDRAY_PATTERNS(WARDRAY_PATTERN_ENUMERATOR) };
#undef WARDRAY_PATTERN_ENUMERATOR
    Type type = Type::None;
    /// Everything but the type and the placement, shared between copies until one changes it: read through a
    /// const Pattern (or params.get()), since a non-const `params->` gives this copy a value of its own.
    Cow<PatternParams> params;
    Transform transform;  ///< pattern space to the enclosing space (world for a pigment on an object)
    /// Warps applied after `transform` (world to pattern space, in this order), before the classic turbulence.
    std::vector<Warp> warps;
    /// `no_bump_scale` (POV-Ray's DONT_SCALE_BUMPS_FLAG), on a normal's pattern or a texture's map pattern: the
    /// normal goes into and out of this pattern's space unnormalized, so a scaled pattern's bumps keep their depth
    /// relative to the scale (a normal_map's entries inherit it).
    bool no_bump_scale = false;
    bool operator==(const Pattern&) const = default;
};

#define WARDRAY_PATTERN_KEYWORD(keyword, Enumerator) {#keyword, Pattern::Type::Enumerator},
/// The keyword of each pattern of WARDRAY_PATTERNS, in its order.
inline constexpr KindKeyword<Pattern::Type> k_pattern_keywords[] = {WARDRAY_PATTERNS(WARDRAY_PATTERN_KEYWORD)};
#undef WARDRAY_PATTERN_KEYWORD

/// One `[value colour]` entry of a colour map (values stored as POV-Ray's single-precision floats).
struct ColorMapEntry {
    double value = 0.0;
    Color color;
    bool operator==(const ColorMapEntry&) const = default;
};

struct PigmentMapEntry;

/// A pigment: a solid colour, or a pattern looked up in a colour map or a pigment map.
struct Pigment {
    Color color;  // POV-Ray compat: the default pigment is black.
    Pattern pattern;
    std::vector<ColorMapEntry> color_map;
    SharedVector<PigmentMapEntry> pigment_map;  ///< shared between copies of the pigment until one changes it
    std::optional<ImageMap> image_map;  ///< an image_map pigment (its transform and warps in `pattern`)
    /// `uv_mapping`: evaluated at the surface's (u, v, 0) instead of the point, and not moved by the object.
    bool uv_mapping = false;
    /// `quick_color`: what the pigment shows instead at +Q0 to +Q5 (POV-Ray's Quick_Colour).
    std::optional<Color> quick_color;
    SourceLoc loc;

    /// True for a plain colour: no pattern or image to evaluate.
    bool is_solid() const { return pattern.type == Pattern::Type::None && !image_map; }
    bool operator==(const Pigment&) const = default;
};

/// One `[value pigment]` entry of a pigment map.
struct PigmentMapEntry {
    double value = 0.0;
    Pigment pigment;
    bool operator==(const PigmentMapEntry&) const = default;
};

// Defined once PigmentMapEntry is complete: comparing pigments compares their pigment maps (clang needs it).
inline bool PigmentRef::operator==(const PigmentRef& other) const {
    return pigment == other.pigment || (pigment && other.pigment && *pigment == *other.pigment);
}

struct NormalMapEntry;

/// One `[value <height, slope>]` entry of a normal's slope_map.
struct SlopeMapEntry {
    double value = 0.0;
    double height = 0.0;
    double slope = 0.0;
    bool operator==(const SlopeMapEntry&) const = default;
};

/// A normal perturbation: a pattern whose slope tilts the shading normal, scaled by `bump_size`.
struct Normal {
    Pattern pattern;        ///< None: the normal is not perturbed
    double amount = 0.5;    ///< bump_size, or the float after the pattern name
    double delta = 0.02;    ///< POV-Ray's sampling distance for the slope (accuracy)
    SharedVector<NormalMapEntry> normal_map;  ///< shared between copies until one changes it
    std::vector<SlopeMapEntry> slope_map;  ///< reshapes the pattern's value before its slope is taken
    /// `bump_map { png "file" bump_size B use_index ... }`: the normal from an image (its transform and warps
    /// in `pattern`, whose type is then None).
    std::optional<ImageMap> bump_map;
    bool uv_mapping = false;  ///< `uv_mapping`: the pattern is evaluated at the surface's (u, v, 0)
    SourceLoc loc;
    /// True when the normal perturbs anything: a pattern or a bump map.
    bool perturbs() const { return pattern.type != Pattern::Type::None || bump_map.has_value(); }
    bool operator==(const Normal&) const = default;
};

/// One `[value normal]` entry of a normal map.
struct NormalMapEntry {
    double value = 0.0;
    Normal normal;
    bool operator==(const NormalMapEntry&) const = default;
};

/// Surface finish with POV-Ray 3.7's defaults.
struct Finish {
    Color ambient{0.1, 0.1, 0.1};
    Color emission{0.0, 0.0, 0.0};
    double diffuse = 0.6;
    double brilliance = 1.0;
    double phong = 0.0;
    double phong_size = 40.0;
    double specular = 0.0;
    double roughness = 0.05;
    double metallic = 0.0;  ///< highlight tinted by the pigment
    Color reflection_min;   ///< reflection at normal incidence (or everywhere without `reflection { a, b }`)
    Color reflection_max;
    bool reflection_fresnel = false;
    double reflection_falloff = 1.0;
    double reflection_exponent = 1.0;
    double reflection_metallic = 0.0;
    bool conserve_energy = false;
    double irid = 0.0;  ///< thin-film interference amount (`irid { amount thickness turbulence }`)
    double irid_thickness = 0.0;
    double irid_turbulence = 0.0;
    double crand = 0.0;  ///< graininess: a random part of each light's diffuse intensity taken off
    /// POV-Ray 3.1's `finish { ior }`, negative when not given: the object's interior takes it when the object is
    /// placed (POV-Ray's Post_Process), if the object's texture is a plain one.
    double legacy_ior = -1.0;
    /// POV-Ray 3.1's `finish { caustics }`, negative when not given: promoted to the interior as `legacy_ior` is
    /// (unscaled, as POV-Ray's Post_Process copies it).
    double legacy_caustics = -1.0;
    /// POV-Ray 3.1's `finish { refraction R }` (POV-Ray's Temp_Refract, 1 when not given): the object's interior
    /// takes it when the object is placed with a plain texture, overriding an interior's own `refraction`.
    double legacy_refraction = 1.0;
    SourceLoc loc;
    bool operator==(const Finish&) const = default;
};

struct TextureMapEntry;

/// A texture: pigment, normal and finish, or a pattern choosing between textures (texture_map); further
/// `texture` statements on the same object are layers painted over it.
struct Texture {
    Pigment pigment;
    Finish finish;
    Normal normal;
    Pattern map_pattern;  ///< texture_map's pattern (None: a plain texture)
    SharedVector<TextureMapEntry> texture_map;  ///< shared between copies until one changes it
    /// `material_map { png "file" texture { } ... }`: the image picks one of texture_map's entries by index
    /// (entry values 0, 1, ...); its transform and warps are map_pattern's.
    std::optional<ImageMap> material_map;
    std::vector<Texture> layers;  ///< layers on top of this one, lowest first
    bool uv_mapping = false;  ///< `uv_mapping`: the whole texture is evaluated at the surface's (u, v, 0)
    bool operator==(const Texture&) const = default;
};

/// One `[value texture]` entry of a texture map.
struct TextureMapEntry {
    double value = 0.0;
    Texture texture;
    bool operator==(const TextureMapEntry&) const = default;
};

/// The layer that pigment, normal and finish statements after a texture identifier modify: POV-Ray keeps layers
/// as a list headed by the last one listed, the top, and modifies the head (Parse_Texture, Parse_Object_Mods).
inline Texture& top_layer(Texture& t) { return t.layers.empty() ? t : t.layers.back(); }

/// POV-Ray's Link_Textures: `over` and the layers it holds (a layered texture identifier) painted over `base`'s
/// layers, in their order; the list stays flat, as the renderer reads it.
inline void add_layers(Texture& base, Texture over) {
    std::vector<Texture> above = std::move(over.layers);
    over.layers.clear();
    base.layers.push_back(std::move(over));
    for (Texture& layer : above) base.layers.push_back(std::move(layer));
}

/// Moves a texture with the object it is on (POV-Ray's Transform_Textures): every pattern's transform is followed
/// by `tr`. Map entries are evaluated in their parent's pattern space and are left alone.
/// POV-Ray compat: a uv-mapped texture, pigment or normal lives in uv space and stays where it is.
inline void transform_texture(Texture& t, const Transform& tr) {
    if (t.uv_mapping) return;
    if (!t.pigment.uv_mapping) t.pigment.pattern.transform = t.pigment.pattern.transform.then(tr);
    if (!t.normal.uv_mapping) t.normal.pattern.transform = t.normal.pattern.transform.then(tr);
    t.map_pattern.transform = t.map_pattern.transform.then(tr);
    for (Texture& layer : t.layers) transform_texture(layer, tr);
}

/// True when the pigment or one of its pigment_map entries is uv-mapped; `nested` is set for an entry's.
inline bool pigment_uses_uv(const Pigment& p, bool& nested, bool in_map = false) {
    bool uses = p.uv_mapping;
    if (uses && in_map) nested = true;
    for (const PigmentMapEntry& e : p.pigment_map) uses = pigment_uses_uv(e.pigment, nested, true) || uses;
    return uses;
}

/// True when the normal or one of its normal_map entries is uv-mapped; `nested` is set for an entry's.
inline bool normal_uses_uv(const Normal& n, bool& nested, bool in_map = false) {
    bool uses = n.uv_mapping;
    if (uses && in_map) nested = true;
    for (const NormalMapEntry& e : n.normal_map) uses = normal_uses_uv(e.normal, nested, true) || uses;
    return uses;
}

/// True when the texture, at any depth, asks for uv coordinates; `nested` is set when a uv-mapped pigment or
/// normal sits inside a pigment_map or normal_map entry.
inline bool texture_uses_uv(const Texture& t, bool& nested) {
    bool uses = t.uv_mapping;
    uses = pigment_uses_uv(t.pigment, nested) || uses;
    uses = normal_uses_uv(t.normal, nested) || uses;
    for (const TextureMapEntry& e : t.texture_map) uses = texture_uses_uv(e.texture, nested) || uses;
    for (const Texture& l : t.layers) uses = texture_uses_uv(l, nested) || uses;
    return uses;
}

}  // namespace wardray::scene
