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
    /// A modifier that is valid POV-Ray and not rendered yet: warns and skips its block.
    static void skip_unsupported_modifier(ObjectReader& r, ObjectValue& ov, const Token& kw, ModifierState& state);
    /// Applies `tr` to every part of the object and the textures given so far.
    void apply_transform(ObjectValue& ov, const Transform& tr);
    /// The texture a modifier of `ov` changes (its own, made from the default when it had none).
    Texture& texture_to_modify(ObjectValue& ov);
    /// Reads `light_source { ... }` after its keyword.
    Light parse_light_body(const Token& kw);
    /// Reads `area_light` axis1, axis2, size1, size2 (commas optional) into `light`.
    void parse_area_light(Light& light);
    /// A light item that is valid POV-Ray and not rendered yet: warns and skips its block.
    static void skip_unsupported_light_item(ObjectReader& r, Light& light, const Token& kw);

    /// Reads a primitive's parameters after its '{' (the shape reader's).
    virtual Shape parse_shape_parameters(const Token& kw) = 0;
    /// An object statement's value as one Object: a union node when it holds several parts (the shape reader's).
    virtual std::optional<Object> as_single_object(ObjectValue& ov) = 0;
    /// Turns a flattened union into one union node, for inverse and clipped_by (the shape reader's).
    virtual void make_union_node(ObjectValue& ov) = 0;
    /// Reads `{ object ... }` (clipped_by, bounded_by) into Objects (the shape reader's).
    virtual std::vector<Object> parse_object_list(const Token& kw, const std::vector<Object>* bounded_by) = 0;
};

}  // namespace wardray::parser
