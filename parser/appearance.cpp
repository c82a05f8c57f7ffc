// Appearance: colours (with POV-Ray's promotion rules), pigments, finishes, textures and block skipping.
#include <cmath>

#include "parser/keywords.h"
#include "parser/parser.h"

namespace wardray::parser {

namespace {

double srgb_to_linear(double c) {
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

}  // namespace

bool Parser::is_color_keyword(const Token& t) const {
    if (t.kind != TokenKind::Identifier) return false;
    static const char* const words[] = {"color", "colour", "rgb", "rgbf", "rgbt", "rgbft", "srgb", "srgbf",
                                        "srgbt", "srgbft", "red", "green", "blue", "filter", "transmit"};
    for (const char* w : words)
        if (t.text == w) return true;
    return false;
}

Color Parser::parse_color() {
    Color c;
    bool any = false;
    while (true) {
        const Token t = any ? peek_expr() : peek();
        const std::string& w = t.text;
        if (t.kind == TokenKind::Identifier && (w == "color" || w == "colour")) {
            next();
            continue;
        }
        if (t.kind == TokenKind::Identifier && (w.rfind("rgb", 0) == 0 || w.rfind("srgb", 0) == 0) &&
            is_color_keyword(t)) {
            next();
            const bool srgb = w[0] == 's';
            const std::string form = srgb ? w.substr(1) : w;
            const int terms = form == "rgb" ? 3 : (form == "rgbft" ? 5 : 4);
            const Token at = peek();
            // POV-Ray compat: components beyond the keyword's count (a colour identifier after rgb) are ignored.
            const Numeric e = parse_numeric();
            // POV-Ray compat: `rgb 0.5` promotes the float to r, g and b only.
            const Numeric p = e.promoted(terms);
            c.r = p.v[0];
            c.g = p.v[1];
            c.b = p.v[2];
            if (srgb) {
                c.r = srgb_to_linear(c.r);
                c.g = srgb_to_linear(c.g);
                c.b = srgb_to_linear(c.b);
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

void Parser::skip_block(const Token& kw) {
    // Skips a balanced `{ ... }` (directives inside are still processed, as POV-Ray would).
    expect("{");
    const std::size_t depth = m_brace_depth;
    while (m_brace_depth >= depth) {
        const Token t = next();
        if (t.kind == TokenKind::EndOfFile) fail(kw, "'" + kw.text + "' block has no closing '}'");
    }
}

void Parser::skip_optional_block(const Token& kw) {
    if (is_punct(peek(), "{")) skip_block(kw);
}

Pigment Parser::parse_pigment_body(const Token& kw) {
    expect("{");
    const std::size_t depth = m_brace_depth;
    Pigment p = m_default_pigment;
    p.loc = make_diagnostic(Severity::Note, kw, "").loc;
    expand_macros();
    if (is_array_element_next()) {
        const Token at = peek();
        const Value element = *take_array_element();
        if (const auto* ep = std::get_if<Pigment>(&element)) p = *ep;
        else if (const auto* n = std::get_if<Numeric>(&element)) p.color = n->to_color();
        else fail(at, "this array element is not a pigment or colour");
    }
    const Token& first = peek();
    if (first.kind == TokenKind::Identifier) {
        if (const Value* v = lookup(first.text); v && std::holds_alternative<Pigment>(*v)) {
            next();
            p = std::get<Pigment>(*v);
        }
    }
    while (true) {
        expand_macros();
        const Token& t = peek();
        if (is_punct(t, "}")) {
            next();
            return p;
        }
        if (t.kind == TokenKind::Identifier && !is_color_keyword(t)) {
            Transform ignored;
            const Token item = t;
            if (parse_transform_item(item, ignored)) continue;  // no effect on a solid colour
            if (item.text == "quick_color" || item.text == "quick_colour") {
                next();
                parse_color();
                continue;
            }
            if (is_pattern_keyword(item.text) || is_unsupported_block(item.text)) {
                warn_unsupported(item, "pigment pattern '" + item.text + "'");
                // The rest of this pigment describes the pattern: skip it.
                while (m_brace_depth >= depth) {
                    if (next().kind == TokenKind::EndOfFile) fail(kw, "pigment block has no closing '}'");
                }
                return p;
            }
            const Value* v = lookup(item.text);
            if (v == nullptr && !is_keyword(item.text) && !m_macros.count(item.text)) fail_undeclared(item);
            if (v != nullptr && !std::holds_alternative<Numeric>(*v))
                fail(item, "'" + item.text + "' cannot be used in a pigment here");
        }
        p.color = parse_color();
    }
}

void Parser::parse_finish_item(Finish& f, const Token& item) {
    const std::string& w = item.text;
    auto scalar_with_albedo = [&]() {
        accept_keyword("albedo");
        return parse_float();
    };
    if (w == "ambient") {
        f.ambient = parse_color();
    } else if (w == "emission") {
        f.emission = parse_color();
    } else if (w == "diffuse") {
        f.diffuse = scalar_with_albedo();
        if (accept(",")) {
            parse_float();
            warn_unsupported(item, "diffuse backside value");
        }
    } else if (w == "brilliance") {
        f.brilliance = parse_float();
    } else if (w == "phong") {
        f.phong = scalar_with_albedo();
    } else if (w == "phong_size") {
        f.phong_size = parse_float();
    } else if (w == "specular") {
        f.specular = scalar_with_albedo();
    } else if (w == "roughness") {
        f.roughness = parse_float();
        if (f.roughness <= 0.0) fail(item, "roughness must be greater than 0");
    } else if (w == "reflection") {
        warn_unsupported(item, "reflection");
        if (is_punct(peek(), "{")) {
            skip_block(item);
        } else {
            parse_color();
            if (accept(",")) parse_color();
        }
    } else if (w == "metallic") {
        warn_unsupported(item, "metallic");
        parse_bool_optional();
    } else if (w == "conserve_energy") {
        warn_unsupported(item, "conserve_energy");
        parse_bool_optional();
    } else if (w == "crand" || w == "reflection_exponent") {
        warn_unsupported(item, w);
        parse_float();
    } else if (w == "irid" || w == "subsurface") {
        warn_unsupported(item, w);
        skip_block(item);
    } else {
        fail(item, "expected a finish item but found '" + w + "'");
    }
}

Finish Parser::parse_finish_body(const Token& kw) {
    expect("{");
    Finish f = m_default_finish;
    f.loc = make_diagnostic(Severity::Note, kw, "").loc;
    expand_macros();
    if (is_array_element_next()) {
        const Token at = peek();
        const Value element = *take_array_element();
        if (const auto* ef = std::get_if<Finish>(&element)) f = *ef;
        else fail(at, "this array element is not a finish");
    }
    const Token& first = peek();
    if (first.kind == TokenKind::Identifier) {
        if (const Value* v = lookup(first.text); v && std::holds_alternative<Finish>(*v)) {
            next();
            f = std::get<Finish>(*v);
        }
    }
    while (true) {
        const Token t = next();
        if (is_punct(t, "}")) return f;
        if (t.kind != TokenKind::Identifier) fail(t, "expected a finish item but found '" + t.text + "'");
        if (lookup(t.text) != nullptr) fail(t, "'" + t.text + "' must come first in the finish block");
        if (!is_keyword(t.text)) fail_undeclared(t);
        parse_finish_item(f, t);
    }
}

Texture Parser::parse_texture_body(const Token& kw) {
    expect("{");
    const std::size_t depth = m_brace_depth;
    Texture tx{m_default_pigment, m_default_finish};
    expand_macros();
    if (is_array_element_next()) {
        const Token at = peek();
        const Value element = *take_array_element();
        if (const auto* et = std::get_if<Texture>(&element)) tx = *et;
        else fail(at, "this array element is not a texture");
    }
    const Token& first = peek();
    if (first.kind == TokenKind::Identifier) {
        if (const Value* v = lookup(first.text); v && std::holds_alternative<Texture>(*v)) {
            next();
            tx = std::get<Texture>(*v);
        }
    }
    while (true) {
        expand_macros();
        const Token t = peek();
        Transform ignored;
        if (parse_transform_item(t, ignored)) continue;  // no effect on solid colours
        next();
        if (is_punct(t, "}")) return tx;
        if (t.kind != TokenKind::Identifier) fail(t, "expected a texture item but found '" + t.text + "'");
        if (t.text == "pigment") {
            tx.pigment = parse_pigment_body(t);
        } else if (t.text == "finish") {
            tx.finish = parse_finish_body(t);
        } else if (t.text == "normal") {
            warn_unsupported(t, "normal");
            skip_block(t);
        } else if (is_pattern_keyword(t.text)) {
            warn_unsupported(t, "texture pattern '" + t.text + "'");
            while (m_brace_depth >= depth) {
                if (next().kind == TokenKind::EndOfFile) fail(kw, "texture block has no closing '}'");
            }
            return tx;
        } else {
            if (!is_keyword(t.text) && lookup(t.text) == nullptr) fail_undeclared(t);
            fail(t, "expected pigment, finish, normal or a transform in texture but found '" + t.text + "'");
        }
    }
}

}  // namespace wardray::parser
