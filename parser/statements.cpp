// Scene statements: the top-level statement table, placing objects, the camera and the global settings.
#include <algorithm>
#include <cmath>

#include "parser/keyword_table.h"
#include "parser/keywords.h"
#include "parser/parser.h"

namespace wardray::parser {

void SceneReader::parse_statement() {
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
    using Statement = void (*)(SceneReader&, const Token&);
    static const KeywordTable<Statement> statements = {
        {"camera",
         [](SceneReader& r, const Token& kw) {
             const CameraSpec spec = r.parse_camera_body(kw);
             std::string error;
             std::string warning;
             Camera cam = resolve_camera(spec, error, warning);
             if (!warning.empty()) r.warn(kw, warning);
             if (!error.empty()) r.fail(kw, error);
             r.m_builder.set_camera(cam);
         }},
        {"light_source", [](SceneReader& r, const Token& kw) { r.m_builder.add_light(r.parse_light_body(kw)); }},
        // POV-Ray compat: the old `default { ... }` statement is #default.
        {"default", [](SceneReader& r, const Token& kw) { r.directive_default(kw); }},
        {"global_settings", [](SceneReader& r, const Token& kw) { r.parse_global_settings(kw); }},
        {"background",
         [](SceneReader& r, const Token&) {
             r.expect("{");
             r.m_builder.set_background(r.parse_color());
             r.expect("}");
         }},
        {"sky_sphere", [](SceneReader& r, const Token& kw) { r.m_builder.set_sky_sphere(r.parse_sky_sphere(kw)); }},
        {"fog", [](SceneReader& r, const Token& kw) { r.m_builder.add_fog(r.parse_fog(kw)); }},
    };
    if (const Statement* statement = statements.find(w)) {
        (*statement)(*this, t);
    } else if (is_object_keyword(t)) {
        place_object(parse_object(t));
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

std::optional<Value> SceneReader::parse_item_value(const Token& t) {
    using Item = Value (*)(SceneReader&, const Token&);
    static const KeywordTable<Item> items = {
        {"pigment", [](SceneReader& r, const Token& kw) -> Value { return r.parse_pigment_body(kw); }},
        {"finish", [](SceneReader& r, const Token& kw) -> Value { return r.parse_finish_body(kw); }},
        {"normal", [](SceneReader& r, const Token& kw) -> Value { return r.parse_normal_body(kw); }},
        {"interior", [](SceneReader& r, const Token& kw) -> Value { return r.parse_interior_body(kw); }},
        {"texture",
         [](SceneReader& r, const Token& kw) -> Value {
             Texture tx = r.parse_texture_body(kw);
             // POV-Ray compat: further textures in one declaration are layers painted over the first.
             const ScopedSetting layers(r.m_directive_ends_value_at, r.m_brace_depth);
             while (r.is_word(r.peek_expr(), "texture")) tx.layers.push_back(r.parse_texture_body(r.next()));
             return tx;
         }},
        // A declared colour map is kept as a pigment holding only that map; parse_color_map reads it back.
        {"color_map", [](SceneReader& r, const Token& kw) -> Value { return r.color_map_value(kw); }},
        {"colour_map", [](SceneReader& r, const Token& kw) -> Value { return r.color_map_value(kw); }},
        {"transform", [](SceneReader& r, const Token& kw) -> Value { return r.parse_transform_body(kw); }},
        {"camera", [](SceneReader& r, const Token& kw) -> Value { return r.parse_camera_body(kw); }},
        {"light_source",
         [](SceneReader& r, const Token& kw) -> Value {
             ObjectValue ov;
             ov.lights.push_back(r.parse_light_body(kw));
             return ov;
         }},
    };
    if (t.kind != TokenKind::Identifier) return std::nullopt;
    if (const Item* item = items.find(t.text)) return (*item)(*this, next());
    if (is_object_keyword(t)) return parse_object(next());
    return std::nullopt;
}

Pigment SceneReader::color_map_value(const Token& kw) {
    Pigment p;
    p.color_map = parse_color_map(kw);
    return p;
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

}  // namespace

void SceneReader::place_object(ObjectValue ov) {
    for (ObjectPart& part : ov.parts) {
        if (!part.has_texture) part.object.texture = ov.texture.value_or(default_texture());
        inherit_textures(part.object);
        m_builder.add_object(std::move(part.object));
    }
    for (Light& l : ov.lights) m_builder.add_light(std::move(l));
}

CameraSpec SceneReader::parse_camera_body(const Token& kw) {
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

void SceneReader::parse_radiosity(const Token& kw, RadiositySettings& rad) {
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

void SceneReader::parse_global_settings(const Token& kw) {
    expect("{");
    GlobalSettings& g = m_builder.global();
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
