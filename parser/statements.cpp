// Scene statements: the top-level statement table, placing objects, the camera and the global settings.
#include <algorithm>
#include <cmath>

#include "parser/keyword_table.h"
#include "parser/keywords.h"
#include "parser/parser.h"
#include "parser/texture_mover.h"

namespace wardray::parser {

void SceneReader::parse_statement() {
    const Token t = next();
    // POV-Ray compat: a float, vector or colour #declare takes a second ';' (Parse_RValue's, then Parse_Declare's),
    // even one after the end of the file it stands in (`#include "a.inc";` where a.inc ends with one).
    if (is_punct(t, ";") && m_tokens_taken == m_numeric_declare_semicolon + 1 && m_numeric_declare_semicolon > 0)
        return;
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
             // POV-Ray moves a mesh camera's blurred rays to the camera's location; not drawn that way here.
             if (cam.type == Camera::Type::MeshCamera && cam.focal_blur())
                 r.warn_unsupported(kw, "focal blur on a mesh_camera");
             r.m_builder.set_camera(cam);
         }},
        {"light_source",
         [](SceneReader& r, const Token& kw) {
             ObjectValue ov;
             Light light = r.parse_light_body(kw, &ov);
             ov.lights.push_back(std::move(light));
             r.place_object(std::move(ov));
         }},
        // POV-Ray compat: the old `default { ... }` statement is #default.
        {"default", [](SceneReader& r, const Token& kw) { r.directive_default(kw); }},
        {"global_settings", [](SceneReader& r, const Token& kw) { r.parse_global_settings(kw); }},
        {"background",
         [](SceneReader& r, const Token&) {
             r.expect("{");
             r.m_builder.set_background(r.parse_color(), !(r.m_version_given && r.m_version >= 3.7));
             r.expect("}");
         }},
        {"sky_sphere",
         [](SceneReader& r, const Token& kw) {
             SkySphere sky = r.parse_sky_sphere(kw);
             if (r.m_builder.has_sky_sphere()) r.warn(kw, "Only one sky-sphere allowed (last one will be used).");
             r.m_builder.set_sky_sphere(std::move(sky));
         }},
        {"fog", [](SceneReader& r, const Token& kw) { r.m_builder.add_fog(r.parse_fog(kw)); }},
        {"rainbow", [](SceneReader& r, const Token& kw) { r.m_builder.add_rainbow(r.parse_rainbow(kw)); }},
        {"media", [](SceneReader& r, const Token& kw) { r.m_builder.add_media(r.parse_media_body(kw)); }},
        // POV-Ray compat: the 3.1 forms without '#', read with POV-Ray's warnings.
        {"declare",
         [](SceneReader& r, const Token& kw) {
             r.warn(kw, "Should have '#' before 'declare'.");
             if (r.m_version >= 3.5)
                 r.warn(kw, "'declare' should be changed to '#declare'. Future versions may not support 'declare' "
                            "and may require '#declare'.");
             r.directive_declare(kw, false);
         }},
        {"include",
         [](SceneReader& r, const Token& kw) {
             r.warn(kw, "Should have '#' before 'include'.");
             r.directive_include(kw);
         }},
    };
    if (const Statement* statement = statements.find(w)) {
        (*statement)(*this, t);
    } else if (is_object_start(t)) {
        ObjectValue ov = parse_object(t);
        own_parts(ov, t);  // a placed copy of a declared object gets its own parts, charged to the budget here
        place_object(std::move(ov));
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
        {"media", [](SceneReader& r, const Token& kw) -> Value { return r.parse_media_body(kw); }},
        {"density", [](SceneReader& r, const Token& kw) -> Value { return r.parse_density_body(kw); }},
        {"material", [](SceneReader& r, const Token& kw) -> Value { return r.parse_material_body(kw); }},
        {"texture",
         [](SceneReader& r, const Token& kw) -> Value {
             Texture tx = r.parse_texture_body(kw);
             // POV-Ray compat: further textures in one declaration are layers painted over the first.
             const ScopedSetting layers(r.m_directive_ends_value_at, r.m_brace_depth);
             while (r.is_word(r.peek_expr(), "texture")) add_layers(tx, r.parse_texture_body(r.next()));
             return tx;
         }},
        // A declared colour map is kept as a pigment holding only that map; parse_color_map reads it back.
        {"color_map", [](SceneReader& r, const Token& kw) -> Value { return r.color_map_value(kw); }},
        {"colour_map", [](SceneReader& r, const Token& kw) -> Value { return r.color_map_value(kw); }},
        {"transform", [](SceneReader& r, const Token& kw) -> Value { return r.parse_transform_body(kw); }},
        {"sky_sphere", [](SceneReader& r, const Token& kw) -> Value { return r.parse_sky_sphere(kw); }},
        {"fog", [](SceneReader& r, const Token& kw) -> Value { return r.parse_fog(kw); }},
        {"rainbow", [](SceneReader& r, const Token& kw) -> Value { return r.parse_rainbow(kw); }},
        {"camera", [](SceneReader& r, const Token& kw) -> Value { return r.parse_camera_body(kw); }},
        {"light_source",
         [](SceneReader& r, const Token& kw) -> Value {
             ObjectValue ov;
             Light light = r.parse_light_body(kw, &ov);
             ov.lights.push_back(std::move(light));
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
        if (child.interior_texture.empty()) child.interior_texture = o.interior_texture;
        inherit_textures(child);
    }
}

// POV-Ray compat (Post_Process), down the tree once the textures are inherited: a child without an interior of its
// own shares its CSG parent's (keeping its own `hollow`), and an `ior` or `caustics` given in a plain texture's
// finish (3.1 syntax) becomes the object's interior's, as does its `refraction` (1 unless given).
void inherit_interiors(Object& o) {
    const Texture& tx = o.texture;
    const bool plain = tx.map_pattern.type == Pattern::Type::None && tx.texture_map.empty();
    if (plain && tx.finish.legacy_ior >= 0.0) o.interior.ior = tx.finish.legacy_ior;
    if (plain && tx.finish.legacy_caustics >= 0.0) o.interior.caustics = tx.finish.legacy_caustics;
    if (plain) o.interior.refraction = tx.finish.legacy_refraction;
    auto* csg = std::get_if<Csg>(&o.shape);
    if (csg == nullptr) return;
    for (Object& child : csg->children) {
        if (child.interior_id == 0) {
            const bool hollow = child.interior.hollow;
            child.interior = o.interior;
            child.interior.hollow = hollow;
            child.interior_id = o.interior_id;
        }
        inherit_interiors(child);
    }
}

// POV-Ray compat (Post_Process): a CSG's photon flags that are set override its children's, down the tree.
void promote_photons(Object& o) {
    auto* csg = std::get_if<Csg>(&o.shape);
    if (csg == nullptr) return;
    const ObjectPhotons& p = o.photons;
    for (Object& child : csg->children) {
        ObjectPhotons& c = child.photons;
        if (p.target) {
            c.target = true;
            c.spacing_multiplier = p.spacing_multiplier;
        }
        if (p.pass_through) c.pass_through = true;
        if (p.reflection != PhotonSwitch::Unset) c.reflection = p.reflection;
        if (p.refraction != PhotonSwitch::Unset) c.refraction = p.refraction;
        if (!p.collect) c.collect = false;
        // POV-Ray's CheckPassThru on the child, without its warning (given where the flags were read).
        if (c.pass_through && c.target && c.refraction != PhotonSwitch::Off) {
            if (c.refraction == PhotonSwitch::On) c.pass_through = false;
            else c.refraction = PhotonSwitch::Off;
        }
        promote_photons(child);
    }
}

}  // namespace

// uv_mapping where this renderer has no uv coordinates yet: a warning at the object (or the pigment).
void SceneReader::warn_uv_unsupported(const Object& o, bool in_csg) {
    bool nested = false;
    bool uses = o.uv_mapping || texture_uses_uv(o.texture, nested);
    for (const Texture& t : o.interior_texture) uses = texture_uses_uv(t, nested) || uses;
    const auto* mesh = std::get_if<Mesh>(&o.shape);
    // A top-level bicubic patch has uv coordinates as a mesh has, under the same conditions.
    const bool has_uv = mesh != nullptr || std::holds_alternative<BicubicPatch>(o.shape);
    if (mesh)
        for (const Texture& t : mesh->textures) uses = texture_uses_uv(t, nested) || uses;
    if (const auto* csg = std::get_if<Csg>(&o.shape))
        for (const Object& child : csg->children) warn_uv_unsupported(child, true);
    if (!uses) return;
    std::string what;
    if (nested) what = "uv_mapping inside a pigment_map or normal_map";
    else if (std::holds_alternative<Csg>(o.shape)) what = "uv_mapping on the parts of a CSG";
    else if (!has_uv) what = std::string("uv_mapping on ") + std::string(shape_keyword(o.shape));
    else if (in_csg || !o.clipped_by.empty() || o.inverse)
        what = std::string("uv_mapping on a ") + (mesh ? "mesh" : "bicubic_patch") + " in CSG, clipped or inverse";
    if (what.empty()) return;
    Diagnostic d;
    d.severity = Severity::Warning;
    d.loc = o.loc;
    d.message = what + " is not rendered yet";
    emit_feature_warning(std::move(d));
}

void SceneReader::share_equal_textures(Object& o, bool own_texture) {
    // A loop that writes `sphere { ... pigment { White } }` parses one texture per sphere, all equal: the objects
    // share one value instead of a copy each (a Texture is about 3 KB). Only textures given on the object count.
    if (own_texture) {
        const auto same = [&](const scene::Cow<Texture>& recent) { return recent.shares(o.texture); };
        const auto equal = [&](const scene::Cow<Texture>& recent) {
            return interchangeable(recent.get(), o.texture.get());
        };
        if (std::none_of(m_recent_textures.begin(), m_recent_textures.end(), same)) {
            const auto found = std::find_if(m_recent_textures.begin(), m_recent_textures.end(), equal);
            if (found != m_recent_textures.end()) {
                o.texture = *found;
            } else {
                m_recent_textures[m_recent_next] = o.texture;
                m_recent_next = (m_recent_next + 1) % m_recent_textures.size();
            }
        }
    }
    if (auto* csg = std::get_if<Csg>(&o.shape))
        for (Object& child : csg->children) share_equal_textures(child, child.has_texture);
}

void SceneReader::place_object(ObjectValue ov) {
    renumber_light_groups(ov);
    for (const ObjectPart& part : ov.parts) warn_uv_unsupported(part.object, false);
    std::uint32_t shared_interior = 0;
    // One texture for every part that has none of its own: the union's, or the #default one (shared with the
    // other objects placed since the #default last changed), so untextured parts cost a pointer each.
    const scene::Cow<Texture> inherited = ov.texture ? scene::Cow<Texture>(*ov.texture) : shared_default_texture();
    if (!m_options.object_sink) m_builder.reserve_objects(ov.parts.size());
    for (ObjectPart& part : ov.parts) {
        // POV-Ray compat (Link_To_Frame, remove_bounds on): a top-level object that is cheap to intersect loses
        // its bounds; CSG, polynomials, text and quadrics keep them.
        const Shape& shape = part.object.shape;
        if (!ov.compound && !std::holds_alternative<Csg>(shape) && !std::holds_alternative<Quartic>(shape) &&
            !std::holds_alternative<Poly>(shape) &&
            !std::holds_alternative<Text>(shape) && !std::holds_alternative<Quadric>(shape))
            part.object.bounded_by.clear();
        if (!part.has_texture) part.object.texture = inherited;
        inherit_textures(part.object);
        share_equal_textures(part.object, part.has_texture);
        // POV-Ray compat (Post_Process): a top-level object without an interior gets a new one, which the parts
        // of a union without one share.
        if (part.object.interior_id == 0) {
            if (shared_interior == 0) shared_interior = ++m_interior_ids;
            part.object.interior_id = shared_interior;
        }
        inherit_interiors(part.object);
        promote_photons(part.object);
        if (m_options.object_sink)
            m_options.object_sink(part.object);
        else
            m_builder.add_object(std::move(part.object));
    }
    for (Light& l : ov.lights) m_builder.add_light(std::move(l));
}

namespace {

/// A radiosity count, rounded as POV-Ray does.
int as_int(double f) { return static_cast<int>(std::lround(f)); }

}  // namespace

bool SceneReader::focal_blur(SceneReader& r, CameraSpec& c, const Token& item, const Token&) {
    using Item = void (*)(SceneReader&, CameraSpec&, const Token&);
    static const KeywordTable<Item> items = {
        {"aperture", [](SceneReader& r, CameraSpec& c, const Token&) { c.aperture = r.parse_float(); }},
        {"focal_point", [](SceneReader& r, CameraSpec& c, const Token&) { c.focal_point = r.parse_vector(); }},
        {"blur_samples",
         [](SceneReader& r, CameraSpec& c, const Token& item) {
             // POV-Ray compat: `blur_samples max` or `blur_samples min, max`.
             const double first = r.parse_float();
             if (first <= 0.0) r.fail(item, "Illegal number of focal blur samples.");
             const bool two = r.accept(",") || r.starts_value(r.peek());
             const int second = two ? static_cast<int>(r.parse_float()) : 0;
             c.blur_samples_min = second == 0 ? 0 : static_cast<int>(first);
             c.blur_samples = second == 0 ? static_cast<int>(first) : second;
             if (c.blur_samples_min > c.blur_samples)
                 r.fail(item, "Focal blur samples minimum must not be larger than maximum.");
         }},
        {"confidence",
         [](SceneReader& r, CameraSpec& c, const Token& item) {
             const double k = r.parse_float();
             if (k > 0.0 && k < 1.0) c.confidence = k;
             else r.warn(item, "Illegal confidence value. Default is used.");
         }},
        {"variance",
         [](SceneReader& r, CameraSpec& c, const Token& item) {
             const double k = r.parse_float();
             if (k >= 0.0 && k <= 1.0) c.variance = k;
             else r.warn(item, "Illegal variance value. Default is used.");
         }},
    };
    (*items.find(item.text))(r, c, item);
    return false;
}

void SceneReader::read_assumed_gamma(SceneReader& r, GlobalSettings& g, const Token& item) {
    GammaCurve gamma = GammaCurve::srgb();
    if (!r.accept_keyword("srgb")) {
        const Token at = r.peek();
        const double value = r.parse_float();
        if (!(value > 0.0)) r.fail(at, "gamma value must be positive");
        gamma = GammaCurve::power_law(value);
    }
    if (g.assumed_gamma_given) {
        r.warn(item, "a second assumed_gamma is ignored");
        return;
    }
    g.assumed_gamma = gamma;
    g.assumed_gamma_given = true;
    r.m_working_gamma = gamma;
}

void SceneReader::radiosity_file(SceneReader& r, RadiositySettings&, const Token& item) {
    r.warn_unsupported(item, "radiosity " + item.text);
    const Token name_tok = r.peek();
    const std::string name = r.parse_string();
    // Not read or written, but confined already, as every file a scene names.
    if (item.text == "load_file") r.require_readable(name_tok, r.scene_relative(name), "radiosity load_file");
    else r.require_writable(name_tok, r.scene_relative(name));
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
        // An item returns true when it ends the camera block.
        using Item = bool (*)(SceneReader&, CameraSpec&, const Token& item, const Token& kw);
        static const KeywordTable<Item> items = {
            {"location", [](SceneReader& r, CameraSpec& c, const Token&, const Token&) {
                 c.location = r.parse_vector();
                 return false;
             }},
            {"look_at", [](SceneReader& r, CameraSpec& c, const Token&, const Token&) {
                 c.look_at = r.parse_vector();
                 return false;
             }},
            {"direction", [](SceneReader& r, CameraSpec& c, const Token&, const Token&) {
                 c.direction = r.parse_vector();
                 return false;
             }},
            {"right", [](SceneReader& r, CameraSpec& c, const Token&, const Token&) {
                 c.right = r.parse_vector();
                 c.had_right = true;
                 return false;
             }},
            {"up", [](SceneReader& r, CameraSpec& c, const Token&, const Token&) {
                 c.up = r.parse_vector();
                 c.had_up = true;
                 return false;
             }},
            {"sky", [](SceneReader& r, CameraSpec& c, const Token&, const Token&) {
                 c.sky = r.parse_vector();
                 return false;
             }},
            {"angle", [](SceneReader& r, CameraSpec& c, const Token&, const Token&) {
                 c.angle = r.parse_float();
                 // POV-Ray compat: the spherical camera's vertical angle follows, its comma optional.
                 if (c.type == Camera::Type::Spherical && (r.accept(",") || r.starts_value(r.peek())))
                     c.v_angle = r.parse_float();
                 return false;
             }},
            {"aperture", &focal_blur},
            {"blur_samples", &focal_blur},
            {"confidence", &focal_blur},
            {"variance", &focal_blur},
            {"focal_point", &focal_blur},
            {"normal", [](SceneReader& r, CameraSpec& c, const Token& item, const Token&) {
                 c.normal = r.parse_normal_body(item);
                 return false;
             }},
        };
        if (const auto type = find_kind(k_camera_keywords, w.view())) {
            spec.type = *type;  // a projection of WARDRAY_CAMERAS
            if (spec.type == Camera::Type::Cylinder) {
                const double n = parse_float();
                spec.cylinder = static_cast<int>(n);
                if (spec.cylinder < 1 || spec.cylinder > 4)
                    fail(t, "Invalid cylinder camera type, valid are types 1 to 4.");
            }
            if (spec.type == Camera::Type::MeshCamera) parse_mesh_camera(spec, t);
        } else if (const Item* item = items.find(w)) {
            if ((*item)(*this, spec, t, kw)) return spec;
        } else {
            if (!is_keyword(w) && lookup(w) == nullptr) fail_undeclared(t);
            fail(t, "expected a camera item but found '" + w + "'");
        }
    }
}

void SceneReader::parse_radiosity(const Token& kw, RadiositySettings& rad) {
    expect("{");
    rad.loc = make_diagnostic(Severity::Note, kw, "").loc;
    while (true) {
        expand_macros();
        const Token t = next();
        if (is_punct(t, "}")) return;
        const TokenText& w = t.text;
        if (t.kind != TokenKind::Identifier) fail(t, "expected a radiosity item but found '" + w + "'");
        using Item = void (*)(SceneReader&, RadiositySettings&, const Token&);
        static const KeywordTable<Item> items = {
            {"count",
             [](SceneReader& r, RadiositySettings& s, const Token&) {
                 s.count = as_int(r.parse_float());
                 if (r.accept(",")) s.count_directions = as_int(r.parse_float());
             }},
            {"nearest_count",
             [](SceneReader& r, RadiositySettings& s, const Token&) {
                 s.nearest_count = as_int(r.parse_float());
                 if (r.accept(",")) s.nearest_count_pretrace = as_int(r.parse_float());
             }},
            {"error_bound",
             [](SceneReader& r, RadiositySettings& s, const Token&) { s.error_bound = r.parse_float(); }},
            {"low_error_factor",
             [](SceneReader& r, RadiositySettings& s, const Token&) { s.low_error_factor = r.parse_float(); }},
            {"minimum_reuse",
             [](SceneReader& r, RadiositySettings& s, const Token&) { s.minimum_reuse = r.parse_float(); }},
            {"maximum_reuse",
             [](SceneReader& r, RadiositySettings& s, const Token&) { s.maximum_reuse = r.parse_float(); }},
            {"recursion_limit",
             [](SceneReader& r, RadiositySettings& s, const Token&) { s.recursion_limit = as_int(r.parse_float()); }},
            {"pretrace_start",
             [](SceneReader& r, RadiositySettings& s, const Token&) { s.pretrace_start = r.parse_float(); }},
            {"pretrace_end",
             [](SceneReader& r, RadiositySettings& s, const Token&) { s.pretrace_end = r.parse_float(); }},
            {"brightness", [](SceneReader& r, RadiositySettings& s, const Token&) { s.brightness = r.parse_float(); }},
            {"gray_threshold",
             [](SceneReader& r, RadiositySettings& s, const Token&) { s.gray_threshold = r.parse_float(); }},
            {"adc_bailout",
             [](SceneReader& r, RadiositySettings& s, const Token&) { s.adc_bailout = r.parse_float(); }},
            {"always_sample",
             [](SceneReader& r, RadiositySettings& s, const Token&) { s.always_sample = r.parse_bool_optional(); }},
            {"normal", [](SceneReader& r, RadiositySettings& s, const Token&) { s.normal = r.parse_bool_optional(); }},
            {"media", [](SceneReader& r, RadiositySettings& s, const Token&) { s.media = r.parse_bool_optional(); }},
            {"max_sample", [](SceneReader& r, RadiositySettings& s, const Token&) { s.max_sample = r.parse_float(); }},
            {"subsurface",
             [](SceneReader& r, RadiositySettings&, const Token& item) {
                 r.warn_unsupported(item, "radiosity subsurface");
                 r.parse_bool_optional();
             }},
            {"save_file", &radiosity_file},
            {"load_file", &radiosity_file},
        };
        if (const Item* item = items.find(w)) {
            (*item)(*this, rad, t);
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
        using Setting = void (*)(SceneReader&, GlobalSettings&, const Token&);
        // Settings that are valid POV-Ray and not rendered yet: warned about, their block skipped.
        auto skip_unsupported_setting = [](SceneReader& r, GlobalSettings&, const Token& item) {
            r.warn_unsupported(item, item.text);
            r.skip_block(item);
        };
        static const KeywordTable<Setting> settings = {
            {"assumed_gamma", &read_assumed_gamma},
            {"ambient_light",
             [](SceneReader& r, GlobalSettings& g, const Token&) { g.ambient_light = r.parse_color(); }},
            {"max_trace_level",
             [](SceneReader& r, GlobalSettings& g, const Token&) {
                 g.max_trace_level = static_cast<int>(std::lround(r.parse_float()));
             }},
            {"adc_bailout", [](SceneReader& r, GlobalSettings& g, const Token&) { g.adc_bailout = r.parse_float(); }},
            {"radiosity",
             [](SceneReader& r, GlobalSettings& g, const Token& item) {
                 RadiositySettings rad = g.radiosity.value_or(RadiositySettings{});
                 r.parse_radiosity(item, rad);
                 g.radiosity = rad;
             }},
            {"photons",
             [](SceneReader& r, GlobalSettings& g, const Token& item) {
                 PhotonSettings ph;
                 r.parse_photons(item, ph);
                 // POV-Ray compat: `gather` with a maximum of 0 turns photons off.
                 if (ph.gather_max > 0) g.photons = ph;
                 else g.photons.reset();
             }},
            {"subsurface", skip_unsupported_setting},
            {"noise_generator",
             [](SceneReader& r, GlobalSettings& g, const Token&) {
                 g.noise_generator = std::clamp(static_cast<int>(r.parse_float()), 1, 3);
             }},
            {"max_intersections", [](SceneReader& r, GlobalSettings&, const Token&) { r.parse_float(); }},
            {"number_of_waves",
             [](SceneReader& r, GlobalSettings& g, const Token& kw) {
                 g.number_of_waves = static_cast<int>(r.parse_float());
                 if (g.number_of_waves <= 0) {
                     r.warn(kw, "Illegal Value: number_of_waves must be greater than 0.\nChanged to 1.");
                     g.number_of_waves = 1;
                 }
             }},
            {"mm_per_unit", [](SceneReader& r, GlobalSettings&, const Token&) { r.parse_float(); }},
            {"irid_wavelength", [](SceneReader& r, GlobalSettings&, const Token&) { r.parse_color(); }},
            {"hf_gray_16", [](SceneReader& r, GlobalSettings&, const Token&) { r.parse_bool_optional(); }},
            {"charset",
             [](SceneReader& r, GlobalSettings&, const Token&) {
                 r.m_charset_utf8 = r.expect_identifier().text == "utf8";
             }},
        };
        if (const Setting* setting = settings.find(w)) {
            (*setting)(*this, g, t);
        } else {
            if (!is_keyword(w) && lookup(w) == nullptr) fail_undeclared(t);
            fail(t, "expected a global setting but found '" + w + "'");
        }
    }
}

}  // namespace wardray::parser
