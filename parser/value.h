// Values the scene language computes and stores in identifiers: numbers, strings and scene items.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "parser/namespaces.h"
#include "parser/part_list.h"
#include "parser/splines.h"

namespace wardray::parser {

/// A float (n == 1), a vector of 2..5 components, or a colour (five components: r g b filter transmit).
struct Numeric {
    int n = 1;
    std::array<double, 5> v{};

    /// A float.
    static Numeric scalar(double f) {
        Numeric r;
        r.v[0] = f;
        return r;
    }
    /// A 3-vector.
    static Numeric vector3(const Vec3& a) {
        Numeric r;
        r.n = 3;
        r.v = {a.x, a.y, a.z, 0.0, 0.0};
        return r;
    }
    /// A colour with its five components.
    static Numeric color(const Color& c) {
        Numeric r;
        r.n = 5;
        r.v = {c.r, c.g, c.b, c.filter, c.transmit};
        return r;
    }
    /// POV-Ray compat: a float promotes to every component, a shorter vector is padded with zeros.
    Numeric promoted(int terms) const {
        Numeric r = *this;
        if (n >= terms) return r;
        for (int i = n; i < terms; ++i) r.v[i] = (n == 1) ? v[0] : 0.0;
        r.n = terms;
        return r;
    }
    /// The first three components (a float fills all three).
    Vec3 vec3() const {
        const Numeric p = promoted(3);
        return {p.v[0], p.v[1], p.v[2]};
    }
    /// As a colour, with POV-Ray's promotion to five components.
    Color to_color() const {
        const Numeric p = promoted(5);
        return {p.v[0], p.v[1], p.v[2], p.v[3], p.v[4]};
    }
};

/// An object statement after flattening unions: its shapes and the lights it holds.
struct ObjectValue {
    PartList parts;  ///< shared with the declared object it was copied from until one of them changes
    std::vector<Light> lights;
    bool compound = false;            ///< a union: its texture goes to the parts without one
    std::optional<Texture> texture;   ///< the union's own texture
    /// The union's own interior, when it has one: the parts with this Object::interior_id share it.
    std::uint32_t interior_id = 0;
    /// The objects charged to the parse's object budget as copies of declared objects; a redeclaration that
    /// drops this value gives them back, so `#declare U = union { object { U } ... }` repeated costs one
    /// object per new part, not one per part copied.
    std::size_t copied = 0;
};

/// The camera as written, before resolution to the final vectors.
struct CameraSpec {
    Camera::Type type = Camera::Type::Perspective;
    Vec3 location{0.0, 0.0, 0.0};
    Vec3 direction{0.0, 0.0, 1.0};
    Vec3 right{1.33, 0.0, 0.0};
    Vec3 up{0.0, 1.0, 0.0};
    Vec3 sky{0.0, 1.0, 0.0};
    std::optional<Vec3> look_at;
    std::optional<double> angle;
    std::optional<double> v_angle;  ///< spherical: the second value of `angle`
    int cylinder = 1;
    MeshCameraSpec mesh_camera;
    std::optional<Normal> normal;
    std::optional<Vec3> focal_point;
    double aperture = 0.0;
    int blur_samples = 0;
    int blur_samples_min = 0;
    double confidence = 0.9;
    double variance = 1.0 / 10000.0;
    bool had_up = false;
    bool had_right = false;
    bool other_projection = false;  ///< a projection not rendered yet (its angle is not checked)
    Transform transform;
    SourceLoc loc;
};

/// Resolves a camera as POV-Ray 3.7 does: angle, then look_at (with sky), then orthographic sizing, then transforms.
/// Returns an error message in `error` when the camera is degenerate (and leaves the vectors usable).
Camera resolve_camera(const CameraSpec& spec, std::string& error, std::string& warning);

/// A `material { texture interior_texture interior }`: what it gives the object it is put on.
struct MaterialValue {
    std::optional<Texture> texture;           ///< further texture statements are in its layers
    std::optional<Texture> interior_texture;  ///< likewise
    std::optional<Interior> interior;
};

/// A declared item of a kind not supported yet (material, media, ...), kept by name only.
struct Unsupported {
    std::string what;
};

struct ArrayValue;

/// A declared `function { ... }`: a compiled float function, a transform function (returns a vector), or a kind
/// a spline function (its spline's value at the first argument), or a kind that is parsed but not evaluated yet
/// (pattern, pigment), which evaluates to zero with a warning.
struct UserFunction {
    enum class Kind { Float, Transform, Pattern, Pigment, Spline };
    Kind kind = Kind::Float;
    std::shared_ptr<const FunctionProgram> program;  ///< Float: the compiled body
    Transform transform;                             ///< Transform: maps the point (x, y, z)
    std::shared_ptr<const Spline> spline;            ///< Spline: the spline
    std::shared_ptr<const Pigment> pigment;          ///< Pattern and Pigment: the block (its pattern, or colours)
    SourceLoc loc;
};

struct OpenFile;

/// The identifier #fopen creates; #fclose, or reading past the end, removes it.
struct FileHandle {
    std::shared_ptr<OpenFile> file;
};

/// A large item held in a Value: shared and immutable, so copying a Value is cheap and a declared identifier
/// costs a few dozen bytes plus its item (a texture is nearly 2 KB; include files declare hundreds).
template <typename T>
class Boxed {
public:
    Boxed(T item) : m_item(std::make_shared<const T>(std::move(item))) {}  // NOLINT: converts like the item
    const T& operator*() const { return *m_item; }
    const T* operator->() const { return m_item.get(); }
    /// Whether this is the item's only holder (dropping it frees the item).
    bool sole() const { return m_item.use_count() == 1; }

private:
    std::shared_ptr<const T> m_item;
};

/// A library declaration not evaluated yet: an index into the parser's deferred declarations. Only the symbol
/// tables hold it; looking the identifier up evaluates it first.
struct Deferred {
    std::uint32_t index = 0;
};

/// Anything an identifier can hold. Deferred stays last (value_kind_name names the others by index).
using Value = std::variant<Numeric, std::string, Boxed<Pigment>, Boxed<Finish>, Boxed<Texture>, Boxed<ObjectValue>,
                           Boxed<Transform>, Boxed<CameraSpec>, Unsupported, std::shared_ptr<ArrayValue>,
                           std::shared_ptr<const UserFunction>, FileHandle, Boxed<Interior>, Boxed<Normal>,
                           Boxed<Spline>, Boxed<SkySphere>, Boxed<Fog>, Boxed<Rainbow>, Boxed<Media>,
                           Boxed<MaterialValue>, Deferred>;

/// An `array[N][M]...`: elements in row-major order, each empty until assigned.
struct ArrayValue {
    std::vector<std::size_t> dims;
    std::vector<std::optional<Value>> elements;
};

}  // namespace wardray::parser
