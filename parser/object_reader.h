// ObjectReader: object statements (shapes, CSG, declared objects), their modifiers, transforms and lights.
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include "parser/appearance_reader.h"

namespace wardray::parser {

/// Reads objects: a shape, a CSG node or a declared object with its modifiers (textures, transforms, flags,
/// clipping), and light sources. The shape parameters are read by the shape reader (shapes.cpp) through the
/// hooks below.
class ObjectReader : public AppearanceReader {
protected:
    using AppearanceReader::AppearanceReader;

    /// True when `t` starts an object: an object keyword, or a declared object's identifier standing alone.
    bool is_object_start(const Token& t);
    /// Reads an object after its keyword `kw`, or the copy of the declared object `kw` names.
    ObjectValue parse_object(const Token& kw);
    /// Reads a CSG block's child statements and light sources up to its modifiers: each child object goes to
    /// `take_child`, the lights (the children's too) to `ov`.
    void read_csg_children(ObjectValue& ov, const std::function<void(ObjectValue& child)>& take_child);
    /// Reads an object's modifiers up to its '}'; `compound` for CSG, whose children come first.
    void parse_object_modifiers(ObjectValue& ov, bool compound);
    /// What one object's modifiers have read so far, which later modifiers depend on.
    struct ModifierState {
        bool textured = false;            ///< a texture was given: further ones are layers
        std::vector<Object> bounded_by;   ///< for clipped_by without objects of its own
    };
    /// Applies `tr` to every part of the object and the textures given so far.
    void apply_transform(ObjectValue& ov, const Transform& tr);
    /// The texture a modifier of `ov` changes (its own, made from the default when it had none).
    Texture& texture_to_modify(ObjectValue& ov);
    /// Reads `material { ... }` after its keyword (material.cpp).
    MaterialValue parse_material_body(const Token& kw);
    /// Gives `ov` a material's texture (as a texture statement would), interior texture and interior.
    void apply_material(ObjectValue& ov, const MaterialValue& m, const Token& kw, ModifierState& state);
    /// A texture statement (or a material's texture) at `kw`: POV-Ray compat (Link_Textures), it goes on top of
    /// the object's texture when it has a plain one of its own (from an earlier texture, pigment, normal or finish
    /// statement, or the declared object it copies), and else becomes its texture.
    void add_texture(ObjectValue& ov, const Texture& tx, const Token& kw, ModifierState& state);
    /// The interior an `interior` modifier of `ov` changes: the object's own, or the union's.
    Interior own_interior(const ObjectValue& ov) const;
    /// Gives `ov` an interior (an `interior` or `material` modifier): its own, or a union's, which its parts that
    /// have none share.
    void set_interior(ObjectValue& ov, const Interior& in);
    /// Gives a copy of a declared object interior ids of its own (POV-Ray's Copy_Object copies each interior).
    void fresh_interior_ids(ObjectValue& ov);
    /// Gives `ov` parts of its own before they change, charging the copies to the object budget at `at`.
    void own_parts(ObjectValue& ov, const Token& at);
    /// Gives `ov` an interior texture: layered over its own, or to each part of a union that has none.
    void add_interior_texture(ObjectValue& ov, const Texture& tx);
    /// The `material`, `interior_texture` and `double_illuminate` modifiers (material.cpp).
    static void read_material_modifier(ObjectReader& r, ObjectValue& ov, const Token& kw, ModifierState& state);
    static void read_interior_texture(ObjectReader& r, ObjectValue& ov, const Token& kw, ModifierState& state);
    static void read_double_illuminate(ObjectReader& r, ObjectValue& ov, const Token& kw, ModifierState& state);
    /// `sturm [bool]`: Sturm sequences instead of closed forms for a cubic or quartic (parser/shapes.cpp).
    static void read_sturm(ObjectReader& r, ObjectValue& ov, const Token& kw, ModifierState& state);
    /// An object's `photons { }` block (parser/photons.cpp).
    static void read_object_photons(ObjectReader& r, ObjectValue& ov, const Token& kw, ModifierState& state);
    /// A light's `photons { refraction reflection area_light }` block.
    static void read_light_photons(ObjectReader& r, Light& light, const Token& kw);
    /// Reads `light_group { objects lights modifiers }` after its keyword (light_group.cpp): a union whose lights
    /// light only its objects.
    ObjectValue parse_light_group(const Token& kw);
    /// Gives every light group of `ov` a number no other placed object uses (a declared group placed twice
    /// becomes two groups, each lighting its own objects).
    void renumber_light_groups(ObjectValue& ov);
    /// Reads `light_source { ... }` after its keyword; its `looks_like` object goes to `looks` (where it is null,
    /// the object is left out with a warning).
    Light parse_light_body(const Token& kw, ObjectValue* looks = nullptr);
    /// Reads `projected_through { object modifiers }` into the light (light_objects.cpp).
    void read_projected_through(Light& light, const Token& kw);
    /// Moves a light's position, point_at and projected_through object (not its area axes).
    static void transform_light(Light& light, const Transform& tr);
    /// Reads `looks_like { object modifiers }` (light_objects.cpp): the object, moved to the light, casting no shadow.
    void read_looks_like(const Light& light, ObjectValue* looks, const Token& kw);
    /// Reads `area_light` axis1, axis2, size1, size2 (commas optional) into `light`.
    void parse_area_light(Light& light);

    /// Reads a primitive's parameters after its '{' (the shape reader's).
    virtual Shape parse_shape_parameters(const Token& kw) = 0;
    /// An object statement's value as one Object: a union node when it holds several parts (the shape reader's).
    virtual std::optional<Object> as_single_object(ObjectValue& ov) = 0;
    /// Turns a flattened union into one union node, for inverse and clipped_by (the shape reader's).
    virtual void make_union_node(ObjectValue& ov) = 0;
    /// Reads `{ object ... }` (clipped_by, bounded_by) into Objects (the shape reader's).
    virtual std::vector<Object> parse_object_list(const Token& kw, const std::vector<Object>* bounded_by) = 0;

    int m_light_group_count = 0;  ///< the light groups numbered so far (Light::group)
    std::uint32_t m_interior_ids = 0;  ///< the interior ids given so far (Object::interior_id)
};

}  // namespace wardray::parser
