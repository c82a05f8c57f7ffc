// Scene description, objects: a shape with its placement, appearance and flags; CSG over objects.
#pragma once

#include <array>
#include <cstdint>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

#include "core/diagnostics.h"
#include "core/transform.h"
#include "scene/cow.h"
#include "scene/interior.h"
#include "scene/kind_list.h"
#include "scene/shapes.h"
#include "scene/texture.h"

namespace wardray::scene {

struct Object;

/// Constructive solid geometry over child objects (each with its own transform relative to this node).
struct Csg {
    enum class Op { Union, Intersection, Difference, Merge };
    Op op = Op::Union;
    std::vector<Object> children;
    /// The keyword that wrote this node (one per Op, in its order).
    const char* keyword() const {
        static constexpr const char* names[] = {"union", "intersection", "difference", "merge"};
        return names[static_cast<int>(op)];
    }
    bool operator==(const Csg&) const = default;
};

#define WARDRAY_SHAPE_TYPE(keyword, Type) Type,
/// The shapes the renderer draws: the types of WARDRAY_SHAPES (scene/shapes.h) in its order, then CSG.
using Shape = UniqueVariant<WARDRAY_SHAPES(WARDRAY_SHAPE_TYPE) Csg>;
#undef WARDRAY_SHAPE_TYPE

#define WARDRAY_SHAPE_KEYWORD(keyword, Type) std::string_view{#keyword},
/// Every keyword that starts a primitive, in the order of WARDRAY_SHAPES.
inline constexpr std::array k_shape_keywords = {WARDRAY_SHAPES(WARDRAY_SHAPE_KEYWORD)};
#undef WARDRAY_SHAPE_KEYWORD

/// An object's `photons { target [spacing multiplier] refraction reflection collect pass_through }` block; the
/// flags as POV-Ray keeps them after promoting a CSG's to its children and CheckPassThru.
struct ObjectPhotons {
    bool target = false;
    double spacing_multiplier = 1.0;  ///< POV-Ray's Ph_Density
    PhotonSwitch refraction = PhotonSwitch::Unset;
    PhotonSwitch reflection = PhotonSwitch::Unset;
    bool collect = true;  ///< `collect off` sets PH_IGNORE_PHOTONS_FLAG
    bool pass_through = false;
    bool operator==(const ObjectPhotons&) const = default;
};

/// One object of the scene: a shape, its placement, its appearance and its flags.
struct Object {
    Shape shape;
    Transform transform;  ///< object space to world space, in the order the keywords appeared
    /// Shared with the declared object or CSG parent it came from until one of them changes it; empty: default.
    Cow<Texture> texture;
    /// The interior rays see inside this object: its own, or after parsing its CSG parent's when it has none.
    Interior interior;
    /// Which interior this is (POV-Ray's Interior pointer): objects with the same nonzero id share one interior
    /// (the children that inherit it from their CSG parent), which POV-Ray's ray interior list counts once. 0
    /// while parsing means none of its own yet; an object built without the parser with 0 is its own interior.
    std::uint32_t interior_id = 0;
    /// `hollow` was given on this object itself (POV-Ray's HOLLOW_SET_FLAG): a CSG's `hollow` leaves it alone.
    bool hollow_set = false;
    bool inverse = false;
    bool no_shadow = false;
    bool no_image = false;
    bool no_reflection = false;
    bool no_radiosity = false;
    bool has_texture = false;  ///< the statement gave its own texture (else it takes its CSG parent's)
    /// Object `uv_mapping` (POV-Ray's UV_FLAG): every texture is evaluated at (u, v, 0) and stays put.
    bool uv_mapping = false;
    /// `interior_texture`: at most one texture (its further layers in `layers`), seen where a ray meets the surface
    /// from inside; empty when the object has none (then `texture` is seen from both sides).
    std::vector<Texture> interior_texture;
    /// `double_illuminate`: lights behind the surface light it too (POV-Ray's DOUBLE_ILLUMINATE_FLAG).
    bool double_illuminate = false;
    /// The light groups whose lights light this surface (scene::Light::group), innermost first.
    std::vector<int> light_groups;
    /// In a light_group without `global_lights`: the global lights do not light it (NO_GLOBAL_LIGHTS_FLAG).
    bool no_global_lights = false;
    ObjectPhotons photons;
    std::vector<Object> clipped_by;  ///< clipping objects, placed relative to this object's transform
    /// `bounded_by` objects, placed as clipped_by: POV-Ray tests the object only on rays that meet them all.
    std::vector<Object> bounded_by;
    SourceLoc loc;
    bool operator==(const Object&) const = default;
};

/// POV-Ray's test of two objects' Interior pointers: true when `a` and `b` have one interior (the same object, or
/// an interior a CSG's children share).
inline bool same_interior(const Object& a, const Object& b) {
    return &a == &b || (a.interior_id != 0 && a.interior_id == b.interior_id);
}

namespace detail {

/// The keyword of shape type T when exactly one keyword of WARDRAY_SHAPES writes it, else empty.
template <typename T>
constexpr std::string_view only_keyword() {
    std::string_view found;
    int count = 0;
#define WARDRAY_SHAPE_MATCH(keyword, Type) \
    if (std::is_same_v<T, Type>) {         \
        found = #keyword;                  \
        ++count;                           \
    }
    WARDRAY_SHAPES(WARDRAY_SHAPE_MATCH)
#undef WARDRAY_SHAPE_MATCH
    return count == 1 ? found : std::string_view{};
}

}  // namespace detail

/// The keyword a shape was written with, as `--check` names it: "sphere", "mesh2", "union", ...
inline const char* shape_keyword(const Shape& shape) {
    return std::visit(
        [](const auto& s) -> const char* {
            using T = std::decay_t<decltype(s)>;
            if constexpr (requires { s.keyword(); }) {
                return s.keyword();
            } else {
                constexpr std::string_view keyword = detail::only_keyword<T>();
                static_assert(!keyword.empty(), "a shape type several keywords write names its own with keyword()");
                return keyword.data();  // a string literal's view: null-terminated
            }
        },
        shape);
}

}  // namespace wardray::scene
