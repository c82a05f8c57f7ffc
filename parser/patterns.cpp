// Patterns: pattern keywords and modifiers, colour/pigment/normal maps, and the pigment and normal blocks.
#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include "parser/keywords.h"
#include "parser/parser.h"

namespace wardray::parser {

namespace {

using PType = Pattern::Type;

ColorMapEntry entry(double v, double r, double g, double b) { return {v, Color{r, g, b, 0.0, 0.0}}; }

// POV-Ray compat: map positions (and frequency, phase, poly_wave's exponent, bump_size, accuracy) are
// single-precision floats in POV-Ray.
double map_value(double v) { return static_cast<double>(static_cast<float>(v)); }

std::vector<ColorMapEntry> default_color_map(Pattern::Type type) {
    // POV-Ray 3.7's built-in maps for a pattern pigment without a map of its own.
    switch (type) {
        case PType::Bozo:
            return {entry(0.4, 1, 1, 1), entry(0.4, 0, 1, 0), entry(0.6, 0, 1, 0),
                    entry(0.6, 0, 0, 1), entry(0.8, 0, 0, 1), entry(0.8, 1, 0, 0)};
        case PType::Brick:
            return {entry(0.0, 0.5, 0.5, 0.5), entry(1.0, 0.6, 0.15, 0.15)};
        case PType::Wood:
            return {entry(0.6, 0.666, 0.312, 0.2), entry(0.6, 0.4, 0.1333, 0.066)};
        case PType::Radial:
            return {entry(0.0, 0, 1, 1), entry(0.333, 1, 1, 0), entry(0.666, 1, 0, 1), entry(1.0, 0, 1, 1)};
        case PType::Agate:
            return {entry(0.0, 1, 1, 1),       entry(0.5, 0.95, 0.75, 0.5), entry(0.5, 0.9, 0.7, 0.5),
                    entry(0.6, 0.9, 0.7, 0.4), entry(0.6, 1.0, 0.7, 0.4),   entry(1.0, 0.6, 0.3, 0.0)};
        case PType::Marble:
            return {entry(0.0, 0.9, 0.8, 0.8), entry(0.9, 0.9, 0.08, 0.08), entry(0.9, 0, 0, 0)};
        case PType::Mandel:  // not julia or magnet: those take the grey ramp
            return {entry(0.001, 0, 0, 0), entry(0.001, 0, 1, 1), entry(0.012, 1, 1, 0),
                    entry(0.015, 1, 0, 1), entry(0.1, 0, 1, 1)};
        case PType::Hexagon:
            return {entry(0.0, 0, 0, 1), entry(1.0, 0, 1, 0), entry(2.0, 1, 0, 0)};
        case PType::Square:
        case PType::Triangular:
        case PType::Cubic:
            // POV-Ray compat: all three take cubic's six colours (square the first four).
            return {entry(0, 1, 0, 0), entry(1, 0, 1, 0), entry(2, 0, 0, 1),
                    entry(3, 1, 1, 0), entry(4, 0, 1, 1), entry(5, 1, 0, 1)};
        case PType::Checker:
        case PType::Object:
            // POV-Ray compat: checker (and object) take the first two of hexagon's colours.
            return {entry(0.0, 0, 0, 1), entry(1.0, 0, 1, 0)};
        default:
            return {entry(0.0, 0, 0, 0), entry(1.0, 1, 1, 1)};
    }
}

}  // namespace

bool Parser::starts_value(const Token& t) {
    if (t.kind == TokenKind::Number) return true;
    if (is_punct(t, "<") || is_punct(t, "(") || is_punct(t, "-") || is_punct(t, "+")) return true;
    if (t.kind != TokenKind::Identifier) return false;
    if (is_color_keyword(t)) return true;
    // The float constants (`metallic on` in diffract.pov); x, y, z, u, v and t would be read as keywords here.
    static const char* const constants[] = {"on", "off", "true", "false", "yes", "no", "pi"};
    for (const char* c : constants)
        if (t.text == c) return true;
    const Value* v = lookup(t.text);
    return v != nullptr && std::holds_alternative<Numeric>(*v);
}

void Parser::skip_to_close(const Token& kw, const char* close, std::size_t depth) {
    while (true) {
        const Token& t = peek();
        if (t.kind == TokenKind::EndOfFile) fail(kw, "'" + kw.text + "' has no closing '" + close + "'");
        const bool ours = m_brace_depth == depth && is_punct(t, close);
        next();
        if (ours) return;
    }
}

int Parser::parse_pattern_keyword(const Token& t, Pattern& pat) {
    if (t.kind != TokenKind::Identifier) return -1;
    // The patterns of WARDRAY_PATTERNS (scene/texture.h); the switch below reads their own parameters.
    const std::optional<PType> found = find_kind(k_pattern_keywords, t.text.view());
    if (!found) return -1;
    next();
    const PType previous = pat.type;
    pat.type = *found;
    switch (pat.type) {
        case PType::Gradient:
            pat.params->gradient = normalize(parse_vector());
            break;
        case PType::Function: {
            const std::shared_ptr<const UserFunction> f = parse_user_function(t);
            if (f->kind != UserFunction::Kind::Float || !f->program) fail(t, "a function pattern needs a float function");
            if (!f->program->unsupported().empty()) warn(t, "pattern function is not rendered yet: " + f->program->unsupported());
            pat.params->function = f->program;
            break;
        }
        case PType::Marble:
        case PType::Wood:
            pat.params->wave = WaveType::Triangle;
            break;
        case PType::Agate:
            // POV-Ray compat: agate always carries turbulence parameters (its amount stays 0 unless given).
            if (!pat.params->turbulence) pat.params->turbulence = Turbulence{};
            pat.params->agate_turb = 1.0;
            break;
        case PType::Crackle:
            pat.params->crackle_form = {-1.0, 1.0, 0.0};
            pat.params->crackle_metric = 2.0;
            pat.params->crackle_offset = 0.0;
            pat.params->crackle_solid = false;
            break;
        case PType::Facets:
            pat.params->facets_size = 0.1;
            pat.params->facets_coords = 0.0;
            pat.params->crackle_metric = 2.0;
            break;
        case PType::Checker:
            pat.params->frequency = 0.0;
            return 2;
        case PType::Object:
            // `object { OBJECT a, b }`: the list of the two comes inside the braces, which the
            // caller closes after it (take_pattern_list_open).
            expect("{");
            pat.params->object = std::make_shared<const Object>(parse_pattern_object(t));
            pat.params->frequency = 0.0;
            m_pattern_list_open = true;
            return 2;
        case PType::Hexagon:
            pat.params->frequency = 0.0;
            return 3;
        case PType::Square:
            pat.params->frequency = 0.0;
            return 4;
        case PType::Triangular:
        case PType::Cubic:
            pat.params->frequency = 0.0;
            return 6;
        case PType::Brick:
            if (previous != PType::Brick) {
                pat.params->brick_size = {8.0, 3.0, 4.5};
                pat.params->mortar = 0.5;
            }
            pat.params->frequency = 0.0;
            return 2;
        default:
            return parse_pattern_parameters(t, pat);
    }
    return 0;
}

bool Parser::take_pattern_list_open() { return std::exchange(m_pattern_list_open, false); }

Object Parser::parse_pattern_object(const Token& kw) {
    // POV-Ray's Parse_Bound_Clip: the objects, transforms after them moving all; the pattern takes one.
    std::vector<Object> list;
    while (true) {
        expand_macros();
        Transform tr;
        if (!list.empty() && parse_transform_item(peek(), tr)) {
            for (Object& o : list) o.transform = o.transform.then(tr);
            continue;
        }
        if (!is_object_start(peek())) break;
        const Token t = next();
        ObjectValue child = parse_object(t);
        if (auto o = as_single_object(child)) list.push_back(std::move(*o));
    }
    if (list.size() != 1) fail(kw, "object or object identifier expected.");
    return std::move(list.front());
}

bool Parser::parse_pattern_modifier(const Token& t, Pattern& pat) {
    if (t.kind != TokenKind::Identifier) return false;
    Transform tr;
    if (parse_transform_item(t, tr)) {
        pat.transform = pat.transform.then(tr);
        return true;
    }
    if (parse_pavement_modifier(t, pat)) return true;
    const std::string w = t.text;
    auto turb = [&]() -> Turbulence& {
        if (!pat.params->turbulence) pat.params->turbulence = Turbulence{};
        return *pat.params->turbulence;
    };
    static const std::pair<const char*, WaveType> waves[] = {
        {"ramp_wave", WaveType::Ramp},       {"triangle_wave", WaveType::Triangle}, {"sine_wave", WaveType::Sine},
        {"scallop_wave", WaveType::Scallop}, {"cubic_wave", WaveType::Cubic},       {"poly_wave", WaveType::Poly}};
    for (const auto& [name, wave] : waves) {
        if (w != name) continue;
        next();
        pat.params->wave = wave;
        if (wave == WaveType::Poly && starts_value(peek())) pat.params->exponent = map_value(parse_float());
        return true;
    }
    if (w == "turbulence") {
        next();
        turb().amount = parse_vector();
    } else if (w == "octaves") {
        next();
        // POV-Ray compat: octaves are clamped to 1..10.
        turb().octaves = std::clamp(static_cast<int>(parse_float()), 1, 10);
    } else if (w == "omega") {
        next();
        turb().omega = static_cast<float>(parse_float());  // POV-Ray compat: single precision
    } else if (w == "lambda") {
        next();
        turb().lambda = static_cast<float>(parse_float());
    } else if (w == "frequency") {
        next();
        pat.params->frequency = map_value(parse_float());  // POV-Ray compat: frequency and phase are single precision
    } else if (w == "phase") {
        next();
        pat.params->phase = map_value(parse_float());
    } else if (w == "noise_generator") {
        next();
        const int g = static_cast<int>(parse_float());
        if (g < 0 || g > 3) fail(t, "noise_generator must be 0, 1, 2 or 3");
        pat.params->noise_generator = g;
    } else if (w == "agate_turb") {
        next();
        pat.params->agate_turb = parse_float();
        turb();
    } else if (w == "brick_size") {
        next();
        pat.params->brick_size = parse_vector();
    } else if (w == "mortar") {
        next();
        pat.params->mortar = parse_float();
    } else if (w == "form") {
        next();
        pat.params->crackle_form = parse_vector();
    } else if (w == "metric") {
        next();
        // POV-Ray compat: the metric is the first component of a vector.
        pat.params->crackle_metric = parse_vector().x;
    } else if (w == "size" && pat.type == PType::Facets) {
        next();
        pat.params->facets_size = parse_float();
    } else if (w == "coords" && pat.type == PType::Facets) {
        next();
        pat.params->facets_coords = parse_float();
    } else if (w == "offset") {
        next();
        pat.params->crackle_offset = parse_float();
    } else if (w == "solid") {
        next();
        pat.params->crackle_solid = true;
    } else if (w == "no_bump_scale") {
        next();
        pat.no_bump_scale = true;
    } else if (parse_pattern_extra(t, pat)) {
        return true;
    } else {
        return false;
    }
    return true;
}

std::vector<ColorMapEntry> Parser::parse_color_map(const Token& kw) {
    expect("{");
    std::vector<ColorMapEntry> map;
    while (true) {
        expand_macros();
        const Token t = next();
        if (is_punct(t, "}")) break;
        if (t.kind == TokenKind::Identifier && map.empty()) {
            // A declared colour map arrives as a pigment holding only its map.
            const Value* v = lookup(t.text);
            if (v == nullptr) fail_undeclared(t);
            if (const auto* p = std::get_if<Boxed<Pigment>>(v); p && !(*p)->color_map.empty()) {
                map = (*p)->color_map;
                expect("}");
                return map;
            }
            if (!std::holds_alternative<Unsupported>(*v)) fail(t, "'" + t.text + "' is not a color_map");
            skip_to_close(kw, "}", m_brace_depth);
            return default_color_map(PType::None);
        }
        if (!is_punct(t, "[")) fail(t, "expected '[' or '}' in " + kw.text + " but found " + describe_token(t));
        const double value = parse_float();
        accept(",");
        if (is_color_keyword(peek())) {
            map.push_back({map_value(value), parse_color()});
        } else {
            const Token at = peek();
            const Numeric e = parse_numeric();
            if (e.n == 1) {
                // POV-Ray's old form: [from, to colour1 colour2] spans an interval.
                accept(",");
                const Color from = parse_color();
                if (!accept_keyword("color")) accept_keyword("colour");
                const Color to = parse_color();
                map.push_back({map_value(value), from});
                map.push_back({map_value(e.v[0]), to});
            } else {
                if (e.n > 5) fail(at, "a colour has at most 5 components");
                // POV-Ray compat: the expression may be followed by colour items (`[0.5 Red filter 0.5]`).
                map.push_back({map_value(value), parse_color_modifiers(e.to_color())});
            }
        }
        expect("]");
    }
    if (map.empty()) fail(kw, "a color_map must have at least one entry");
    return map;
}

bool Parser::parse_pigment_start(Pigment& p) {
    expand_macros();
    // An element of an array of colours starts a colour expression (`pigment { Colors[i] * 0.5 }`, isocacti.pov
    // through arrays.inc's Rand_Array_Item): the colour reader takes it whole.
    if (is_array_element_next() && !is_colour_array_next()) {
        const Token at = peek();
        const Value element = *take_array_element();
        if (const auto* ep = std::get_if<Boxed<Pigment>>(&element)) p = **ep;
        else if (const auto* n = std::get_if<Numeric>(&element)) p.color = n->to_color();
        else fail(at, "this array element is not a pigment or colour");
        return true;
    }
    const Token& first = peek();
    if (first.kind == TokenKind::Identifier) {
        if (const Value* v = lookup(first.text); v && std::holds_alternative<Boxed<Pigment>>(*v)) {
            next();
            const SourceLoc loc = p.loc;
            p = *std::get<Boxed<Pigment>>(*v);
            p.loc = loc;
            return true;
        }
    }
    return false;
}

bool Parser::is_colour_array_next() {
    const Value* v = lookup(peek().text);
    const auto& array = std::get<std::shared_ptr<ArrayValue>>(*v);
    for (const auto& e : array->elements)
        if (e) return std::holds_alternative<Numeric>(*e);
    return false;
}

Pigment Parser::parse_pigment_body(const Token& kw, const Pigment* base) {
    // POV-Ray's Parse_Pigment modifies the pigment in place: with `base` (the pigment of a texture being
    // modified, `texture { T_Stone1 pigment { octaves 3 } }`) the items change it, else the default pigment.
    expect("{");
    Pigment p = base ? *base : m_default_pigment;
    p.loc = make_diagnostic(Severity::Note, kw, "").loc;
    parse_pigment_start(p);
    parse_pigment_items(p, kw, "}");
    return p;
}

void Parser::parse_pigment_list(Pigment& p, int count) {
    // `checker A, B` / `hexagon A, B, C` / `brick A, B`: colours or pigments at values 0, 1, 2; missing ones
    // come from the pattern's default map.
    std::vector<ColorMapEntry> defaults = default_color_map(p.pattern.type);
    p.color_map.clear();
    p.pigment_map.clear();
    // POV-Ray compat: a macro call may stand for an entry (`hexagon M(1), M(2), M(3)` with M giving a pigment).
    expand_macros();
    if (is_word(peek(), "pigment")) {
        for (int i = 0; i < count && is_word(peek(), "pigment"); ++i) {
            const Token kw = next();
            p.pigment_map.push_back({static_cast<double>(i), parse_pigment_body(kw)});
            accept(",");
            expand_macros();
        }
        for (int i = static_cast<int>(p.pigment_map.size()); i < count; ++i) {
            Pigment fill = m_default_pigment;
            p.pigment_map.push_back({static_cast<double>(i), fill});
        }
        return;
    }
    for (int i = 0; i < count && starts_value(peek()); ++i) {
        p.color_map.push_back({static_cast<double>(i), parse_color()});
        accept(",");
    }
    // POV-Ray compat (Parse_Blend_List): a missing entry takes the default map's colour at value i.
    for (int i = static_cast<int>(p.color_map.size()); i < count; ++i)
        p.color_map.push_back({static_cast<double>(i), defaults[i].color});
}

void Parser::parse_pigment_items(Pigment& p, const Token& kw, const char* close) {
    const std::size_t depth = m_brace_depth;
    while (true) {
        expand_macros();
        const Token t = peek();
        if (is_punct(t, close)) {
            next();
            break;
        }
        if (t.kind == TokenKind::EndOfFile) fail(kw, "'" + kw.text + "' has no closing '" + close + "'");
        if (is_word(t, "uv_mapping")) {
            // POV-Ray compat: the rest of the pigment is evaluated at the surface's (u, v, 0). It is a pigment
            // of its own (Parse_Item_Into_Blend_List), so it may start with a pigment identifier
            // (`pigment { uv_mapping Declared }`).
            next();
            parse_pigment_start(p);
            p.uv_mapping = true;
            continue;
        }
        if (t.kind == TokenKind::Identifier && !is_color_keyword(t)) {
            const int count = parse_pattern_keyword(t, p.pattern);
            const bool list_inside = take_pattern_list_open();
            if (p.pattern.type == PType::Facets) fail(t, "Keyword 'facets' can only be used in a normal statement.");
            if (count > 0) parse_pigment_list(p, count);
            if (list_inside) expect("}");
            if (count >= 0 || parse_pattern_modifier(t, p.pattern)) continue;
            if (t.text == "color_map" || t.text == "colour_map") {
                next();
                p.color_map = parse_color_map(t);
                p.pigment_map.clear();
                continue;
            }
            // POV-Ray compat: a density's density_map is its pigment_map (entries are densities).
            if (t.text == "pigment_map" || t.text == "density_map") {
                next();
                p.pigment_map = parse_pigment_map(t, p.pattern.type == PType::Average);
                p.color_map.clear();
                continue;
            }
            if (t.text == "quick_color" || t.text == "quick_colour") {
                next();
                p.quick_color = parse_color();
                continue;
            }
            if (t.text == "image_map") {
                next();
                parse_image_map(t, p);
                continue;
            }
            if (is_pattern_keyword(t.text) || is_unsupported_block(t.text)) {
                warn_unsupported(t, "pigment pattern '" + t.text + "'");
                // The rest of this pigment describes the pattern: skip it and keep the solid colour.
                p.pattern = Pattern{};
                p.color_map.clear();
                p.pigment_map.clear();
                skip_to_close(kw, close, depth);
                return;
            }
            const Value* v = lookup(t.text);
            if (v == nullptr && !is_keyword(t.text) && !m_macros.count(t.text)) fail_undeclared(t);
            const bool colour_element = v != nullptr && is_array_element_next() && is_colour_array_next();
            if (v != nullptr && !std::holds_alternative<Numeric>(*v) && !colour_element)
                fail(t, "'" + t.text + "' cannot be used in a pigment here");
        }
        p.color = parse_color();
        p.pattern.type = PType::None;
    }
    check_pavement(kw, p.pattern);
    if (!p.is_solid() && !p.image_map && p.color_map.empty() && p.pigment_map.empty()) {
        // POV-Ray compat: a mandel with an exponent above 2 is another pattern type there (MANDEL3/4/X_PATTERN),
        // which takes the grey ramp, not mandel's own map.
        const bool other_mandel = p.pattern.type == PType::Mandel && p.pattern.params->fractal_exponent != 2;
        p.color_map = default_color_map(other_mandel ? PType::None : p.pattern.type);
    }
}

std::vector<PigmentMapEntry> Parser::parse_pigment_map(const Token& kw, bool optional_values) {
    expect("{");
    std::vector<PigmentMapEntry> map;
    while (true) {
        expand_macros();
        const Token t = next();
        if (is_punct(t, "}")) break;
        if (!is_punct(t, "[")) fail(t, "expected '[' or '}' in pigment_map but found " + describe_token(t));
        PigmentMapEntry e;
        // POV-Ray compat: an average map's weights may be left out (1 each).
        e.value = optional_values && !starts_value(peek()) ? 1.0 : map_value(parse_float());
        accept(",");
        e.pigment = m_default_pigment;
        e.pigment.loc = make_diagnostic(Severity::Note, t, "").loc;
        parse_pigment_start(e.pigment);
        parse_pigment_items(e.pigment, kw, "]");
        map.push_back(std::move(e));
    }
    if (map.empty()) fail(kw, "a pigment_map must have at least one entry");
    return map;
}

Normal Parser::parse_normal_body(const Token& kw, const Normal* base) {
    // In place like the pigment (POV-Ray's Parse_Tnormal), from `base` when it is a normal. A texture without one
    // has none in POV-Ray (a null Tnormal), so the transforms its object went through do not reach a new normal.
    expect("{");
    Normal n = base && base->perturbs() ? *base : default_normal();
    n.loc = make_diagnostic(Severity::Note, kw, "").loc;
    parse_normal_start(n);
    parse_normal_items(n, kw, "}");
    return n;
}

void Parser::parse_normal_start(Normal& n) {
    expand_macros();
    const Token& first = peek();
    if (first.kind == TokenKind::Identifier) {
        // A declared normal, or an element of an array of them (allnormals.pov), then modifiers.
        const Token at = first;
        std::optional<Value> declared;
        if (is_array_element_next()) {
            declared = take_array_element();
            if (!declared) fail(at, "this array element is empty");
        } else if (const Value* v = lookup(at.text); v && std::holds_alternative<Boxed<Normal>>(*v)) {
            declared = *v;
            next();
        }
        if (declared) {
            const auto* normal = std::get_if<Boxed<Normal>>(&*declared);
            if (normal == nullptr) fail(at, "expected a normal but found " + std::string(value_kind_name(*declared)));
            const SourceLoc loc = n.loc;
            n = **normal;
            n.loc = loc;
        }
    }
}

void Parser::parse_normal_items(Normal& n, const Token& kw, const char* close) {
    const std::size_t depth = m_brace_depth;
    while (true) {
        expand_macros();
        const Token t = peek();
        if (is_punct(t, close)) {
            next();
            check_pavement(kw, n.pattern);
            return;
        }
        if (t.kind != TokenKind::Identifier) fail(t, "expected a normal item but found " + describe_token(t));
        if (is_word(t, "uv_mapping")) {
            // As in a pigment: the rest is a normal of its own, which may start with a normal identifier.
            next();
            parse_normal_start(n);
            n.uv_mapping = true;
            continue;
        }
        const int count = parse_pattern_keyword(t, n.pattern);
        const bool list_inside = take_pattern_list_open();
        if (count >= 0) {
            for (int i = 0; i < count && is_word(peek(), "normal"); ++i) {
                const Token nkw = next();
                n.normal_map.push_back({static_cast<double>(i), parse_normal_body(nkw)});
                accept(",");
            }
            if (list_inside) expect("}");
            // POV-Ray compat: an optional bump amount follows the pattern.
            accept(",");
            if (starts_value(peek())) n.amount = map_value(parse_float());
            continue;
        }
        if (parse_pattern_modifier(t, n.pattern)) continue;
        next();
        if (t.text == "bump_size") {
            n.amount = map_value(parse_float());  // POV-Ray compat: bump_size and accuracy are single precision
        } else if (t.text == "accuracy") {
            n.delta = map_value(parse_float());
        } else if (t.text == "normal_map") {
            expect("{");
            n.normal_map.clear();
            n.slope_map.clear();
            while (!accept("}")) {
                const Token open = expect("[");
                NormalMapEntry e;
                // POV-Ray compat (Parse_Blend_Map): an entry starts from the #default normal.
                e.normal = default_normal();
                const bool weighted = n.pattern.type != PType::Average || starts_value(peek());
                e.value = weighted ? map_value(parse_float()) : 1.0;
                accept(",");
                // POV-Ray compat: an entry is a normal's body, so it may start with a normal identifier.
                parse_normal_start(e.normal);
                parse_normal_items(e.normal, open, "]");
                n.normal_map.push_back(std::move(e));
            }
        } else if (t.text == "slope_map") {
            n.slope_map = parse_slope_map();
            n.normal_map.clear();
        } else if (t.text == "bump_map") {
            parse_bump_map(t, n);
        } else if (is_pattern_keyword(t.text) || is_unsupported_block(t.text)) {
            warn_unsupported(t, "normal pattern '" + t.text + "'");
            n = Normal{};
            skip_to_close(kw, close, depth);
            return;
        } else {
            if (!is_keyword(t.text) && lookup(t.text) == nullptr) fail_undeclared(t);
            fail(t, "expected a normal pattern or modifier but found '" + t.text + "'");
        }
    }
}

}  // namespace wardray::parser
