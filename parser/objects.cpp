// Objects: object statements (union flattening, CSG nodes), their modifiers, transforms and light sources.
#include <algorithm>
#include <cmath>

#include "parser/keywords.h"
#include "parser/parser.h"

namespace wardray::parser {

bool is_object_keyword(const Token& t) {
    if (t.kind != TokenKind::Identifier) return false;
    const TokenText& w = t.text;
    return is_shape_keyword(w) || w == "object" || w == "union" || w == "intersection" || w == "difference" ||
           w == "merge" || is_unsupported_object(w);
}

namespace {

// POV-Ray compat: a transform moves the textures given before it (Transform_Textures), down a CSG tree.
void transform_textures(Object& o, bool own_texture, const Transform& tr) {
    if (own_texture) transform_texture(o.texture, tr);
    if (auto* csg = std::get_if<Csg>(&o.shape))
        for (Object& child : csg->children) transform_textures(child, child.has_texture, tr);
}

}  // namespace

ObjectValue ObjectReader::parse_object(const Token& kw) {
    const NestingGuard guard(*this, kw);
    const TokenText& w = kw.text;
    if (is_unsupported_object(w) && !is_shape_keyword(w) && w != "intersection" && w != "difference" && w != "merge") {
        warn_unsupported(kw, w);
        skip_block(kw);
        return {};
    }
    expect("{");
    ObjectValue ov;
    const SourceLoc loc = make_diagnostic(Severity::Note, kw, "").loc;
    auto add_shape = [&](Shape shape) {
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
        ov = *std::get<Boxed<ObjectValue>>(*copied);
    } else if (is_shape_keyword(w)) {
        add_shape(parse_shape_parameters(kw));
        // POV-Ray compat: a tiny rotation "to fix cracks in text that lies along an axis".
        if (w == "text") ov.parts.back().object.transform = Transform::rotation({0.001, 0.001, 0.001});
    } else if (w == "object") {
        expand_macros();
        std::optional<Value> element;
        const Token at = peek();
        if ((element = take_array_element())) {
            if (const auto* o = std::get_if<Boxed<ObjectValue>>(&*element)) ov = **o;
            else if (!std::holds_alternative<Unsupported>(*element)) fail(at, "this array element is not an object");
            parse_object_modifiers(ov, ov.compound);
            return ov;
        }
        const Token id = next();
        if (is_object_keyword(id)) {
            ov = parse_object(id);
        } else if (is_word(id, "light_source")) {
            ov.lights.push_back(parse_light_body(id));
        } else if (id.kind == TokenKind::Identifier) {
            const Value* v = lookup(id.text);
            if (v == nullptr) fail_undeclared(id);
            if (std::holds_alternative<Unsupported>(*v)) {
                // Already warned about where it was declared; the object is left out.
            } else if (const auto* o = std::get_if<Boxed<ObjectValue>>(v)) {
                ov = **o;
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
        while (true) {
            expand_macros();
            const Token& t = peek();
            if (is_object_keyword(t)) {
                const Token child_kw = next();
                ObjectValue child = parse_object(child_kw);
                if (auto o = as_single_object(child)) csg.children.push_back(std::move(*o));
                for (Light& l : child.lights) ov.lights.push_back(std::move(l));
            } else if (is_word(t, "light_source")) {
                const Token lkw = next();
                ov.lights.push_back(parse_light_body(lkw));
            } else {
                break;
            }
        }
        add_shape(std::move(csg));
    } else {
        // union: children first, then the union's own modifiers.
        ov.compound = true;
        while (true) {
            expand_macros();
            const Token& t = peek();
            if (is_object_keyword(t)) {
                const Token child_kw = next();
                ObjectValue child = parse_object(child_kw);
                for (ObjectPart& part : child.parts) {
                    if (!part.has_texture && child.texture) {
                        part.object.texture = *child.texture;
                        part.has_texture = true;
                    }
                    ov.parts.push_back(std::move(part));
                }
                for (Light& l : child.lights) ov.lights.push_back(std::move(l));
            } else if (is_word(t, "light_source")) {
                const Token lkw = next();
                ov.lights.push_back(parse_light_body(lkw));
            } else {
                break;
            }
        }
    }
    parse_object_modifiers(ov, ov.compound);
    return ov;
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
    return part.object.texture;
}

void ObjectReader::apply_transform(ObjectValue& ov, const Transform& tr) {
    for (ObjectPart& part : ov.parts) {
        part.object.transform = part.object.transform.then(tr);
        transform_textures(part.object, part.has_texture, tr);
    }
    if (ov.texture) transform_texture(*ov.texture, tr);
    for (Light& l : ov.lights) {
        l.position = tr.point(l.position);
        l.point_at = tr.point(l.point_at);
    }
}

void ObjectReader::parse_object_modifiers(ObjectValue& ov, bool compound) {
    bool textured = false;
    std::vector<Object> bounded_by;
    while (true) {
        expand_macros();
        const Token t = peek();
        Transform tr;
        if (parse_transform_item(t, tr)) {
            apply_transform(ov, tr);
            continue;
        }
        next();
        if (is_punct(t, "}")) return;
        if (t.kind != TokenKind::Identifier) fail(t, "expected an object modifier or '}' but found '" + t.text + "'");
        const TokenText& w = t.text;
        if (w == "pigment") {
            texture_to_modify(ov).pigment = parse_pigment_body(t);
        } else if (w == "finish") {
            texture_to_modify(ov).finish = parse_finish_body(t);
        } else if (w == "texture") {
            if (textured) {
                // POV-Ray compat: further texture statements are layers on top of the first.
                texture_to_modify(ov).layers.push_back(parse_texture_body(t));
            } else {
                texture_to_modify(ov) = parse_texture_body(t);
                textured = true;
            }
        } else if (w == "no_shadow" || w == "no_image" || w == "no_reflection" || w == "no_radiosity") {
            for (ObjectPart& part : ov.parts) {
                Object& o = part.object;
                (w == "no_shadow" ? o.no_shadow : w == "no_image" ? o.no_image
                                                : w == "no_reflection" ? o.no_reflection : o.no_radiosity) = true;
            }
        } else if (w == "inverse") {
            make_union_node(ov);
            for (ObjectPart& part : ov.parts) part.object.inverse = !part.object.inverse;
        } else if (w == "clipped_by") {
            const std::vector<Object> clips = parse_object_list(t, &bounded_by);
            make_union_node(ov);
            // Clipping objects are given in world space; store them relative to the object so later transforms
            // move both together.
            for (ObjectPart& part : ov.parts) {
                const Transform to_local = part.object.transform.inverse();
                for (Object clip : clips) {
                    clip.transform = clip.transform.then(to_local);
                    part.object.clipped_by.push_back(std::move(clip));
                }
            }
        } else if (w == "bounded_by") {
            // Bounds are accepted and not needed for correctness: the renderer builds its own.
            bounded_by = parse_object_list(t, nullptr);
        } else if (w == "open") {
            for (ObjectPart& part : ov.parts) {
                if (auto* c = std::get_if<Cylinder>(&part.object.shape)) c->open = true;
                if (auto* c = std::get_if<Cone>(&part.object.shape)) c->open = true;
                if (auto* c = std::get_if<Prism>(&part.object.shape)) c->open = true;
                if (auto* c = std::get_if<Sor>(&part.object.shape)) c->open = true;
            }
        } else if (w == "hollow") {
            parse_bool_optional();
        } else if (w == "sturm" || w == "split_union" || w == "cutaway_textures") {
            if (w == "split_union") parse_bool_optional();
        } else if (w == "double_illuminate") {
            warn_unsupported(t, w);
        } else if (w == "radiosity") {
            warn_unsupported(t, "object radiosity importance");
            skip_block(t);
        } else if (w == "normal") {
            texture_to_modify(ov).normal = parse_normal_body(t);
        } else if (w == "interior") {
            const Interior interior = parse_interior_body(t);
            for (ObjectPart& part : ov.parts) part.object.interior = interior;
        } else if (w == "interior_texture" || w == "material" ||
                   w == "photons") {
            warn_unsupported(t, w);
            skip_block(t);
        } else if (w == "uv_mapping") {
            warn_unsupported(t, w);
        } else if (is_object_keyword(t) && compound) {
            fail(t, "objects of a union must come before its modifiers");
        } else {
            if (!is_keyword(w) && lookup(w) == nullptr) fail_undeclared(t);
            fail(t, "expected an object modifier or '}' but found '" + w + "'");
        }
    }
}

Light ObjectReader::parse_light_body(const Token& kw) {
    expect("{");
    Light light;
    light.loc = make_diagnostic(Severity::Note, kw, "").loc;
    expand_macros();
    const Token& first = peek();
    const Value* ident = first.kind == TokenKind::Identifier ? lookup(first.text) : nullptr;
    const auto* boxed = ident ? std::get_if<Boxed<ObjectValue>>(ident) : nullptr;
    const ObjectValue* ov = boxed ? &**boxed : nullptr;
    if (ov != nullptr && ov->lights.size() == 1 && ov->parts.empty()) {
        next();
        light = ov->lights.front();
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
            light.position = tr.point(light.position);
            light.point_at = tr.point(light.point_at);
            light.area_axis1 = tr.vector(light.area_axis1);
            light.area_axis2 = tr.vector(light.area_axis2);
            continue;
        }
        if (is_color_keyword(t)) {
            light.color = parse_color();
            continue;
        }
        next();
        if (is_punct(t, "}")) return light;
        const TokenText& w = t.text;
        if (t.kind != TokenKind::Identifier) fail(t, "expected a light_source item but found '" + w + "'");
        // POV-Ray compat: `spotlight` and `cylinder` reset radius, falloff and tightness to their own defaults
        // (degrees for a spotlight, distances from the axis for a cylinder light).
        if (w == "spotlight") {
            light.type = Light::Type::Spot;
            light.radius = 30.0;
            light.falloff = 45.0;
            light.tightness = 0.0;
        } else if (w == "cylinder") {
            light.type = Light::Type::Cylinder;
            light.radius = 0.75;
            light.falloff = 1.0;
            light.tightness = 0.0;
        }
        else if (w == "parallel") light.type = Light::Type::Parallel;
        else if (w == "point_at") light.point_at = parse_vector();
        else if (w == "radius") light.radius = parse_float();
        else if (w == "falloff") light.falloff = parse_float();
        else if (w == "tightness") light.tightness = parse_float();
        else if (w == "fade_distance") light.fade_distance = parse_float();
        else if (w == "fade_power") light.fade_power = parse_float();
        else if (w == "shadowless") light.shadowless = true;
        else if (w == "area_light") {
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
        } else if (w == "adaptive") {
            light.adaptive = std::max(0, static_cast<int>(std::min(parse_float(), 100.0)));
        } else if (w == "jitter") {
            light.jitter = true;
        } else if (w == "circular") {
            light.circular = true;
        } else if (w == "orient") {
            light.orient = true;
        } else if (w == "area_illumination") {
            if (parse_bool_optional()) warn_unsupported(t, "area_illumination");
        } else if (w == "media_interaction" || w == "media_attenuation") {
            parse_bool_optional();
        } else if (w == "looks_like" || w == "projected_through" || w == "photons") {
            warn_unsupported(t, w);
            skip_block(t);
        } else {
            if (!is_keyword(w) && lookup(w) == nullptr) fail_undeclared(t);
            fail(t, "expected a light_source item but found '" + w + "'");
        }
    }
}

}  // namespace wardray::parser
