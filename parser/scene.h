// Scene description: the renderer-independent plain data the parser produces, with a source location on each entity.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "parser/diagnostics.h"
#include "parser/transform.h"
#include "parser/vec3.h"

namespace wardray::parser {

/// POV-Ray's five-component colour: linear RGB plus filter and transmit.
struct Color {
    double r = 0.0;
    double g = 0.0;
    double b = 0.0;
    double filter = 0.0;
    double transmit = 0.0;

    Vec3 rgb() const { return {r, g, b}; }
    bool operator==(const Color&) const = default;
};

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

/// A pattern: a value at each point of pattern space, with POV-Ray's modifiers (shared by pigment, normal and
/// texture maps).
struct Pattern {
    enum class Type {
        None, Checker, Gradient, Hexagon, Brick, Bozo, Spotted, Granite, Marble, Wood, Agate, Radial, Onion,
        Leopard, Ripples, Waves, Wrinkles, Bumps, Dents, Crackle, Cells, Boxed, Spherical, Planar, Cylindrical
    };
    Type type = Type::None;
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
    std::optional<Turbulence> turbulence;
    Transform transform;  ///< pattern space to the enclosing space (world for a pigment on an object)
    bool operator==(const Pattern&) const = default;
};

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
    std::vector<PigmentMapEntry> pigment_map;
    SourceLoc loc;

    /// True for a plain colour: no pattern to evaluate.
    bool is_solid() const { return pattern.type == Pattern::Type::None; }
    bool operator==(const Pigment&) const = default;
};

/// One `[value pigment]` entry of a pigment map.
struct PigmentMapEntry {
    double value = 0.0;
    Pigment pigment;
    bool operator==(const PigmentMapEntry&) const = default;
};

struct NormalMapEntry;

/// A normal perturbation: a pattern whose slope tilts the shading normal, scaled by `bump_size`.
struct Normal {
    Pattern pattern;        ///< None: the normal is not perturbed
    double amount = 0.5;    ///< bump_size, or the float after the pattern name
    double delta = 0.02;    ///< POV-Ray's sampling distance for the slope (accuracy)
    std::vector<NormalMapEntry> normal_map;
    SourceLoc loc;
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
    SourceLoc loc;
    bool operator==(const Finish&) const = default;
};

/// The inside of an object: index of refraction and POV-Ray's fade of light passing through.
struct Interior {
    double ior = 1.0;
    double fade_distance = 0.0;
    double fade_power = 0.0;
    Color fade_color;
    bool operator==(const Interior&) const = default;
};

struct TextureMapEntry;

/// A texture: pigment, normal and finish, or a pattern choosing between textures (texture_map); further
/// `texture` statements on the same object are layers painted over it.
struct Texture {
    Pigment pigment;
    Finish finish;
    Normal normal;
    Pattern map_pattern;  ///< texture_map's pattern (None: a plain texture)
    std::vector<TextureMapEntry> texture_map;
    std::vector<Texture> layers;  ///< layers on top of this one, lowest first
    bool operator==(const Texture&) const = default;
};

/// One `[value texture]` entry of a texture map.
struct TextureMapEntry {
    double value = 0.0;
    Texture texture;
    bool operator==(const TextureMapEntry&) const = default;
};

/// Moves a texture with the object it is on (POV-Ray's Transform_Textures): every pattern's transform is followed
/// by `tr`. Map entries are evaluated in their parent's pattern space and are left alone.
inline void transform_texture(Texture& t, const Transform& tr) {
    t.pigment.pattern.transform = t.pigment.pattern.transform.then(tr);
    t.normal.pattern.transform = t.normal.pattern.transform.then(tr);
    t.map_pattern.transform = t.map_pattern.transform.then(tr);
    for (Texture& layer : t.layers) transform_texture(layer, tr);
}

struct Sphere {
    Vec3 center;
    double radius = 1.0;
    bool operator==(const Sphere&) const = default;
};

struct Box {
    Vec3 corner1;
    Vec3 corner2;
    bool operator==(const Box&) const = default;
};

/// POV-Ray's `plane { normal, distance }`: the surface {p : dot(n̂, p) = distance} with n̂ the unit normal;
/// the inside is where dot(n̂, p) < distance. The parser stores the normal as written.
struct Plane {
    Vec3 normal{0.0, 1.0, 0.0};
    double distance = 0.0;
    bool operator==(const Plane&) const = default;
};

/// POV-Ray's `cylinder { base, cap, radius [open] }`.
struct Cylinder {
    Vec3 base;
    Vec3 cap{0.0, 1.0, 0.0};
    double radius = 1.0;
    bool open = false;  ///< no end caps
    bool operator==(const Cylinder&) const = default;
};

/// POV-Ray's `cone { base, base_radius, cap, cap_radius [open] }`.
struct Cone {
    Vec3 base;
    double base_radius = 1.0;
    Vec3 cap{0.0, 1.0, 0.0};
    double cap_radius = 0.0;
    bool open = false;
    bool operator==(const Cone&) const = default;
};

/// POV-Ray's `disc { center, normal, radius [, hole_radius] }`.
struct Disc {
    Vec3 center;
    Vec3 normal{0.0, 1.0, 0.0};
    double radius = 1.0;
    double hole_radius = 0.0;
    bool operator==(const Disc&) const = default;
};

/// POV-Ray's `torus { major, minor }` around the y axis at the origin.
struct Torus {
    double major = 1.0;
    double minor = 0.25;
    bool operator==(const Torus&) const = default;
};

/// Triangles: `triangle`, `smooth_triangle`, `mesh` and `mesh2` all become one list of faces.
struct Mesh {
    enum class Kind { Triangle, SmoothTriangle, Mesh, Mesh2 };
    /// One face: three vertex indices and, for smooth faces, three normal indices (-1 when flat).
    struct Face {
        std::array<int, 3> v{};
        std::array<int, 3> n{-1, -1, -1};
        bool operator==(const Face&) const = default;
    };
    Kind kind = Kind::Mesh;
    std::vector<Vec3> vertices;
    std::vector<Vec3> normals;
    std::vector<Face> faces;
    Vec3 inside_vector;  ///< zero when not given: the mesh has no inside
    bool operator==(const Mesh&) const = default;
};

/// POV-Ray's `polygon { n, points }`: closed sub-polygons (each repeats its first point); later ones cut holes.
struct Polygon {
    std::vector<Vec3> points;
    bool operator==(const Polygon&) const = default;
};

/// POV-Ray's `quadric { <A,B,C>, <D,E,F>, <G,H,I>, J }`:
/// A x² + B y² + C z² + D xy + E xz + F yz + G x + H y + I z + J = 0, inside where negative.
struct Quadric {
    Vec3 squares;
    Vec3 mixed;
    Vec3 linear;
    double constant = 0.0;
    bool operator==(const Quadric&) const = default;
};

/// POV-Ray's `superellipsoid { <e, n> }`: (|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n) = 1.
struct Superellipsoid {
    double e = 1.0;
    double n = 1.0;
    bool operator==(const Superellipsoid&) const = default;
};

/// POV-Ray's `quartic { <a0, ..., a34> }`: the sum of a_i times the monomials x^i y^j z^k (i + j + k <= 4) in
/// POV-Ray's order (x⁴, x³y, x³z, x³, x²y², ..., z, 1: descending powers of x, then y, then z); inside where negative.
struct Quartic {
    std::array<double, 35> coefficients{};
    bool operator==(const Quartic&) const = default;
};

/// POV-Ray's `prism { [spline type] [linear_sweep | conic_sweep] height1, height2, n, <u, v>... [open] }`: the 2-D
/// outline (sub-polygons close when their first curve point repeats; even-odd rule) in the x-z plane (u -> x,
/// v -> z), swept along y; conic_sweep scales the outline by y (apex at the origin). The spline types are those of
/// `lathe` (quadratic and cubic sub-polygons have a control point before their first and after their last point).
struct Prism {
    enum class Spline { Linear, Quadratic, Cubic, Bezier };
    Spline spline = Spline::Linear;
    bool conic = false;
    double height1 = 0.0;
    double height2 = 1.0;
    std::vector<Vec3> points;  ///< (u, v, 0)
    bool open = false;
    bool operator==(const Prism&) const = default;
};

/// POV-Ray's `lathe { [linear_spline | quadratic_spline | cubic_spline | bezier_spline] n, <r, y>... }`: the
/// profile curve (r: distance from the axis, y: height) turned about the y axis.
struct Lathe {
    enum class Spline { Linear, Quadratic, Cubic, Bezier };
    Spline spline = Spline::Linear;
    std::vector<Vec3> points;  ///< (r, y, 0)
    bool operator==(const Lathe&) const = default;
};

/// POV-Ray's `sor { n, <r, y>... [open] }`: a surface of revolution whose squared radius is a cubic in y on each
/// interval between consecutive points (the first and the last point only set the end slopes); closed by discs at
/// its lowest and highest point unless open.
struct Sor {
    std::vector<Vec3> points;  ///< (r, y, 0)
    bool open = false;
    bool operator==(const Sor&) const = default;
};

/// One glyph of a `text` object: the TrueType outline in em units (closed contours of quadratic B-spline points,
/// each on or off the curve, in the font's order), placed at `offset` in the text's object space.
struct TextGlyph {
    struct Point {
        double x = 0.0;
        double y = 0.0;
        bool on_curve = true;
        bool operator==(const Point&) const = default;
    };
    std::vector<std::vector<Point>> contours;
    Vec3 offset;
    bool operator==(const TextGlyph&) const = default;
};

/// POV-Ray's `text { ttf "font.ttf" "string" thickness, offset }`: the glyphs laid out by the parser as POV-Ray
/// does (advance, kerning, offset), each extruded from z = 0 to z = thickness; the union of the glyphs.
struct Text {
    std::vector<TextGlyph> glyphs;
    double thickness = 1.0;
    bool operator==(const Text&) const = default;
};

struct Object;

/// Constructive solid geometry over child objects (each with its own transform relative to this node).
struct Csg {
    enum class Op { Union, Intersection, Difference, Merge };
    Op op = Op::Union;
    std::vector<Object> children;
    bool operator==(const Csg&) const = default;
};

/// The shapes the renderer draws.
using Shape = std::variant<Sphere, Box, Plane, Cylinder, Cone, Disc, Torus, Mesh, Polygon, Quadric, Superellipsoid,
                           Quartic, Prism, Lathe, Sor, Text, Csg>;

/// One object of the scene: a shape, its placement, its appearance and its flags.
struct Object {
    Shape shape;
    Transform transform;  ///< object space to world space, in the order the keywords appeared
    Texture texture;
    Interior interior;
    bool inverse = false;
    bool no_shadow = false;
    bool no_image = false;
    bool no_reflection = false;
    bool no_radiosity = false;
    bool has_texture = false;  ///< the statement gave its own texture (else it takes its CSG parent's)
    std::vector<Object> clipped_by;  ///< clipping objects, placed relative to this object's transform
    SourceLoc loc;
    bool operator==(const Object&) const = default;
};

/// The camera, resolved by the parser to POV-Ray's final vectors (after look_at, angle, sky and transforms).
struct Camera {
    enum class Type { Perspective, Orthographic };
    Type type = Type::Perspective;
    Vec3 location{0.0, 0.0, 0.0};
    Vec3 direction{0.0, 0.0, 1.0};  ///< from location to the centre of the image plane
    Vec3 right{1.33, 0.0, 0.0};     ///< full width of the image plane
    Vec3 up{0.0, 1.0, 0.0};         ///< full height of the image plane
    SourceLoc loc;
    bool operator==(const Camera&) const = default;
};

struct Light {
    enum class Type { Point, Spot, Parallel, Cylinder };
    Type type = Type::Point;
    Vec3 position;
    Color color{1.0, 1.0, 1.0};
    double fade_distance = 0.0;  ///< 0: no fading
    double fade_power = 0.0;
    bool shadowless = false;
    // Spotlight and cylinder parameters (degrees), POV-Ray's defaults.
    Vec3 point_at{0.0, 0.0, 1.0};
    double radius = 30.0;
    double falloff = 45.0;
    double tightness = 0.0;
    // `area_light axis1, axis2, size1, size2` with its options, POV-Ray's defaults.
    bool area = false;
    Vec3 area_axis1;
    Vec3 area_axis2;
    int area_size1 = 1;
    int area_size2 = 1;
    int adaptive = 100;  ///< POV-Ray's default: subdivide to the full grid
    bool jitter = false;
    bool circular = false;
    bool orient = false;
    SourceLoc loc;
    bool operator==(const Light&) const = default;
};

/// The `radiosity { ... }` block of global_settings with POV-Ray 3.7's defaults.
struct RadiositySettings {
    int count = 35;
    int count_directions = 1600;
    double error_bound = 1.8;
    double low_error_factor = 0.5;
    double minimum_reuse = 0.015;
    double maximum_reuse = 0.2;
    int nearest_count = 5;
    int nearest_count_pretrace = 0;  ///< 0: not given
    int recursion_limit = 2;
    double pretrace_start = 0.08;
    double pretrace_end = 0.04;
    double brightness = 1.0;
    double gray_threshold = 0.0;
    double adc_bailout = 0.01;
    bool always_sample = false;
    double max_sample = -1.0;  ///< brightest a gather sample may be (its largest channel); ≤ 0: no limit
    bool normal = false;
    bool media = false;
    SourceLoc loc;
    bool operator==(const RadiositySettings&) const = default;
};

struct GlobalSettings {
    double assumed_gamma = 1.0;
    bool assumed_gamma_given = false;
    Color ambient_light{1.0, 1.0, 1.0};
    int max_trace_level = 5;
    double adc_bailout = 1.0 / 255.0;
    int noise_generator = 2;  ///< POV-Ray 3.7's default: range-corrected noise
    std::optional<RadiositySettings> radiosity;
    bool operator==(const GlobalSettings&) const = default;
};

/// `sky_sphere { pigment {...} ... }`: pigments looked up by ray direction, each later one layered over the
/// earlier ones through its filter and transmit.
struct SkySphere {
    std::vector<Pigment> pigments;
    Transform transform;  ///< sky space to world (rotates the directions)
    Color emission{1.0, 1.0, 1.0};
    bool operator==(const SkySphere&) const = default;
};

/// `fog { distance D color C }`: POV-Ray's constant fog (fog_type 1), exp(−depth/D) of the scene left.
struct Fog {
    double distance = 0.0;
    Color color;
    SourceLoc loc;
    bool operator==(const Fog&) const = default;
};

/// Everything the renderer needs from a scene file.
struct Scene {
    std::string path;  ///< the main scene file
    double version = 3.7;  ///< the language version in force at the end of the file
    Camera camera;
    std::vector<Light> lights;
    std::vector<Object> objects;
    GlobalSettings global;
    Color background{0.0, 0.0, 0.0};
    std::optional<SkySphere> sky_sphere;
    std::vector<Fog> fogs;
    /// Features parsed but not rendered yet, and other warnings found while parsing.
    std::vector<Diagnostic> warnings;
};

}  // namespace wardray::parser
