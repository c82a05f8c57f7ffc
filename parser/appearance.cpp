// Appearance: colours (with POV-Ray's promotion rules), finishes, textures, interiors, #default.
#include <algorithm>
#include <cmath>

#include "parser/keyword_table.h"
#include "parser/keywords.h"
#include "parser/parser.h"

namespace wardray::parser {

Color AppearanceReader::parse_color() { return read_color(Color{}, false); }

Color AppearanceReader::parse_color_modifiers(Color c) { return read_color(c, true); }

Color AppearanceReader::read_color(Color c, bool any) {
    while (true) {
        const Token t = any ? peek_expr() : peek();
        const std::string_view w = t.text;
        if (t.kind == TokenKind::Identifier && (w == "color" || w == "colour")) {
            // A second `color` keyword starts the next colour (old-style colour map entries).
            if (any) break;
            next();
            continue;
        }
        if (t.kind == TokenKind::Identifier && (w.rfind("rgb", 0) == 0 || w.rfind("srgb", 0) == 0) &&
            is_color_keyword(t)) {
            // POV-Ray compat: so does a second rgb/rgbt/... keyword (`checker rgb A rgb B` lists two colours).
            if (any) break;
            next();
            const bool srgb = w[0] == 's';
            const std::string_view form = srgb ? w.substr(1) : w;
            const int terms = form == "rgb" ? 3 : (form == "rgbft" ? 5 : 4);
            // POV-Ray compat: components beyond the keyword's count (a colour identifier after rgb) are ignored.
            const Numeric e = parse_numeric();
            // POV-Ray compat: `rgb 0.5` promotes the float to r, g and b only.
            const Numeric p = e.promoted(terms);
            c.r = p.v[0];
            c.g = p.v[1];
            c.b = p.v[2];
            if (srgb) {
                // POV-Ray compat: sRGB values are decoded and re-encoded with the working gamma, which must
                // already be known; before assumed_gamma POV-Ray stops with this error.
                if (!m_working_gamma) fail(t, "cannot read sRGB colours before assumed_gamma is set");
                const GammaTranscoding to_working = transcoding(*m_working_gamma, GammaCurve::srgb());
                c.r = to_working.decode(c.r);
                c.g = to_working.decode(c.g);
                c.b = to_working.decode(c.b);
            }
            if (form == "rgbf") c.filter = p.v[3];
            if (form == "rgbt") c.transmit = p.v[3];
            if (form == "rgbft") {
                c.filter = p.v[3];
                c.transmit = p.v[4];
            }
            any = true;
            continue;
        }
        if (t.kind == TokenKind::Identifier &&
            (w == "red" || w == "green" || w == "blue" || w == "filter" || w == "transmit")) {
            next();
            const double f = parse_float();
            if (w == "red") c.r = f;
            if (w == "green") c.g = f;
            if (w == "blue") c.b = f;
            if (w == "filter") c.filter = f;
            if (w == "transmit") c.transmit = f;
            any = true;
            continue;
        }
        if (any) break;
        // A bare expression or identifier: POV-Ray compat, a float sets all five components (filter and
        // transmit too); a shorter vector leaves the missing components at zero.
        const Token at = peek();
        const Numeric e = parse_numeric();
        if (e.n > 5) fail(at, "a colour has at most 5 components");
        c = e.to_color();
        any = true;
    }
    return c;
}

void AppearanceReader::parse_finish_item(Finish& f, const Token& item) {
    // `albedo` rescales the value when the finish block ends (see parse_finish_body).
    static const auto scalar_with_albedo = [](AppearanceReader& r, const Token& kw) {
        if (r.accept_keyword("albedo")) r.m_finish_albedo |= kw.text == "diffuse" ? 1u : (kw.text == "phong" ? 2u : 4u);
        return r.parse_float();
    };
    using Item = void (*)(AppearanceReader&, Finish&, const Token&);
    static const KeywordTable<Item> items = {
        {"ambient", [](AppearanceReader& r, Finish& f, const Token&) { f.ambient = r.parse_color(); }},
        {"emission", [](AppearanceReader& r, Finish& f, const Token&) { f.emission = r.parse_color(); }},
        {"diffuse",
         [](AppearanceReader& r, Finish& f, const Token& kw) {
             f.diffuse = scalar_with_albedo(r, kw);
             if (r.accept(",")) {
                 r.parse_float();
                 r.warn_unsupported(kw, "diffuse backside value");
             }
         }},
        {"brilliance", [](AppearanceReader& r, Finish& f, const Token&) { f.brilliance = r.parse_float(); }},
        {"phong", [](AppearanceReader& r, Finish& f, const Token& kw) { f.phong = scalar_with_albedo(r, kw); }},
        {"phong_size", [](AppearanceReader& r, Finish& f, const Token&) { f.phong_size = r.parse_float(); }},
        {"specular",
         [](AppearanceReader& r, Finish& f, const Token& kw) { f.specular = scalar_with_albedo(r, kw); }},
        {"roughness",
         [](AppearanceReader& r, Finish& f, const Token& kw) {
             f.roughness = r.parse_float();
             if (f.roughness <= 0.0) r.fail(kw, "roughness must be greater than 0");
         }},
        {"reflection",
         [](AppearanceReader& r, Finish& f, const Token&) {
             if (r.is_punct(r.peek(), "{")) {
                 r.parse_reflection_block(f);
             } else {
                 // Old syntax: one colour for every angle; a second one makes it `reflection { a, b }`.
                 f.reflection_min = f.reflection_max = r.parse_color();
                 f.reflection_falloff = 1.0;
                 f.reflection_fresnel = false;
                 if (r.accept(",")) f.reflection_max = r.parse_color();
             }
         }},
        {"reflection_exponent",
         [](AppearanceReader& r, Finish& f, const Token&) { f.reflection_exponent = r.parse_float(); }},
        {"metallic",
         [](AppearanceReader& r, Finish& f, const Token&) {
             f.metallic = r.starts_value(r.peek()) ? r.parse_float() : 1.0;
         }},
        {"conserve_energy",
         [](AppearanceReader& r, Finish& f, const Token&) { f.conserve_energy = r.parse_bool_optional(); }},
        {"crand", [](AppearanceReader& r, Finish& f, const Token&) { f.crand = r.parse_float(); }},
        {"irid",
         [](AppearanceReader& r, Finish& f, const Token&) {
             r.expect("{");
             f.irid = r.parse_float();
             while (!r.accept("}")) {
                 const Token t = r.next();
                 if (r.is_word(t, "thickness")) f.irid_thickness = r.parse_float();
                 else if (r.is_word(t, "turbulence")) f.irid_turbulence = r.parse_vector().x;
                 else r.fail(t, "expected thickness or turbulence in irid but found " + describe_token(t));
             }
         }},
        // POV-Ray compat: POV-Ray 3.1's interior items inside a finish, read by 3.7 with these warnings.
        {"ior",
         [](AppearanceReader& r, Finish& f, const Token& kw) {
             f.legacy_ior = r.parse_float();
             r.warn(kw, "Index of refraction value should be specified in 'interior{...}' statement.");
         }},
        {"caustics",
         [](AppearanceReader& r, Finish& f, const Token& kw) {
             f.legacy_caustics = r.parse_float();
             r.warn(kw, "Caustics value should be specified in 'interior{...}' statement.");
         }},
        {"refraction",
         [](AppearanceReader& r, Finish& f, const Token& kw) {
             // POV-Ray scales the refracted light by this value (its interior's Old_Refract, set when the object
             // is placed); 1 changes nothing.
             f.legacy_refraction = r.parse_float();
             r.warn(kw, "Refraction value unnecessary to turn on refraction. To attenuate, the fade_power and "
                        "fade_distance keywords should be specified in 'interior{...}' statement.");
         }},
        {"subsurface",
         [](AppearanceReader& r, Finish&, const Token& kw) {
             r.warn_unsupported(kw, kw.text);
             r.skip_block(kw);
         }},
    };
    if (const Item* read = items.find(item.text)) {
        (*read)(*this, f, item);
        return;
    }
    fail(item, "expected a finish item but found '" + item.text + "'");
}

Finish AppearanceReader::parse_finish_body(const Token& kw, const Finish* base) {
    expect("{");
    m_finish_albedo = 0;
    Finish f = base ? *base : m_default_finish;
    f.loc = make_diagnostic(Severity::Note, kw, "").loc;
    expand_macros();
    if (is_array_element_next()) {
        const Token at = peek();
        const Value element = *take_array_element();
        if (const auto* ef = std::get_if<Boxed<Finish>>(&element)) f = **ef;
        else fail(at, "this array element is not a finish");
    }
    const Token& first = peek();
    if (first.kind == TokenKind::Identifier) {
        if (const Value* v = lookup(first.text); v && std::holds_alternative<Boxed<Finish>>(*v)) {
            next();
            f = *std::get<Boxed<Finish>>(*v);
        }
    }
    while (true) {
        const Token t = next();
        if (is_punct(t, "}")) {
            // POV-Ray's albedo forms: the value given is the albedo; convert it to POV-Ray's coefficient.
            if (m_finish_albedo & 1u) f.diffuse *= (f.brilliance + 1.0) / 2.0;
            if (m_finish_albedo & 2u) f.phong *= (f.phong_size + 1.0) / 2.0;
            if (m_finish_albedo & 4u) {
                const double r = 1.0 / f.roughness;
                f.specular *= (r + 2.0) / (4.0 * (2.0 - std::pow(2.0, -r / 2.0)));
            }
            m_finish_albedo = 0;
            return f;
        }
        if (t.kind != TokenKind::Identifier) fail(t, "expected a finish item but found '" + t.text + "'");
        if (lookup(t.text) != nullptr) fail(t, "'" + t.text + "' must come first in the finish block");
        if (!is_keyword(t.text)) fail_undeclared(t);
        parse_finish_item(f, t);
    }
}

Texture AppearanceReader::parse_texture_body(const Token& kw) {
    expect("{");
    Texture tx = default_texture();
    parse_texture_items(tx, kw, "}");
    return tx;
}

namespace {

// POV-Ray compat (Post_Textures): a texture's `no_bump_scale` reaches its normal, its texture_map's pattern (the
// normal's way into the entries' space) and every entry of that map.
void mark_no_bump_scale(Texture& t) {
    t.normal.pattern.no_bump_scale = true;
    t.map_pattern.no_bump_scale = true;
    for (TextureMapEntry& e : t.texture_map) mark_no_bump_scale(e.texture);
}

}  // namespace

void AppearanceReader::parse_texture_items(Texture& tx, const Token& kw, const char* close) {
    const std::size_t depth = m_brace_depth;
    bool no_bump_scale = false;
    expand_macros();
    if (is_array_element_next()) {
        const Token at = peek();
        const Value element = *take_array_element();
        if (const auto* et = std::get_if<Boxed<Texture>>(&element)) tx = **et;
        else fail(at, "this array element is not a texture");
    }
    const Token& first = peek();
    if (first.kind == TokenKind::Identifier) {
        if (const Value* v = lookup(first.text); v && std::holds_alternative<Boxed<Texture>>(*v)) {
            next();
            tx = *std::get<Boxed<Texture>>(*v);
        }
    }
    parse_texture_part_identifiers(tx);
    while (true) {
        expand_macros();
        const Token t = peek();
        Transform tr;
        if (parse_transform_item(t, tr)) {
            // A transform inside a uv-mapped texture moves it in uv space.
            const bool uv = tx.uv_mapping;
            tx.uv_mapping = false;
            transform_texture(tx, tr);
            tx.uv_mapping = uv;
            continue;
        }
        if (is_punct(t, close)) {
            next();
            // (After a texture_map's pattern the flag is read as that pattern's modifier: it marks the map too.)
            if (tx.map_pattern.no_bump_scale) mark_no_bump_scale(tx);
            if (no_bump_scale) mark_no_bump_scale(top_layer(tx));
            return;
        }
        if (t.kind != TokenKind::Identifier) fail(t, "expected a texture item but found '" + t.text + "'");
        if (t.text == "uv_mapping") {
            next();
            tx.uv_mapping = true;
            continue;
        }
        // texture_map patterns: `texture { gradient y texture_map { ... } }` or `checker texture {..} texture {..}`.
        const int count = parse_pattern_keyword(t, tx.map_pattern);
        const bool list_inside = take_pattern_list_open();
        if (tx.map_pattern.type == Pattern::Type::Facets) fail(t, "Keyword 'facets' can only be used in a normal statement.");
        if (count >= 0) {
            tx.texture_map.clear();
            for (int i = 0; i < count && is_word(peek(), "texture"); ++i) {
                const Token tkw = next();
                tx.texture_map.push_back({static_cast<double>(i), parse_texture_body(tkw)});
                accept(",");
            }
            if (list_inside) expect("}");
            continue;
        }
        if (tx.map_pattern.type != Pattern::Type::None && parse_pattern_modifier(t, tx.map_pattern)) continue;
        next();
        if (t.text == "tiles") {
            tx = parse_tiles(t);
        } else if (t.text == "material_map") {
            parse_material_map(t, tx);
        } else if (t.text == "no_bump_scale") {
            // POV-Ray's DONT_SCALE_BUMPS flag, given to the texture's normal and map once the texture is read.
            no_bump_scale = true;
        } else if (t.text == "pigment") {
            top_layer(tx).pigment = parse_pigment_body(t, &top_layer(tx).pigment);
        } else if (t.text == "finish") {
            top_layer(tx).finish = parse_finish_body(t, &top_layer(tx).finish);
        } else if (t.text == "normal") {
            top_layer(tx).normal = parse_normal_body(t, &top_layer(tx).normal);
        } else if (t.text == "texture_map") {
            expect("{");
            tx.texture_map.clear();
            while (!accept("}")) {
                const Token open = expect("[");
                TextureMapEntry e;
                // POV-Ray compat: an average map's weights may be left out (1 each).
                const bool weighted = tx.map_pattern.type != Pattern::Type::Average || starts_value(peek());
                e.value = weighted ? static_cast<double>(static_cast<float>(parse_float())) : 1.0;
                accept(",");
                e.texture = default_texture();
                parse_texture_items(e.texture, open, "]");
                tx.texture_map.push_back(std::move(e));
            }
            if (tx.texture_map.empty()) fail(t, "a texture_map must have at least one entry");
        } else if (is_pattern_keyword(t.text) || is_unsupported_block(t.text)) {
            warn_unsupported(t, "texture pattern '" + t.text + "'");
            skip_to_close(kw, close, depth);
            return;
        } else {
            if (!is_keyword(t.text) && lookup(t.text) == nullptr) fail_undeclared(t);
            fail(t, "expected pigment, finish, normal or a transform in texture but found '" + t.text + "'");
        }
    }
}

Texture AppearanceReader::parse_texture_list(const Token& kw) {
    // POV-Ray compat: textures in a row are layers, the last listed on top (Link_Textures).
    if (!is_word(peek(), "texture")) fail(peek(), "expected a texture in '" + kw.text + "' but found " + describe_token(peek()));
    Texture base = parse_texture_body(next());
    while (is_word(peek(), "texture")) add_layers(base, parse_texture_body(next()));
    return base;
}

Texture AppearanceReader::parse_tiles(const Token& kw) {
    // `tiles { texture {..} tile2 texture {..} }`: a checker of the two; the first tile at the pattern's value 1
    // (POV-Ray's Parse_Tiles keeps the old tiles' order).
    expect("{");
    Texture tx;
    tx.map_pattern.type = Pattern::Type::Checker;
    tx.map_pattern.params->frequency = 0.0;
    Texture first = parse_texture_list(kw);
    const Token second = peek();
    if (!is_word(second, "tile2")) fail(second, "expected 'tile2' in tiles but found " + describe_token(second));
    next();
    Texture other = is_word(peek(), "texture") ? parse_texture_list(second) : default_texture();
    expect("}");
    tx.texture_map.push_back({0.0, std::move(other)});
    tx.texture_map.push_back({1.0, std::move(first)});
    return tx;
}

void AppearanceReader::parse_texture_part_identifiers(Texture& tx) {
    // POV-Ray compat: a plain texture may begin with pigment, normal and finish identifiers standing alone, in any
    // order (`texture { Jade finish { F } }`), a concession POV-Ray keeps from its first versions (Parse_Texture).
    if (tx.map_pattern.type != Pattern::Type::None || !tx.texture_map.empty()) return;
    while (true) {
        expand_macros();
        const Token& t = peek();
        if (t.kind != TokenKind::Identifier) return;
        const Value* v = lookup(t.text);
        if (v == nullptr || m_macros.count(t.text)) return;
        if (const auto* p = std::get_if<Boxed<Pigment>>(v)) {
            top_layer(tx).pigment = **p;
        } else if (const auto* n = std::get_if<Boxed<Normal>>(v)) {
            top_layer(tx).normal = **n;
        } else if (const auto* f = std::get_if<Boxed<Finish>>(v)) {
            top_layer(tx).finish = **f;
        } else {
            return;
        }
        next();
    }
}

void AppearanceReader::parse_reflection_block(Finish& f) {
    // reflection { [min,] max [fresnel] [falloff F] [exponent E] [metallic M] }
    expect("{");
    f.reflection_min = parse_color();
    f.reflection_max = f.reflection_min;
    accept(",");
    const bool two_colours = starts_value(peek());
    if (two_colours) f.reflection_max = parse_color();
    while (true) {
        const Token t = next();
        if (is_punct(t, "}")) return;
        if (is_word(t, "fresnel")) {
            f.reflection_fresnel = parse_bool_optional();
            // POV-Ray compat: `reflection { r fresnel }` means Fresnel from 0 up to r.
            if (f.reflection_fresnel && !two_colours) f.reflection_min = Color{};
        } else if (is_word(t, "falloff")) {
            f.reflection_falloff = parse_float();
        } else if (is_word(t, "exponent")) {
            f.reflection_exponent = parse_float();
        } else if (is_word(t, "metallic")) {
            f.reflection_metallic = starts_value(peek()) ? parse_float() : 1.0;
        } else {
            fail(t, "expected fresnel, falloff, exponent or metallic in reflection but found " + describe_token(t));
        }
    }
}

Interior AppearanceReader::parse_interior_body(const Token& /*kw*/, const Interior& base) {
    expect("{");
    Interior in = base;
    expand_macros();
    if (const Token& first = peek(); first.kind == TokenKind::Identifier && !is_keyword(first.text) &&
                                     lookup(first.text) != nullptr) {
        // A declared interior, which the items after it modify.
        const Value* v = lookup(first.text);
        if (const auto* declared = std::get_if<Boxed<Interior>>(v)) in = **declared;
        else fail(first, "'" + first.text + "' is " + value_kind_name(*v) + ", not an interior");
        next();
    }
    while (true) {
        expand_macros();
        const Token t = next();
        if (is_punct(t, "}")) return in;
        if (t.kind != TokenKind::Identifier) fail(t, "expected an interior item but found " + describe_token(t));
        if (t.text == "ior") {
            in.ior = parse_float();
        } else if (t.text == "fade_distance") {
            in.fade_distance = parse_float();
        } else if (t.text == "fade_power") {
            in.fade_power = parse_float();
        } else if (t.text == "fade_color" || t.text == "fade_colour") {
            in.fade_color = parse_color();
        } else if (t.text == "caustics") {
            // POV-Ray keeps the value times 45, the exponent of its fake-caustics term.
            in.caustics = parse_float() * 45.0;
        } else if (t.text == "dispersion") {
            // A ratio of indices: zero or less would make every band's index infinite or undefined.
            const double d = parse_float();
            if (d > 0.0) in.dispersion = d;
            else warn(t, "dispersion must be positive; ignored");
        } else if (t.text == "dispersion_samples") {
            // POV-Ray truncates the value, then requires 2 at least; a bound keeps a hostile count from stalling
            // every ray that crosses the interior.
            constexpr double kMaxSamples = 1000.0;
            const double n = std::trunc(parse_float());
            if (!(n >= 2.0)) fail(t, "Dispersion samples minimum is 2.");
            if (n > kMaxSamples) warn(t, "dispersion_samples above 1000 limited to 1000");
            in.dispersion_samples = static_cast<int>(std::min(n, kMaxSamples));
        } else if (t.text == "refraction") {
            // POV-Ray compat: still read, with POV-Ray's warning; it scales the refracted light (1 changes nothing).
            // (A plain texture's finish overrides it when the object is placed, as in POV-Ray.)
            in.refraction = parse_float();
            warn(t, "Refraction value unnecessary to turn on refraction. To attenuate, the fade_power and "
                    "fade_distance keywords should be specified in 'interior{...}' statement.");
        } else if (t.text == "media") {
            in.media.push_back(parse_media_body(t));
        } else {
            if (!is_keyword(t.text) && lookup(t.text) == nullptr) fail_undeclared(t);
            fail(t, "expected ior, fade_distance, fade_power or fade_color in interior but found '" + t.text + "'");
        }
    }
}

void AppearanceReader::directive_default(const Token& tok) {
    // Deferred declarations were written against the defaults in force where they stand.
    evaluate_all_deferred();
    expect("{");
    while (true) {
        const Token t = next();
        if (is_punct(t, "}")) return;
        if (is_word(t, "texture")) {
            const Texture tx = parse_texture_body(t);
            m_default_pigment = tx.pigment;
            m_default_finish = tx.finish;
            if (tx.normal.perturbs()) m_default_normal = tx.normal;
        } else if (is_word(t, "normal")) {
            m_default_normal = parse_normal_body(t);
        } else if (is_word(t, "pigment")) {
            m_default_pigment = parse_pigment_body(t);
        } else if (is_word(t, "finish")) {
            m_default_finish = parse_finish_body(t);
        } else if (t.kind == TokenKind::Identifier && is_unsupported_block(t.text)) {
            warn_unsupported(t, t.text);
            skip_block(t);
        } else {
            fail(t, "expected texture, pigment, normal or finish in #default but found '" + t.text + "'");
        }
    }
}

}  // namespace wardray::parser
