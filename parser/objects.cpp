// Objects: object statements (union flattening, CSG nodes), their modifiers, transforms and light sources.
#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>
#include <memory>

#include "parser/keyword_table.h"
#include "parser/keywords.h"
#include "parser/parser.h"
#include "parser/texture_mover.h"

namespace wardray::parser {

bool is_object_keyword(const Token& t) {
    if (t.kind != TokenKind::Identifier) return false;
    const TokenText& w = t.text;
    return is_shape_keyword(w) || w == "object" || w == "union" || w == "intersection" || w == "difference" ||
           w == "merge" || is_unsupported_object(w);
}

namespace {

// POV-Ray compat: a transform moves the textures given before it (Transform_Textures), down a CSG tree.
void transform_textures(Object& o, bool own_texture, TextureMover& mover) {
    // POV-Ray compat: an object with uv_mapping keeps its textures in uv space.
    if (o.uv_mapping) return;
    if (own_texture) mover.move(o.texture);
    for (Texture& inside : o.interior_texture) mover.move(inside);
    if (auto* mesh = std::get_if<Mesh>(&o.shape); mesh && !mesh->textures.empty()) mover.move(mesh->textures);
    if (auto* blob = std::get_if<Blob>(&o.shape); blob && !blob->textures.empty()) mover.move(blob->textures);
    if (auto* csg = std::get_if<Csg>(&o.shape))
        for (Object& child : csg->children) transform_textures(child, child.has_texture, mover);
}

// POV-Ray compat: a bicubic patch is re-tessellated after every transform, also its CSG parents', and a smooth
// height field's normals are interpolated in world space; both keep the transforms.
void place_patches(Object& o, const Transform& tr) {
    if (auto* patch = std::get_if<BicubicPatch>(&o.shape)) patch->placement = patch->placement.get().then(tr);
    if (auto* hf = std::get_if<HeightField>(&o.shape)) hf->placement = hf->placement.get().then(tr);
    if (auto* blob = std::get_if<Blob>(&o.shape)) blob->placement = blob->placement.get().then(tr);
    if (auto* csg = std::get_if<Csg>(&o.shape))
        for (Object& child : csg->children) place_patches(child, tr);
}

// POV-Ray compat (Transform_Object): a transform moves the media of every interior down the CSG tree.
void transform_interiors(Object& o, const Transform& tr) {
    for (Media& m : o.interior.media) transform_media(m, tr);
    if (auto* csg = std::get_if<Csg>(&o.shape))
        for (Object& child : csg->children) transform_interiors(child, tr);
}

// POV-Ray compat (Set_CSG_Children_Flag): `hollow` on a CSG is given to every child below it that did not say
// `hollow` itself.
void set_children_hollow(Object& o, bool hollow) {
    auto* csg = std::get_if<Csg>(&o.shape);
    if (csg == nullptr) return;
    for (Object& child : csg->children) {
        if (child.hollow_set) continue;
        child.interior.hollow = hollow;
        set_children_hollow(child, hollow);
    }
}

// Gives `o` the interior `in`, keeping its own `hollow` (an object flag in POV-Ray, not an interior item).
void replace_interior(Object& o, const Interior& in, std::uint32_t id) {
    const bool hollow = o.interior.hollow;
    o.interior = in;
    o.interior.hollow = hollow;
    o.interior_id = id;
}

/// Sets the flag `flag` (no_shadow, no_image, ...) on every part of the object.
void set_flag(ObjectValue& ov, bool Object::*flag) {
    for (ObjectPart& part : ov.parts) part.object.*flag = true;
}

}  // namespace

void ObjectReader::parse_area_light(Light& light) {
    light.area = true;
    // POV-Ray compat: the commas between the four values are optional.
    light.area_axis1 = parse_vector();
    accept(",");
    light.area_axis2 = parse_vector();
    accept(",");
    const Token& at1 = peek();
    const double n1 = parse_float();
    accept(",");
    const Token& at2 = peek();
    const double n2 = parse_float();
    // POV-Ray compat: sizes are truncated, and a size below 1 is an error.
    if (!(n1 >= 1.0) || n1 > 1e4) fail(at1, "area_light size must be between 1 and 10000");
    if (!(n2 >= 1.0) || n2 > 1e4) fail(at2, "area_light size must be between 1 and 10000");
    light.area_size1 = static_cast<int>(n1);
    light.area_size2 = static_cast<int>(n2);
}

bool ObjectReader::is_object_start(const Token& t) {
    if (is_object_keyword(t)) return true;
    if (t.kind != TokenKind::Identifier || is_keyword(t.text) || m_macros.count(t.text)) return false;
    const Value* v = lookup(t.text);
    return v != nullptr && std::holds_alternative<Boxed<ObjectValue>>(*v);
}

namespace {

// True when `node` is a CSG node of `op` adding nothing of its own to its children (no placement, texture, interior,
// flags, clips or bounds), so that as a child of a node of `op` it can give it its children instead: an intersection
// or merge at any position (both are associative), a difference as a difference's first child (A - B - C).
bool splices_into(const Object& node, Csg::Op op) {
    // Every member, named so a new one fails to compile here until it is judged too.
    const auto& [shape, transform, texture, interior, interior_id, hollow_set, inverse, no_shadow, no_image,
                 no_reflection, no_radiosity, has_texture, uv_mapping, interior_texture, double_illuminate,
                 light_groups, no_global_lights, photons, clipped_by, bounded_by, loc] = node;
    static_cast<void>(texture);  // seen only through has_texture: the children without one inherit it
    static_cast<void>(loc);
    const auto* csg = std::get_if<Csg>(&shape);
    if (csg == nullptr || csg->op != op || op == Csg::Op::Union) return false;
    return transform == Transform{} && !has_texture && interior == Interior{} && interior_id == 0 && !hollow_set &&
           !inverse && !no_shadow && !no_image && !no_reflection && !no_radiosity && !uv_mapping &&
           interior_texture.empty() && !double_illuminate && light_groups.empty() && !no_global_lights &&
           photons == ObjectPhotons{} && clipped_by.empty() && bounded_by.empty();
}

/// `object { Declared }`: a copy of the declared object that shares its parts (O(1)); nothing is charged to the
/// object budget until the copy's parts are changed (ObjectReader::own_parts).
void copy_declared(ObjectValue& ov, const ObjectValue& declared) {
    ov = declared;
    ov.copied = 0;
}

}  // namespace

void ObjectReader::own_parts(ObjectValue& ov, const Token& at) {
    if (!ov.parts.shared()) return;
    const std::size_t charged = ov.parts.shared_objects();
    count_copies(at, charged);  // before copying, so a huge copy is never made
    ov.copied += charged;
    static_cast<void>(ov.parts.begin());
}

ObjectValue ObjectReader::parse_object(const Token& kw) {
    // Objects nest as deep as the stack allows (POV-Ray reads 20,000 nested unions); the rest to k_max_nesting.
    const NestingGuard guard(*this, kw, m_object_nesting, k_max_object_nesting);
    const TokenText& w = kw.text;
    if (!is_object_keyword(kw)) {
        // POV-Ray compat: a declared object's identifier alone is that object, without modifiers (Parse_Object).
        const Value* v = lookup(w);
        if (v == nullptr) fail_undeclared(kw);
        // Made in its own frame, so this one (on the stack once per nesting level) holds one ObjectValue, not two.
        const auto copy_of = [this](const ObjectValue& declared) __attribute__((noinline)) {
            ObjectValue copy;
            copy_declared(copy, declared);
            fresh_interior_ids(copy);
            return copy;
        };
        return copy_of(*std::get<Boxed<ObjectValue>>(*v));
    }
    if (w == "light_group") return parse_light_group(kw);
    if (is_unsupported_object(w) && !is_shape_keyword(w) && w != "intersection" && w != "difference" && w != "merge") {
        warn_unsupported(kw, w);
        skip_block(kw);
        return {};
    }
    expect("{");
    ObjectValue ov;
    const SourceLoc loc = make_diagnostic(Severity::Note, kw, "").loc;
    auto add_shape = [&](Shape shape) {
        count_objects(kw, 1);
        ObjectPart part;
        part.object.shape = std::move(shape);
        part.object.loc = loc;
        ov.parts.push_back(std::move(part));
    };
    const Value* copied = nullptr;
    if (w == "mesh" || w == "mesh2") {
        // POV-Ray compat: `mesh { Declared_Mesh modifiers }` copies the declared mesh (the mesh-camera examples
        // place one mesh several times this way).
        const Token& first = peek();
        const Value* v = first.kind == TokenKind::Identifier ? lookup(first.text) : nullptr;
        const auto* declared = v ? std::get_if<Boxed<ObjectValue>>(v) : nullptr;
        if (declared && (*declared)->parts.size() == 1 && (*declared)->lights.empty() &&
            std::holds_alternative<Mesh>((*declared)->parts.front().object.shape))
            copied = v;
    }
    if (copied != nullptr) {
        next();
        copy_declared(ov, *std::get<Boxed<ObjectValue>>(*copied));
        fresh_interior_ids(ov);
    } else if (is_shape_keyword(w)) {
        add_shape(parse_shape_parameters(kw));
        // POV-Ray compat: a tiny rotation "to fix cracks in text that lies along an axis".
        if (w == "text") ov.parts.back().object.transform = Transform::rotation({0.001, 0.001, 0.001});
    } else if (w == "object") {
        expand_macros();
        std::optional<Value> element;
        const Token at = peek();
        if ((element = take_array_element())) {
            if (const auto* o = std::get_if<Boxed<ObjectValue>>(&*element)) {
                copy_declared(ov, **o);
                fresh_interior_ids(ov);
            }
            else if (!std::holds_alternative<Unsupported>(*element)) fail(at, "this array element is not an object");
            parse_object_modifiers(ov, ov.compound);
            return ov;
        }
        const Token id = next();
        if (is_object_keyword(id)) {
            // Through the heap: a temporary here would double this frame, which deep nesting repeats.
            const std::unique_ptr<ObjectValue> inner(new ObjectValue(parse_object(id)));
            ov = std::move(*inner);
        } else if (is_word(id, "light_source")) {
            Light light = parse_light_body(id, &ov);
            ov.lights.push_back(std::move(light));
        } else if (id.kind == TokenKind::Identifier) {
            const Value* v = lookup(id.text);
            if (v == nullptr) fail_undeclared(id);
            if (std::holds_alternative<Unsupported>(*v)) {
                // Already warned about where it was declared; the object is left out.
            } else if (const auto* o = std::get_if<Boxed<ObjectValue>>(v)) {
                copy_declared(ov, **o);
                fresh_interior_ids(ov);
            } else {
                fail(id, "expected an object identifier but '" + id.text + "' is not an object");
            }
        } else {
            fail(id, "expected an object identifier but found '" + id.text + "'");
        }
    } else if (w == "intersection" || w == "difference" || w == "merge") {
        // A real CSG node: each child statement becomes one child object (a union node when it has several parts).
        Csg csg;
        csg.op = w == "intersection" ? Csg::Op::Intersection : w == "difference" ? Csg::Op::Difference : Csg::Op::Merge;
        read_csg_children(ov, [&](ObjectValue& child) {
            own_parts(child, kw);
            ov.copied += child.copied;
            auto o = as_single_object(child);
            if (!o) return;
            // A same-op child adding nothing of its own joins this node at any depth, A B C D for `intersection { A
            // intersection { B C } D }` (no deep tree); a difference only as its first child (not A - (B - C)).
            if ((csg.children.empty() || csg.op != Csg::Op::Difference) && splices_into(*o, csg.op)) {
                auto& inner = std::get<Csg>(o->shape).children;
                if (csg.children.empty()) std::swap(csg.children, inner);
                csg.children.insert(csg.children.end(), std::make_move_iterator(inner.begin()),
                                    std::make_move_iterator(inner.end()));
                return;
            }
            csg.children.push_back(std::move(*o));
        });
        add_shape(std::move(csg));
    } else {
        // union: children first, then the union's own modifiers.
        ov.compound = true;
        read_csg_children(ov, [&](ObjectValue& child) {
            ov.copied += child.copied;
            if (child.texture) {  // one value the untextured parts share, not a 3 KB copy each
                const scene::Cow<Texture> shared(*child.texture);
                for (ObjectPart& part : child.parts)
                    if (!part.has_texture) part.object.texture = shared, part.has_texture = true;
            }
            // The parts move as one block: a union redeclared around its previous value (`#declare U = union {
            // object { U } ... }`, many times over) then shares U's parts, where POV-Ray copies them.
            if (!ov.parts.empty()) own_parts(child, kw);  // two shared chains cannot be joined without a copy
            ov.parts.append(std::move(child.parts));
        });
    }
    parse_object_modifiers(ov, ov.compound);
    return ov;
}

void ObjectReader::read_csg_children(ObjectValue& ov, const std::function<void(ObjectValue& child)>& take_child) {
    while (true) {
        expand_macros();
        const Token& t = peek();
        if (is_object_start(t)) {
            const Token child_kw = next();
            // On the heap, built there in place: an ObjectValue is over 3 KB (its optional texture), and this frame
            // is on the stack once per level of `union { union { ... } }`.
            const std::unique_ptr<ObjectValue> child(new ObjectValue(parse_object(child_kw)));
            take_child(*child);
            for (Light& l : child->lights) ov.lights.push_back(std::move(l));
        } else if (is_word(t, "light_source")) {
            const Token lkw = next();
            const auto looks = std::make_unique<ObjectValue>();
            ov.lights.push_back(parse_light_body(lkw, looks.get()));
            if (!looks->parts.empty()) take_child(*looks);
        } else {
            return;
        }
    }
}

Texture& ObjectReader::texture_to_modify(ObjectValue& ov) {
    if (ov.compound || ov.parts.size() != 1) {
        if (!ov.texture) ov.texture = default_texture();
        return *ov.texture;
    }
    ObjectPart& part = ov.parts.front();
    if (!part.has_texture) {
        part.object.texture = default_texture();
        part.has_texture = true;
    }
    return *part.object.texture;
}

void ObjectReader::apply_transform(ObjectValue& ov, const Transform& tr) {
    TextureMover mover(tr);
    for (ObjectPart& part : ov.parts) {
        part.object.transform = part.object.transform.then(tr);
        transform_textures(part.object, part.has_texture, mover);
        place_patches(part.object, tr);
        // POV-Ray compat (Transform_Interior): the interiors' media move with the object.
        transform_interiors(part.object, tr);
    }
    if (ov.texture) transform_texture(*ov.texture, tr);
    for (Light& l : ov.lights) transform_light(l, tr);
}

void ObjectReader::parse_object_modifiers(ObjectValue& ov, bool compound) {
    ModifierState state;
    while (true) {
        expand_macros();
        const Token t = peek();
        Transform tr;
        if (parse_transform_item(t, tr)) {
            own_parts(ov, t);
            apply_transform(ov, tr);
            continue;
        }
        next();
        if (is_punct(t, "}")) return;
        own_parts(ov, t);
        if (t.kind != TokenKind::Identifier) fail(t, "expected an object modifier or '}' but found '" + t.text + "'");
        const TokenText& w = t.text;
        using Modifier = void (*)(ObjectReader&, ObjectValue&, const Token&, ModifierState&);
        static const KeywordTable<Modifier> modifiers = {
            {"pigment",
             [](ObjectReader& r, ObjectValue& ov, const Token& kw, ModifierState&) {
                 Texture& top = top_layer(r.texture_to_modify(ov));
                 top.pigment = r.parse_pigment_body(kw, &top.pigment);
             }},
            {"finish",
             [](ObjectReader& r, ObjectValue& ov, const Token& kw, ModifierState&) {
                 Texture& top = top_layer(r.texture_to_modify(ov));
                 top.finish = r.parse_finish_body(kw, &top.finish);
             }},
            {"texture",
             [](ObjectReader& r, ObjectValue& ov, const Token& kw, ModifierState& state) {
                 r.add_texture(ov, r.parse_texture_body(kw), kw, state);
             }},
            {"no_shadow",
             [](ObjectReader&, ObjectValue& ov, const Token&, ModifierState&) { set_flag(ov, &Object::no_shadow); }},
            {"no_image",
             [](ObjectReader&, ObjectValue& ov, const Token&, ModifierState&) { set_flag(ov, &Object::no_image); }},
            {"no_reflection",
             [](ObjectReader&, ObjectValue& ov, const Token&, ModifierState&) {
                 set_flag(ov, &Object::no_reflection);
             }},
            {"no_radiosity",
             [](ObjectReader&, ObjectValue& ov, const Token&, ModifierState&) { set_flag(ov, &Object::no_radiosity); }},
            {"inverse",
             [](ObjectReader& r, ObjectValue& ov, const Token&, ModifierState&) {
                 r.make_union_node(ov);
                 for (ObjectPart& part : ov.parts) part.object.inverse = !part.object.inverse;
             }},
            {"clipped_by",
             [](ObjectReader& r, ObjectValue& ov, const Token& kw, ModifierState& state) {
                 const std::vector<Object> clips = r.parse_object_list(kw, &state.bounded_by);
                 r.make_union_node(ov);
                 // Clipping objects are given in world space; store them relative to the object so later
                 // transforms move both together.
                 for (ObjectPart& part : ov.parts) {
                     const Transform to_local = part.object.transform.inverse();
                     for (Object clip : clips) {
                         clip.transform = clip.transform.then(to_local);
                         part.object.clipped_by.push_back(std::move(clip));
                     }
                 }
             }},
            // POV-Ray compat: the object is tested only on rays that meet its bounds, so a bound smaller than the
            // object cuts it (SceneReader::place_object drops the bounds POV-Ray drops). Stored relative to each
            // part, as clips are: for a union the test is the same on every part.
            {"bounded_by",
             [](ObjectReader& r, ObjectValue& ov, const Token& kw, ModifierState& state) {
                 state.bounded_by = r.parse_object_list(kw, nullptr);
                 for (ObjectPart& part : ov.parts) {
                     const Transform to_local = part.object.transform.inverse();
                     for (Object bound : state.bounded_by) {
                         bound.transform = bound.transform.then(to_local);
                         part.object.bounded_by.push_back(std::move(bound));
                     }
                 }
             }},
            {"open",
             [](ObjectReader&, ObjectValue& ov, const Token&, ModifierState&) {
                 for (ObjectPart& part : ov.parts) {
                     if (auto* c = std::get_if<Cylinder>(&part.object.shape)) c->open = true;
                     if (auto* c = std::get_if<Cone>(&part.object.shape)) c->open = true;
                     if (auto* c = std::get_if<Prism>(&part.object.shape)) c->open = true;
                     if (auto* c = std::get_if<Sor>(&part.object.shape)) c->open = true;
                 }
             }},
            // POV-Ray compat: `hollow` on a CSG (a union's parts here) sets it on the children that did not say it
            // themselves, down the tree.
            {"hollow",
             [](ObjectReader& r, ObjectValue& ov, const Token&, ModifierState&) {
                 const bool hollow = r.parse_bool_optional();
                 const bool single = !ov.compound && ov.parts.size() == 1;
                 for (ObjectPart& part : ov.parts) {
                     if (!single && part.object.hollow_set) continue;
                     part.object.interior.hollow = hollow;
                     part.object.hollow_set = part.object.hollow_set || single;
                     set_children_hollow(part.object, hollow);
                 }
             }},
            {"sturm", &read_sturm},
            // POV-Ray compat: an acceleration hint of height fields, blobs and meshes; the picture is the same.
            {"hierarchy",
             [](ObjectReader& r, ObjectValue&, const Token&, ModifierState&) { r.parse_bool_optional(); }},
            {"split_union",
             [](ObjectReader& r, ObjectValue&, const Token&, ModifierState&) { r.parse_bool_optional(); }},
            {"cutaway_textures", [](ObjectReader&, ObjectValue&, const Token&, ModifierState&) {}},
            {"double_illuminate", &read_double_illuminate},
            {"radiosity",
             [](ObjectReader& r, ObjectValue&, const Token& kw, ModifierState&) {
                 r.warn_unsupported(kw, "object radiosity importance");
                 r.skip_block(kw);
             }},
            {"normal",
             [](ObjectReader& r, ObjectValue& ov, const Token& kw, ModifierState&) {
                 Texture& top = top_layer(r.texture_to_modify(ov));
                 top.normal = r.parse_normal_body(kw, &top.normal);
             }},
            {"interior",
             [](ObjectReader& r, ObjectValue& ov, const Token& kw, ModifierState&) {
                 r.set_interior(ov, r.parse_interior_body(kw, r.own_interior(ov)));
             }},
            {"interior_texture", &read_interior_texture},
            {"material", &read_material_modifier},
            {"photons", &read_object_photons},
            {"uv_mapping",
             [](ObjectReader&, ObjectValue& ov, const Token&, ModifierState&) {
                 for (ObjectPart& part : ov.parts) part.object.uv_mapping = true;
             }},
        };
        if (const Modifier* modifier = modifiers.find(w)) {
            (*modifier)(*this, ov, t, state);
        } else if (is_object_keyword(t) && compound) {
            fail(t, "objects of a union must come before its modifiers");
        } else {
            if (!is_keyword(w) && lookup(w) == nullptr) fail_undeclared(t);
            fail(t, "expected an object modifier or '}' but found '" + w + "'");
        }
    }
}

Interior ObjectReader::own_interior(const ObjectValue& ov) const {
    if (!ov.compound && ov.parts.size() == 1) return ov.parts.front().object.interior;
    for (const ObjectPart& part : ov.parts)
        if (ov.interior_id != 0 && part.object.interior_id == ov.interior_id) return part.object.interior;
    return {};
}

void ObjectReader::set_interior(ObjectValue& ov, const Interior& in) {
    if (!ov.compound && ov.parts.size() == 1) {
        Object& o = ov.parts.front().object;
        replace_interior(o, in, o.interior_id != 0 ? o.interior_id : ++m_interior_ids);
        return;
    }
    // POV-Ray compat (Post_Process): a union's interior goes to the children that have none of their own, and
    // they share it.
    if (ov.interior_id == 0) ov.interior_id = ++m_interior_ids;
    for (ObjectPart& part : ov.parts)
        if (part.object.interior_id == 0 || part.object.interior_id == ov.interior_id)
            replace_interior(part.object, in, ov.interior_id);
}

void ObjectReader::fresh_interior_ids(ObjectValue& ov) {
    // Shared parts without interiors keep being shared: nothing here to renumber.
    if (ov.interior_id == 0 && !ov.parts.any_interior_id()) return;
    std::map<std::uint32_t, std::uint32_t> ids;
    auto fresh = [&](std::uint32_t& id) {
        if (id == 0) return;
        auto [it, added] = ids.try_emplace(id, 0);
        if (added) it->second = ++m_interior_ids;
        id = it->second;
    };
    fresh(ov.interior_id);
    std::vector<Object*> pending;
    for (ObjectPart& part : ov.parts) pending.push_back(&part.object);
    while (!pending.empty()) {
        Object* o = pending.back();
        pending.pop_back();
        fresh(o->interior_id);
        if (auto* csg = std::get_if<Csg>(&o->shape))
            for (Object& child : csg->children) pending.push_back(&child);
    }
}

Light ObjectReader::parse_light_body(const Token& kw, ObjectValue* looks) {
    expect("{");
    Light light;
    light.loc = make_diagnostic(Severity::Note, kw, "").loc;
    expand_macros();
    const Token& first = peek();
    const Value* ident = first.kind == TokenKind::Identifier ? lookup(first.text) : nullptr;
    const auto* boxed = ident ? std::get_if<Boxed<ObjectValue>>(ident) : nullptr;
    const ObjectValue* ov = boxed ? &**boxed : nullptr;
    if (ov != nullptr && ov->lights.size() == 1 && (ov->parts.empty() || looks != nullptr)) {
        next();
        light = ov->lights.front();
        // A declared light brings its looks_like object.
        for (const ObjectPart& part : ov->parts) looks->parts.push_back(part);
    } else {
        light.position = parse_vector();
        accept(",");
        if (!is_punct(peek(), "}")) light.color = parse_color();
    }
    while (true) {
        expand_macros();
        const Token t = peek();
        Transform tr;
        if (parse_transform_item(t, tr)) {
            transform_light(light, tr);
            if (looks != nullptr) apply_transform(*looks, tr);
            continue;
        }
        if (is_color_keyword(t)) {
            light.color = parse_color();
            continue;
        }
        next();
        if (is_punct(t, "}")) {
            if (!light.projected_through.empty() && light.area)
                warn(kw, "projected_through on an area light is approximated: the light's centre decides which "
                         "points it reaches");
            return light;
        }
        const TokenText& w = t.text;
        if (t.kind != TokenKind::Identifier) fail(t, "expected a light_source item but found '" + w + "'");
        if (w == "looks_like") {
            read_looks_like(light, looks, t);
            continue;
        }
        using Item = void (*)(ObjectReader&, Light&, const Token&);
        static const KeywordTable<Item> items = {
            // POV-Ray compat: `spotlight` and `cylinder` reset radius, falloff and tightness to their own
            // defaults (degrees for a spotlight, distances from the axis for a cylinder light).
            {"spotlight",
             [](ObjectReader&, Light& l, const Token&) {
                 l.type = Light::Type::Spot;
                 l.radius = 30.0;
                 l.falloff = 45.0;
                 l.tightness = 0.0;
             }},
            {"cylinder",
             [](ObjectReader&, Light& l, const Token&) {
                 l.type = Light::Type::Cylinder;
                 l.radius = 0.75;
                 l.falloff = 1.0;
                 l.tightness = 0.0;
             }},
            {"parallel", [](ObjectReader&, Light& l, const Token&) { l.type = Light::Type::Parallel; }},
            {"point_at", [](ObjectReader& r, Light& l, const Token&) { l.point_at = r.parse_vector(); }},
            {"radius", [](ObjectReader& r, Light& l, const Token&) { l.radius = r.parse_float(); }},
            {"falloff", [](ObjectReader& r, Light& l, const Token&) { l.falloff = r.parse_float(); }},
            {"tightness", [](ObjectReader& r, Light& l, const Token&) { l.tightness = r.parse_float(); }},
            {"fade_distance", [](ObjectReader& r, Light& l, const Token&) { l.fade_distance = r.parse_float(); }},
            {"fade_power", [](ObjectReader& r, Light& l, const Token&) { l.fade_power = r.parse_float(); }},
            {"shadowless", [](ObjectReader&, Light& l, const Token&) { l.shadowless = true; }},
            {"area_light", [](ObjectReader& r, Light& l, const Token&) { r.parse_area_light(l); }},
            {"adaptive",
             [](ObjectReader& r, Light& l, const Token&) {
                 l.adaptive = std::max(0, static_cast<int>(std::min(r.parse_float(), 100.0)));
             }},
            {"jitter", [](ObjectReader&, Light& l, const Token&) { l.jitter = true; }},
            {"circular", [](ObjectReader&, Light& l, const Token&) { l.circular = true; }},
            {"orient", [](ObjectReader&, Light& l, const Token&) { l.orient = true; }},
            {"area_illumination",
             [](ObjectReader& r, Light&, const Token& kw) {
                 if (r.parse_bool_optional()) r.warn_unsupported(kw, "area_illumination");
             }},
            {"media_interaction",
             [](ObjectReader& r, Light& l, const Token&) { l.media_interaction = r.parse_bool_optional(); }},
            {"media_attenuation",
             [](ObjectReader& r, Light& l, const Token&) { l.media_attenuation = r.parse_bool_optional(); }},
            {"projected_through",
             [](ObjectReader& r, Light& l, const Token& kw) { r.read_projected_through(l, kw); }},
            {"photons", &read_light_photons},
        };
        if (const Item* item = items.find(w)) {
            (*item)(*this, light, t);
        } else {
            if (!is_keyword(w) && lookup(w) == nullptr) fail_undeclared(t);
            fail(t, "expected a light_source item but found '" + w + "'");
        }
    }
}

}  // namespace wardray::parser
