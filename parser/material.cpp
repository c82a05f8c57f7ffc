// Materials and inside surfaces: `material { texture interior_texture interior }` (declared or given on an
// object), an object's `interior_texture` and `double_illuminate`, as POV-Ray 3.7 reads them (Parse_Material).
#include "parser/keywords.h"
#include "parser/parser.h"

namespace wardray::parser {

namespace {

/// POV-Ray's Link_Textures: a further texture statement becomes a layer over the ones before it.
void link_texture(std::optional<Texture>& to, Texture tx) {
    if (!to) {
        to = std::move(tx);
        return;
    }
    add_layers(*to, std::move(tx));
}

/// Moves a texture and the layers it holds with the transform `tr`.
void transform_all(std::optional<Texture>& tx, const Transform& tr) {
    if (tx) transform_texture(*tx, tr);
}

/// Sets double_illuminate on an object and down its CSG tree (POV-Ray's Set_CSG_Tree_Flag).
void set_double_illuminate(Object& o, bool on) {
    o.double_illuminate = on;
    // POV-Ray compat: a difference keeps the flag to itself, and its surfaces (its children's) do not see it.
    if (auto* csg = std::get_if<Csg>(&o.shape); csg && csg->op != Csg::Op::Difference)
        for (Object& child : csg->children) set_double_illuminate(child, on);
}

}  // namespace

MaterialValue ObjectReader::parse_material_body(const Token& /*kw*/) {
    expect("{");
    MaterialValue m;
    expand_macros();
    if (is_array_element_next()) {
        // An element of an array of materials (sample.inc's `material { MArr[I] }`).
        const Token at = peek();
        const Value element = *take_array_element();
        if (const auto* declared = std::get_if<Boxed<MaterialValue>>(&element)) m = **declared;
        else fail(at, "this array element is not a material");
    } else if (const Token& first = peek();
        first.kind == TokenKind::Identifier && !is_keyword(first.text) && !m_macros.count(first.text)) {
        // POV-Ray compat: a declared material, which the items after it add to.
        const Value* v = lookup(first.text);
        if (v == nullptr) fail_undeclared(first);
        if (const auto* declared = std::get_if<Boxed<MaterialValue>>(v)) m = **declared;
        else fail(first, "'" + first.text + "' is " + value_kind_name(*v) + ", not a material");
        next();
    }
    while (true) {
        expand_macros();
        const Token t = peek();
        Transform tr;
        if (parse_transform_item(t, tr)) {
            // POV-Ray compat: a material's transforms move its textures (and its interior's media).
            transform_all(m.texture, tr);
            transform_all(m.interior_texture, tr);
            continue;
        }
        next();
        if (is_punct(t, "}")) return m;
        if (is_word(t, "texture")) {
            link_texture(m.texture, parse_texture_body(t));
        } else if (is_word(t, "interior_texture")) {
            link_texture(m.interior_texture, parse_texture_body(t));
        } else if (is_word(t, "interior")) {
            m.interior = parse_interior_body(t);
        } else {
            if (t.kind == TokenKind::Identifier && !is_keyword(t.text) && lookup(t.text) == nullptr)
                fail_undeclared(t);
            fail(t, "expected texture, interior_texture, interior or a transform in material but found " +
                        describe_token(t));
        }
    }
}

void ObjectReader::add_texture(ObjectValue& ov, const Texture& tx, const Token& kw, ModifierState& state) {
    const bool compound = ov.compound || ov.parts.size() != 1;
    const bool own = state.textured || (compound ? ov.texture.has_value() : ov.parts.front().has_texture);
    Texture& to = texture_to_modify(ov);
    state.textured = true;
    if (!own) {
        to = tx;
        return;
    }
    if (to.map_pattern.type != Pattern::Type::None || !to.texture_map.empty()) {
        warn(kw, "POV-Ray cannot layer a texture over a patterned one (it stops with an error); this texture "
                 "replaces it");
        to = tx;
        return;
    }
    std::optional<Texture> linked = std::move(to);
    link_texture(linked, tx);
    to = std::move(*linked);
}

void ObjectReader::apply_material(ObjectValue& ov, const MaterialValue& m, const Token& kw, ModifierState& state) {
    // As a texture statement would: over the object's own texture, when it has one.
    if (m.texture) add_texture(ov, *m.texture, kw, state);
    if (m.interior_texture) add_interior_texture(ov, *m.interior_texture);
    if (m.interior) set_interior(ov, *m.interior);
}

void ObjectReader::add_interior_texture(ObjectValue& ov, const Texture& tx) {
    if (!ov.compound && ov.parts.size() == 1) {
        std::vector<Texture>& own = ov.parts.front().object.interior_texture;
        std::optional<Texture> linked;
        if (!own.empty()) linked = std::move(own.front());
        link_texture(linked, tx);
        own = {std::move(*linked)};
        return;
    }
    // POV-Ray compat (Post_Process): a union's interior texture goes to the children that have none.
    for (ObjectPart& part : ov.parts)
        if (part.object.interior_texture.empty()) part.object.interior_texture = {tx};
}

void ObjectReader::read_material_modifier(ObjectReader& r, ObjectValue& ov, const Token& kw, ModifierState& state) {
    r.apply_material(ov, r.parse_material_body(kw), kw, state);
}

void ObjectReader::read_interior_texture(ObjectReader& r, ObjectValue& ov, const Token& kw, ModifierState&) {
    r.add_interior_texture(ov, r.parse_texture_body(kw));
}

void ObjectReader::read_double_illuminate(ObjectReader& r, ObjectValue& ov, const Token&, ModifierState&) {
    const bool on = r.parse_bool_optional();
    for (ObjectPart& part : ov.parts) set_double_illuminate(part.object, on);
}

}  // namespace wardray::parser
