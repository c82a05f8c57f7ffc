// Scene statements: objects (union flattening, CSG nodes), transforms, lights, camera, global settings, background.
#include <algorithm>
#include <cmath>

#include "parser/keywords.h"
#include "parser/parser.h"

namespace wardray::parser {

void Parser::parse_statement() {
    const Token t = next();
    if (t.kind != TokenKind::Identifier) {
        fail(t, t.kind == TokenKind::EndOfFile ? "unexpected end of file"
                                               : "expected a statement but found '" + t.text + "'");
    }
    const TokenText& w = t.text;
    if (const auto m = m_macros.find(w); m != m_macros.end()) {
        invoke_macro(t, m->second);
        return;
    }
    if (w == "camera") {
        const CameraSpec spec = parse_camera_body(t);
        std::string error;
        std::string warning;
        Camera cam = resolve_camera(spec, error, warning);
        if (!warning.empty()) warn(t, warning);
        if (!error.empty()) fail(t, error);
        m_scene.camera = cam;
    } else if (w == "light_source") {
        m_scene.lights.push_back(parse_light_body(t));
    } else if (is_object_keyword(t)) {
        place_object(parse_object(t));
    } else if (w == "default") {
        // POV-Ray compat: the old `default { ... }` statement is #default.
        directive_default(t);
    } else if (w == "global_settings") {
        parse_global_settings(t);
    } else if (w == "background") {
        expect("{");
        m_scene.background = parse_color();
        expect("}");
    } else if (w == "sky_sphere") {
        m_scene.sky_sphere = parse_sky_sphere(t);
    } else if (w == "fog") {
        m_scene.fogs.push_back(parse_fog(t));
    } else if (is_unsupported_block(w)) {
        warn_unsupported(t, w);
        skip_block(t);
    } else if (lookup(w) != nullptr) {
        fail(t, "'" + w + "' cannot stand alone here; use object { " + w + " } for declared objects");
    } else if (is_keyword(w)) {
        fail(t, "'" + w + "' cannot start a statement");
    } else {
        fail_undeclared(t);
    }
}

bool Parser::is_object_keyword(const Token& t) const {
    if (t.kind != TokenKind::Identifier) return false;
    const TokenText& w = t.text;
    return is_shape_keyword(w) || w == "object" || w == "union" || w == "intersection" || w == "difference" ||
           w == "merge" || is_unsupported_object(w);
}

namespace {

// POV-Ray compat: CSG children without a texture of their own take their parent's, down the tree.
void inherit_textures(Object& o) {
    auto* csg = std::get_if<Csg>(&o.shape);
    if (csg == nullptr) return;
    for (Object& child : csg->children) {
        if (!child.has_texture) child.texture = o.texture;
        inherit_textures(child);
    }
}

// POV-Ray compat: a transform moves the textures given before it (Transform_Textures), down a CSG tree.
void transform_textures(Object& o, bool own_texture, const Transform& tr) {
    if (own_texture) transform_texture(o.texture, tr);
    if (auto* csg = std::get_if<Csg>(&o.shape))
        for (Object& child : csg->children) transform_textures(child, child.has_texture, tr);
}

}  // namespace

void Parser::place_object(ObjectValue ov) {
    for (ObjectPart& part : ov.parts) {
        // POV-Ray compat (Link_To_Frame, remove_bounds on): a top-level object that is cheap to intersect loses
        // its bounds; CSG, polynomials, text and quadrics keep them.
        const Shape& shape = part.object.shape;
        if (!ov.compound && !std::holds_alternative<Csg>(shape) && !std::holds_alternative<Quartic>(shape) &&
            !std::holds_alternative<Text>(shape) && !std::holds_alternative<Quadric>(shape))
            part.object.bounded_by.clear();
        if (!part.has_texture) part.object.texture = ov.texture.value_or(default_texture());
        inherit_textures(part.object);
        m_scene.objects.push_back(std::move(part.object));
    }
    for (Light& l : ov.lights) m_scene.lights.push_back(std::move(l));
}

ObjectValue Parser::parse_object(const Token& kw) {
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

Texture& Parser::texture_to_modify(ObjectValue& ov) {
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

void Parser::apply_transform(ObjectValue& ov, const Transform& tr) {
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

void Parser::parse_object_modifiers(ObjectValue& ov, bool compound) {
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
            // POV-Ray compat: the object is tested only on rays that meet its bounds, so a bound smaller than the
            // object cuts it (see place_object for the top-level objects whose bounds POV-Ray drops). Stored
            // relative to each part, as clips are: for a union the test is the same on every part.
            bounded_by = parse_object_list(t, nullptr);
            for (ObjectPart& part : ov.parts) {
                const Transform to_local = part.object.transform.inverse();
                for (Object bound : bounded_by) {
                    bound.transform = bound.transform.then(to_local);
                    part.object.bounded_by.push_back(std::move(bound));
                }
            }
        } else if (w == "open") {
            for (ObjectPart& part : ov.parts) {
                if (auto* c = std::get_if<Cylinder>(&part.object.shape)) c->open = true;
                if (auto* c = std::get_if<Cone>(&part.object.shape)) c->open = true;
                if (auto* c = std::get_if<Prism>(&part.object.shape)) c->open = true;
                if (auto* c = std::get_if<Sor>(&part.object.shape)) c->open = true;
            }
        } else if (w == "hollow") {
            // POV-Ray compat: `hollow` on a CSG sets it on the children too; the interior rays see is the
            // top-level object's here, so setting it on every part is the same.
            const bool hollow = parse_bool_optional();
            for (ObjectPart& part : ov.parts) part.object.interior.hollow = hollow;
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

bool Parser::parse_transform_item(const Token& t, Transform& out) {
    if (t.kind != TokenKind::Identifier) return false;
    const TokenText& w = t.text;
    if (w == "translate") {
        next();
        out = out.then(Transform::translation(parse_vector()));
    } else if (w == "rotate") {
        next();
        out = out.then(Transform::rotation(parse_vector()));
    } else if (w == "scale") {
        next();
        Vec3 s = parse_vector();
        for (int i = 0; i < 3; ++i) {
            if (s[i] == 0.0) {
                // POV-Ray compat: a zero scale component is changed to 1 with a warning.
                warn(t, "scale by 0 changed to 1");
                s[i] = 1.0;
            }
        }
        out = out.then(Transform::scaling(s));
    } else if (w == "matrix") {
        next();
        expect("<");
        std::array<double, 12> m{};
        for (int i = 0; i < 12; ++i) {
            if (i > 0) expect(",");
            const Token at = peek();
            const Numeric c = parse_additive();
            if (c.n != 1) fail(at, "matrix entries must be floats");
            m[i] = c.v[0];
        }
        expect(">");
        for (int col = 0; col < 3; ++col) {
            if (m[col] != 0.0 || m[3 + col] != 0.0 || m[6 + col] != 0.0) continue;
            // POV-Ray compat: a zero column scales by 0; like `scale 0`, it becomes 1 with a warning.
            warn(t, "matrix column " + std::to_string(col + 1) + " is zero (a scale by 0); changed to 1");
            m[4 * col] = 1.0;
        }
        const auto tr = Transform::from_pov_matrix(m);
        // POV-Ray compat: POV-Ray stops with "Singular matrix" here too; it cannot place the object.
        if (!tr || !tr->is_invertible()) fail(t, "matrix is singular: it flattens space, so the object has no inverse");
        out = out.then(*tr);
    } else if (w == "transform") {
        next();
        if (is_punct(peek(), "{")) {
            out = out.then(parse_transform_body(t));
        } else {
            const Token id = expect_identifier();
            const Value* v = lookup(id.text);
            if (v == nullptr) fail_undeclared(id);
            const auto* tv = std::get_if<Boxed<Transform>>(v);
            if (tv == nullptr) fail(id, "'" + id.text + "' is not a transform");
            out = out.then(**tv);
        }
    } else {
        return false;
    }
    return true;
}

Transform Parser::parse_transform_body(const Token& kw) {
    expect("{");
    Transform result;
    while (true) {
        expand_macros();  // transforms.inc's macros stand where a transform item is expected
        const Token t = peek();
        if (parse_transform_item(t, result)) continue;
        next();
        if (is_punct(t, "}")) return result;
        if (is_word(t, "inverse")) {
            result = result.inverse();
        } else if (t.kind == TokenKind::Identifier && lookup(t.text) &&
                   std::holds_alternative<Boxed<Transform>>(*lookup(t.text))) {
            result = result.then(*std::get<Boxed<Transform>>(*lookup(t.text)));
        } else {
            fail(t, "expected a transformation but found '" + t.text + "'");
        }
    }
}

Light Parser::parse_light_body(const Token& kw) {
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
        } else if (w == "media_interaction") {
            light.media_interaction = parse_bool_optional();
        } else if (w == "media_attenuation") {
            light.media_attenuation = parse_bool_optional();
        } else if (w == "looks_like" || w == "projected_through" || w == "photons") {
            warn_unsupported(t, w);
            skip_block(t);
        } else {
            if (!is_keyword(w) && lookup(w) == nullptr) fail_undeclared(t);
            fail(t, "expected a light_source item but found '" + w + "'");
        }
    }
}

CameraSpec Parser::parse_camera_body(const Token& kw) {
    expect("{");
    CameraSpec spec;
    spec.loc = make_diagnostic(Severity::Note, kw, "").loc;
    expand_macros();
    const Token& first = peek();
    if (first.kind == TokenKind::Identifier) {
        if (const Value* v = lookup(first.text); v && std::holds_alternative<Boxed<CameraSpec>>(*v)) {
            next();
            spec = *std::get<Boxed<CameraSpec>>(*v);
        }
    }
    while (true) {
        expand_macros();
        const Token t = peek();
        Transform tr;
        if (parse_transform_item(t, tr)) {
            spec.transform = spec.transform.then(tr);
            continue;
        }
        next();
        if (is_punct(t, "}")) return spec;
        const TokenText& w = t.text;
        if (t.kind != TokenKind::Identifier) fail(t, "expected a camera item but found '" + w + "'");
        if (w == "perspective") spec.type = Camera::Type::Perspective;
        else if (w == "orthographic") spec.type = Camera::Type::Orthographic;
        else if (w == "fisheye" || w == "ultra_wide_angle" || w == "omnimax" || w == "panoramic" ||
                 w == "spherical" || w == "mesh_camera") {
            warn_unsupported(t, w + " camera");
            spec.other_projection = true;
            if (w == "mesh_camera") {
                // Its parameters and meshes are not modelled: skip the rest of the camera block.
                const std::size_t depth = m_brace_depth;
                while (m_brace_depth >= depth) {
                    if (next().kind == TokenKind::EndOfFile) fail(kw, "camera block has no closing '}'");
                }
                return spec;
            }
        } else if (w == "cylinder") {
            warn_unsupported(t, "cylinder camera");
            spec.other_projection = true;
            parse_float();
        } else if (w == "location") spec.location = parse_vector();
        else if (w == "look_at") spec.look_at = parse_vector();
        else if (w == "direction") spec.direction = parse_vector();
        else if (w == "right") {
            spec.right = parse_vector();
            spec.had_right = true;
        } else if (w == "up") {
            spec.up = parse_vector();
            spec.had_up = true;
        } else if (w == "sky") spec.sky = parse_vector();
        else if (w == "angle") {
            spec.angle = parse_float();
            if (accept(",")) parse_float();  // the vertical angle of the spherical camera
        } else if (w == "aperture" || w == "blur_samples" || w == "confidence" || w == "variance" ||
                   w == "focal_point") {
            warn_unsupported(t, "focal blur");
            if (w == "focal_point") parse_vector();
            else parse_float();
            if (w == "blur_samples" && accept(",")) parse_float();
        } else if (w == "normal") {
            warn_unsupported(t, "camera normal");
            skip_block(t);
        } else {
            if (!is_keyword(w) && lookup(w) == nullptr) fail_undeclared(t);
            fail(t, "expected a camera item but found '" + w + "'");
        }
    }
}

void Parser::parse_radiosity(const Token& kw, RadiositySettings& rad) {
    expect("{");
    rad.loc = make_diagnostic(Severity::Note, kw, "").loc;
    auto as_int = [](double f) { return static_cast<int>(std::lround(f)); };
    while (true) {
        expand_macros();
        const Token t = next();
        if (is_punct(t, "}")) return;
        const TokenText& w = t.text;
        if (t.kind != TokenKind::Identifier) fail(t, "expected a radiosity item but found '" + w + "'");
        if (w == "count") {
            rad.count = as_int(parse_float());
            if (accept(",")) rad.count_directions = as_int(parse_float());
        } else if (w == "nearest_count") {
            rad.nearest_count = as_int(parse_float());
            if (accept(",")) rad.nearest_count_pretrace = as_int(parse_float());
        } else if (w == "error_bound") rad.error_bound = parse_float();
        else if (w == "low_error_factor") rad.low_error_factor = parse_float();
        else if (w == "minimum_reuse") rad.minimum_reuse = parse_float();
        else if (w == "maximum_reuse") rad.maximum_reuse = parse_float();
        else if (w == "recursion_limit") rad.recursion_limit = as_int(parse_float());
        else if (w == "pretrace_start") rad.pretrace_start = parse_float();
        else if (w == "pretrace_end") rad.pretrace_end = parse_float();
        else if (w == "brightness") rad.brightness = parse_float();
        else if (w == "gray_threshold") rad.gray_threshold = parse_float();
        else if (w == "adc_bailout") rad.adc_bailout = parse_float();
        else if (w == "always_sample") rad.always_sample = parse_bool_optional();
        else if (w == "normal") rad.normal = parse_bool_optional();
        else if (w == "media") rad.media = parse_bool_optional();
        else if (w == "max_sample") rad.max_sample = parse_float();
        else if (w == "subsurface") {
            warn_unsupported(t, "radiosity subsurface");
            parse_bool_optional();
        } else if (w == "save_file" || w == "load_file") {
            warn_unsupported(t, "radiosity " + w);
            parse_string();
        } else {
            if (!is_keyword(w) && lookup(w) == nullptr) fail_undeclared(t);
            fail(t, "expected a radiosity item but found '" + w + "'");
        }
    }
}

void Parser::parse_global_settings(const Token& kw) {
    expect("{");
    GlobalSettings& g = m_scene.global;
    while (true) {
        const Token t = next();
        if (is_punct(t, "}")) return;
        const TokenText& w = t.text;
        if (t.kind != TokenKind::Identifier) fail(t, "expected a global setting but found '" + w + "'");
        if (w == "assumed_gamma") {
            if (accept_keyword("srgb")) {
                warn_unsupported(t, "assumed_gamma srgb");
                g.assumed_gamma = 2.2;
            } else {
                g.assumed_gamma = parse_float();
            }
            g.assumed_gamma_given = true;
        } else if (w == "ambient_light") {
            g.ambient_light = parse_color();
        } else if (w == "max_trace_level") {
            g.max_trace_level = static_cast<int>(std::lround(parse_float()));
        } else if (w == "adc_bailout") {
            g.adc_bailout = parse_float();
        } else if (w == "radiosity") {
            RadiositySettings rad = g.radiosity.value_or(RadiositySettings{});
            parse_radiosity(t, rad);
            g.radiosity = rad;
        } else if (w == "photons" || w == "subsurface") {
            warn_unsupported(t, w);
            skip_block(t);
        } else if (w == "noise_generator") {
            g.noise_generator = std::clamp(static_cast<int>(parse_float()), 1, 3);
        } else if (w == "max_intersections" || w == "number_of_waves" ||
                   w == "mm_per_unit") {
            parse_float();
        } else if (w == "irid_wavelength") {
            parse_color();
        } else if (w == "hf_gray_16") {
            parse_bool_optional();
        } else if (w == "charset") {
            m_charset_utf8 = expect_identifier().text == "utf8";
        } else {
            if (!is_keyword(w) && lookup(w) == nullptr) fail_undeclared(t);
            fail(t, "expected a global setting but found '" + w + "'");
        }
    }
}

}  // namespace wardray::parser
