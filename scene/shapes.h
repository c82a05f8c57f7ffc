// Scene description, shapes: the plain data of each primitive the renderer draws, and their one list.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "core/transform.h"
#include "core/diagnostics.h"
#include "core/vec3.h"
#include "function/function_vm.h"
#include "scene/cow.h"
#include "scene/texture.h"

namespace wardray::scene {

/// POV-Ray's `sphere { center, radius }`.
struct Sphere {
    Vec3 center;
    double radius = 1.0;
    bool operator==(const Sphere&) const = default;
};

/// POV-Ray's `box { corner1, corner2 }`.
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

/// POV-Ray 3.7's `ovus { bottom_radius, top_radius }`: a sphere of the bottom radius at the origin and one of the
/// top radius centred at <0, bottom_radius, 0>, joined by a spindle-torus band whose radius is twice the larger
/// one; with top_radius >= 2 bottom_radius just the top sphere (POV-Ray substitutes it with a warning).
struct Ovus {
    double bottom_radius = 1.0;
    double top_radius = 0.5;
    bool operator==(const Ovus&) const = default;
};

/// POV-Ray's `blob { [threshold T] component s, r, <c> | sphere { <c>, r, [strength] s [transforms] } |
/// cylinder { <a>, <b>, r, [strength] s [transforms] } ... [sturm] [hierarchy] }`: the surface where the summed
/// densities s (1 - d²/r²)² (d: distance to the centre, or to the segment a-b) equal T; inside where above it.
struct Blob {
    struct Component {
        bool cylinder = false;
        Vec3 a;  ///< the centre, or the cylinder's first end
        Vec3 b;  ///< the cylinder's second end
        double radius = 1.0;
        double strength = 1.0;
        Transform transform;  ///< the component's own transforms, in the blob's space
        int texture = -1;     ///< its own texture, an index into `textures`; -1: the blob's
        bool operator==(const Component&) const = default;
    };
    double threshold = 1.0;
    std::vector<Component> components;  ///< in the order POV-Ray keeps them: the last written first
    /// The components' own textures (POV-Ray blends the textures at a point by each component's density there),
    /// moved with the blob as its texture is.
    SharedVector<Texture> textures;
    /// Every transform applied to the blob since it was read (its own and its CSG parents'): blob space to world,
    /// where the component densities that weight their textures are found.
    Cow<Transform> placement;
    bool operator==(const Blob&) const = default;
};

/// POV-Ray's `bicubic_patch { type 0|1 [flatness f] [u_steps n] [v_steps n] <p00>, ..., <p33> }`: the Bézier
/// patch of 16 control points (row i runs along u), which POV-Ray tessellates after every transform: subpatches
/// split in half until flat within `flatness` or `u_steps`/`v_steps` halvings deep, two smooth triangles each.
struct BicubicPatch {
    int type = 0;
    double flatness = 0.0;
    int u_steps = 0;
    int v_steps = 0;
    /// The 16 control points. On the heap, as the uv vectors, so that every object (all of them `Shape`s, a
    /// variant as large as its largest kind) does not carry a patch's 500 bytes.
    std::vector<Vec3> points = std::vector<Vec3>(16);
    /// `uv_vectors`: the texture (u, v, 0) at the patch corners (u, v) = (0, 0), (1, 0), (1, 1), (0, 1) of
    /// POV-Ray's corner order, for uv_mapping; POV-Ray's defaults without them.
    std::vector<Vec3> uv_vectors{{0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {1.0, 1.0, 0.0}, {0.0, 1.0, 0.0}};
    /// Every transform applied to the patch since it was read (its own and its CSG parents'), in order: POV-Ray
    /// tessellates the transformed control points, so flatness is measured after it.
    Cow<Transform> placement;
    bool operator==(const BicubicPatch&) const = default;
};

/// Triangles: `triangle`, `smooth_triangle`, `mesh` and `mesh2` all become one list of faces.
struct Mesh {
    enum class Kind { Triangle, SmoothTriangle, Mesh, Mesh2 };
    /// One face: three vertex indices and, for smooth faces, three normal indices (-1 when flat).
    struct Face {
        std::array<int, 3> v{};
        std::array<int, 3> n{-1, -1, -1};
        std::array<int, 3> uv{-1, -1, -1};   ///< indices into `uvs` (-1: POV-Ray's default uv of the corner)
        std::array<int, 3> tex{-1, -1, -1};  ///< indices into `textures`: none, one (tex[0]) or one per corner
        bool operator==(const Face&) const = default;
    };
    Kind kind = Kind::Mesh;
    /// The keyword this mesh was written with (one per Kind, in its order).
    const char* keyword() const {
        static constexpr const char* names[] = {"triangle", "smooth_triangle", "mesh", "mesh2"};
        return names[static_cast<int>(kind)];
    }
    // Shared between copies (a declared mesh used many times costs its size once) until one of them changes.
    SharedVector<Vec3> vertices;
    SharedVector<Vec3> normals;
    SharedVector<Face> faces;
    SharedVector<Vec3> uvs;           ///< `uv_vectors` (u, v, 0)
    SharedVector<Texture> textures;   ///< per-triangle textures and mesh2's `texture_list`
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
    std::vector<double> coefficients = std::vector<double>(35);  ///< on the heap, as a bicubic patch's points
    bool sturm = false;  ///< roots by Sturm sequences rather than POV-Ray's closed form
    bool operator==(const Quartic&) const = default;
};

/// POV-Ray's `cubic { <a0, ..., a19> }`, `poly { order, <a0, ...> }` and `polynomial { order, xyz(i, j, k): a, ... }`:
/// the sum of a_i times the monomials x^i y^j z^k (i + j + k <= order) in the order of `quartic`; inside where
/// below POV-Ray's tolerance 1e-4.
struct Poly {
    enum class Kind { Cubic, Poly, Polynomial };
    Kind kind = Kind::Poly;
    /// The keyword this polynomial was written with (one per Kind, in its order).
    const char* keyword() const {
        static constexpr const char* names[] = {"cubic", "poly", "polynomial"};
        return names[static_cast<int>(kind)];
    }
    int order = 2;
    std::vector<double> coefficients;  ///< (order + 1)(order + 2)(order + 3) / 6 of them
    bool sturm = false;                ///< Sturm sequences for orders 3 and 4 (higher ones always)
    bool operator==(const Poly&) const = default;
};

/// POV-Ray's `julia_fractal { <c> [quaternion | hypercomplex] [sqr | cube | reciprocal | exp | ln | sin | asin | cos |
/// acos | tan | atan | sinh | asinh | cosh | acosh | tanh | atanh | pwr(a, b)] [max_iteration n] [precision p]
/// [slice <4-vector>, d] }`: the 3-D slice of the filled Julia set of z -> f(z) + c in 4-D (quaternions or
/// hypercomplex numbers), the fourth coordinate w taken from the slice plane.
struct JuliaFractal {
    enum class Algebra { Quaternion, Hypercomplex };
    enum class Function { Exp, Ln, Sin, Asin, Cos, Acos, Tan, Atan, Sinh, Asinh, Cosh, Acosh, Tanh, Atanh, Pwr, Sqr,
                          Cube, Reciprocal };
    std::array<double, 4> c{1.0, 0.0, 0.0, 0.0};
    Algebra algebra = Algebra::Quaternion;
    Function function = Function::Sqr;
    double exponent_re = 0.0;  ///< pwr's exponent
    double exponent_im = 0.0;
    int max_iteration = 20;
    double step = 1.0 / 20.0;                  ///< 1 / precision
    std::array<double, 4> slice{0.0, 0.0, 0.0, 1.0};  ///< unit normal of the slice hyperplane
    double slice_distance = 0.0;
    bool operator==(const JuliaFractal&) const = default;
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

/// POV-Ray's `sphere_sweep { linear_spline | b_spline | cubic_spline n, <c>, r, ... [tolerance d] }`: a sphere
/// moved along the spline through the control spheres, its radius interpolated alike; b_spline and cubic_spline
/// take at least 4 control spheres, the first and the last only shaping the ends (cubic_spline, POV-Ray's
/// Catmull-Rom spline, passes through the others; b_spline approximates them).
struct SphereSweep {
    enum class Spline { Linear, BSpline, Cubic };
    Spline spline = Spline::Linear;
    std::vector<Vec3> centers;
    std::vector<double> radii;
    double tolerance = 1e-6;  ///< POV-Ray's depth tolerance: crossings nearer a ray's origin are dropped
    bool operator==(const SphereSweep&) const = default;
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

/// POV-Ray's `isosurface { function { f } [contained_by { box { c1, c2 } | sphere { c, r } }] [threshold t]
/// [accuracy a] [max_gradient g] [evaluate p0, p1, p2] [open] [max_trace n | all_intersections] }`: the surface
/// f(x, y, z) = t inside its container, inside where f < t; a closed isosurface is capped by the container.
struct Isosurface {
    function::SharedFunction function;
    bool sphere_container = false;
    Vec3 corner1{-1.0, -1.0, -1.0};  ///< the container box, ordered so corner1 <= corner2
    Vec3 corner2{1.0, 1.0, 1.0};
    Vec3 center;                     ///< the container sphere
    double radius = 1.0;
    double threshold = 0.0;
    double accuracy = 0.001;
    double max_gradient = 1.1;
    bool evaluate = false;
    std::array<double, 3> eval{};  ///< evaluate's min_factor, attenuation and its third value
    bool open = false;
    int max_trace = 1;
    int noise_generator = 2;  ///< the scene's global noise_generator when the isosurface was read
    SourceLoc function_loc;   ///< where the function starts, for the max_gradient warning
    bool operator==(const Isosurface&) const = default;
};

/// POV-Ray's `parametric { function { x(u, v) }, function { y(u, v) }, function { z(u, v) } <u1, v1>, <u2, v2>
/// [contained_by { box { c1, c2 } | sphere { c, r } }] [max_gradient g] [accuracy a] [precompute depth, x, y, z] }`:
/// the surface (x(u, v), y(u, v), z(u, v)) over the uv rectangle, found by subdividing it with interval bounds
/// from max_gradient; only the nearest crossing, no inside.
struct Parametric {
    std::array<function::SharedFunction, 3> functions;
    double u_min = 0.0, v_min = 0.0, u_max = 1.0, v_max = 1.0;  ///< ordered so min <= max
    bool sphere_container = false;
    Vec3 corner1{-1.0, -1.0, -1.0};  ///< the container box, ordered so corner1 <= corner2
    Vec3 corner2{1.0, 1.0, 1.0};
    Vec3 center;                     ///< the container sphere
    double radius = 1.0;
    double accuracy = 0.001;
    double max_gradient = 1.0;
    int precompute_depth = 0;  ///< 0: no precompute, else 1..20
    int precompute_axes = 0;   ///< bit 0 x, bit 1 y, bit 2 z: the coordinates whose bounds are precomputed
    int noise_generator = 2;   ///< the scene's global noise_generator when the parametric was read
    bool operator==(const Parametric&) const = default;
};

/// A height field's elevation grid as POV-Ray stores it: one 16-bit height (0..65535) per image pixel, row z = 0
/// being the image's bottom row.
struct HeightGrid {
    int width = 0;   ///< pixels along x (at least 2)
    int height = 0;  ///< pixels along z (at least 2)
    std::vector<std::uint16_t> heights;  ///< width * height, row-major from z = 0
    std::uint16_t at(int x, int z) const { return heights[static_cast<std::size_t>(z) * width + x]; }
    bool operator==(const HeightGrid&) const = default;
};

/// POV-Ray's `height_field { [type] "file" | function W, H { f } [smooth] [water_level w] [hierarchy on|off] }`:
/// two triangles per grid cell over the unit square (x and z from 0 to 1, y = height / 65536), the cell's diagonal
/// from (x + 1, z) to (x, z + 1); nothing below water_level is drawn.
struct HeightField {
    std::shared_ptr<const HeightGrid> grid;
    bool smooth = false;
    double water_level = 0.0;  ///< a fraction of the full height
    /// Every transform applied to the field since it was read (its own and its CSG parents'), in order: POV-Ray
    /// interpolates the smooth vertex normals after taking them to world space.
    Cow<Transform> placement;
    bool operator==(const HeightField&) const = default;
};

}  // namespace wardray::scene

/// The primitive shapes, listed once: X(keyword, SceneType) for each keyword that starts a primitive, in the order
/// of the Shape variant's alternatives (scene/object.h). The variant, the parser's keyword table, reserved words and
/// the reader each keyword calls (`Parser::read_<keyword>`), `--check`'s names and the geometry factory all come
/// from this list. A type that several keywords write (Mesh) names its keyword through `keyword()`.
#define WARDRAY_SHAPES(X)             \
    X(sphere, Sphere)                 \
    X(box, Box)                       \
    X(plane, Plane)                   \
    X(cylinder, Cylinder)             \
    X(cone, Cone)                     \
    X(disc, Disc)                     \
    X(torus, Torus)                   \
    X(ovus, Ovus)                     \
    X(blob, Blob)                     \
    X(bicubic_patch, BicubicPatch)    \
    X(triangle, Mesh)                 \
    X(smooth_triangle, Mesh)          \
    X(mesh, Mesh)                     \
    X(mesh2, Mesh)                    \
    X(polygon, Polygon)               \
    X(quadric, Quadric)               \
    X(superellipsoid, Superellipsoid) \
    X(quartic, Quartic)               \
    X(cubic, Poly)                    \
    X(poly, Poly)                     \
    X(polynomial, Poly)               \
    X(julia_fractal, JuliaFractal)    \
    X(prism, Prism)                   \
    X(lathe, Lathe)                   \
    X(sor, Sor)                       \
    X(sphere_sweep, SphereSweep)      \
    X(text, Text)                     \
    X(isosurface, Isosurface)         \
    X(parametric, Parametric)         \
    X(height_field, HeightField)
