// Expressions: floats, vectors and colours with POV-Ray's precedence, constants and array elements.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <string_view>

#include "core/constants.h"
#include "parser/keyword_table.h"
#include "parser/keywords.h"
#include "parser/parser.h"

namespace wardray::parser {

namespace {

/// POV-Ray 3.7's `now`: the time in days (with a fraction) since 2000-01-01 00:00 UTC.
double days_since_2000() {
    using namespace std::chrono;
    const sys_days y2k = year{2000} / January / 1;
    const auto elapsed = duration_cast<microseconds>(system_clock::now() - y2k);
    return static_cast<double>(elapsed.count()) * 1e-6 / (24.0 * 60.0 * 60.0);
}

// POV-Ray compat: '=' and '!=' compare with this tolerance.
constexpr double k_epsilon = kPovEpsilon;  // POV-Ray's EPSILON

Numeric combine(const Numeric& a, const Numeric& b, double (*op)(double, double)) {
    const int n = std::max(a.n, b.n);
    const Numeric pa = a.promoted(n);
    const Numeric pb = b.promoted(n);
    Numeric r;
    r.n = n;
    for (int i = 0; i < n; ++i) r.v[i] = op(pa.v[i], pb.v[i]);
    return r;
}

}  // namespace

std::string describe_token(const Token& t) {
    switch (t.kind) {
        case TokenKind::EndOfFile: return "end of file";
        case TokenKind::String: return "string \"" + t.text + "\"";
        case TokenKind::Directive: return "'#" + t.text + "'";
        default: return "'" + t.text + "'";
    }
}

const char* value_kind_name(const Value& v) {
    // By position in Value: a new alternative must be named here (Deferred, last, is never shown).
    static_assert(std::variant_size_v<Value> == 21);
    switch (v.index()) {
        case 0: return "a number";
        case 1: return "a string";
        case 2: return "a pigment";
        case 3: return "a finish";
        case 4: return "a texture";
        case 5: return "an object";
        case 6: return "a transform";
        case 7: return "a camera";
        case 9: return "an array";
        case 10: return "a function";
        case 11: return "a file handle";
        case 12: return "an interior";
        case 13: return "a normal";
        case 14: return "a spline";
        case 15: return "a sky_sphere";
        case 16: return "a fog";
        case 17: return "a rainbow";
        case 18: return "a media";
        case 19: return "a material";
        default: return "an unsupported item";
    }
}

// ---------------------------------------------------------------------------------------------------------------
// Entry points

bool Evaluator::is_color_keyword(const Token& t) const {
    if (t.kind != TokenKind::Identifier) return false;
    static const char* const words[] = {"color", "colour", "rgb", "rgbf", "rgbt", "rgbft", "srgb", "srgbf",
                                        "srgbt", "srgbft", "red", "green", "blue", "filter", "transmit"};
    for (const char* w : words)
        if (t.text == w) return true;
    return false;
}

Value Evaluator::parse_rvalue() {
    const Token t = peek();
    const NestingGuard guard(*this, t);
    if (starts_string(t)) return parse_string();
    if (t.kind == TokenKind::Identifier) {
        const TokenText& w = t.text;
        if (const auto m = m_macros.find(w); m != m_macros.end()) {
            next();
            invoke_macro(t, m->second);
            return parse_rvalue();
        }
        if (std::optional<Value> item = parse_item_value(t)) return std::move(*item);
        if (w == "array") return parse_array_declaration(next());
        if (is_array_element_next()) {
            Value element = *take_array_element();
            const ScopedSetting numeric_level(m_directive_ends_value_at, m_brace_depth);
            if (const auto* n = std::get_if<Numeric>(&element)) return parse_additive(n);
            // An element of an array of functions followed by '(' is a call, the first operand of an expression.
            if (const auto* f = std::get_if<std::shared_ptr<const UserFunction>>(&element);
                f != nullptr && is_punct(peek(), "(")) {
                const std::shared_ptr<const UserFunction> keep = *f;
                const Numeric value = call_user_function(t, *keep);
                return parse_additive(&value);
            }
            return element;
        }
        if (w == "function") return parse_user_function(next());
        if (w == "spline") return parse_spline_body(next());
        if (is_unsupported_block(w)) {
            const Token kw = next();
            warn_unsupported(kw, w);
            skip_block(kw);
            return Unsupported{w};
        }
        if (const Value* v = lookup(w); v != nullptr && !std::holds_alternative<Numeric>(*v)) {
            // A function or spline followed by '(' is a call, read as an expression.
            const bool callable = std::holds_alternative<std::shared_ptr<const UserFunction>>(*v) ||
                                  std::holds_alternative<Boxed<Spline>>(*v);
            const bool call = callable && is_punct(m_files[m_file]->tokens[m_pos + 1], "(");
            if (!call) {
                next();
                return *v;
            }
        }
    }
    const ScopedSetting numeric_level(m_directive_ends_value_at, m_brace_depth);
    return parse_numeric();
}

// POV-Ray compat: outside parentheses '<' never compares, so `box { <0,0,0> <1,1,1> }` reads as two vectors
// (POV-Ray's documentation asks for parentheses around every relational, logical and conditional expression).
Numeric Evaluator::parse_numeric() { return parse_conditional(false); }

double Evaluator::parse_float() {
    const Token at = peek();
    const Numeric n = parse_numeric();
    if (n.n != 1) fail(at, "expected a float but found a vector");
    return n.v[0];
}

Vec3 Evaluator::parse_vector() {
    const Token at = peek();
    const Numeric n = parse_numeric();
    if (n.n > 3 && n.n != 5) fail(at, "expected a 3-component vector but found " + std::to_string(n.n) + " components");
    return n.vec3();
}

bool Evaluator::parse_bool_optional() {
    const Token& t = peek_expr();
    bool starts_value = t.kind == TokenKind::Number || is_punct(t, "(") || is_punct(t, "!");
    if (t.kind == TokenKind::Identifier) {
        static const char* const words[] = {"true", "false", "on", "off", "yes", "no"};
        for (const char* w : words) starts_value = starts_value || t.text == w;
        const Value* v = lookup(t.text);
        starts_value = starts_value || (v != nullptr && std::holds_alternative<Numeric>(*v));
    }
    if (!starts_value) return true;
    return parse_float() != 0.0;
}

// ---------------------------------------------------------------------------------------------------------------
// Precedence levels, lowest first: ?: , & | , relations , + - , * / , unary , postfix .x

Numeric Evaluator::parse_conditional(bool allow_less) {
    const Token at = peek();
    const std::uint64_t divisions_by_zero = m_divisions_by_zero;
    Numeric c = parse_logical(allow_less);
    if (!is_punct(peek_expr(), "?")) {
        // Every expression ends here: an infinity or NaN (1e999, pow(10, 400), 0 * 1e999) stops at its source
        // instead of reaching the renderer as a silently skipped object or a NaN pixel. A division by zero has
        // been warned about and goes on, as in POV-Ray.
        for (int i = 0; i < c.n && m_divisions_by_zero == divisions_by_zero; ++i)
            if (!std::isfinite(c.v[i]))
                fail(at, "this expression's value is not a finite number (it overflows or has no value)");
        return c;
    }
    next();
    if (c.n != 1) fail(at, "the condition of '?:' must be a float");
    Numeric a = parse_conditional(allow_less);
    expect(":");
    Numeric b = parse_conditional(allow_less);
    return c.v[0] != 0.0 ? a : b;
}

Numeric Evaluator::parse_logical(bool allow_less) {
    Numeric a = parse_relational(allow_less);
    while (true) {
        const Token& op = peek_expr();
        if (!is_punct(op, "&") && !is_punct(op, "|")) return a;
        const Token o = next();
        const Numeric b = parse_relational(allow_less);
        if (a.n != 1 || b.n != 1) fail(o, "'" + o.text + "' needs float operands");
        const bool x = a.v[0] != 0.0;
        const bool y = b.v[0] != 0.0;
        a = Numeric::scalar((o.text == "&" ? (x && y) : (x || y)) ? 1.0 : 0.0);
    }
}

Numeric Evaluator::parse_relational(bool allow_less) {
    if (starts_string(peek())) {
        // Strings compare with the same operators, lexicographically.
        const std::string x = parse_string();
        const Token o = next();
        const TokenText& s = o.text;
        if (o.kind != TokenKind::Punct || (s != "<" && s != "<=" && s != "=" && s != "!=" && s != ">=" && s != ">"))
            fail(o, "expected a comparison after a string but found " + describe_token(o));
        const int c = x.compare(parse_string());
        const bool r = s == "<" ? c < 0 : s == "<=" ? c <= 0 : s == "=" ? c == 0 : s == "!=" ? c != 0
                                                                                       : s == ">=" ? c >= 0 : c > 0;
        return Numeric::scalar(r ? 1.0 : 0.0);
    }
    Numeric a = parse_additive();
    while (true) {
        const Token& op = peek_expr();
        if (op.kind != TokenKind::Punct) return a;
        const TokenText& s = op.text;
        // Relational operators are '<' '<=' '=' '!=' '>=' '>': tell them by their characters, not by compares.
        const char c0 = s[0];
        if (!((c0 == '<' || c0 == '>' || c0 == '=') && (s.size() == 1 || s[1] == '=')) && s != "!=") return a;
        if (s == "<" && !allow_less) return a;
        const Token o = next();
        const Numeric b = parse_additive();
        if (a.n != 1 || b.n != 1) fail(o, "'" + o.text + "' needs float operands");
        const double x = a.v[0];
        const double y = b.v[0];
        bool r = false;
        if (s == "<") r = x < y;
        // POV-Ray compat: '<=' and '>=' are also true within the tolerance of '='.
        else if (s == "<=") r = x <= y || std::fabs(x - y) < k_epsilon;
        else if (s == "=") r = std::fabs(x - y) < k_epsilon;
        else if (s == "!=") r = std::fabs(x - y) >= k_epsilon;
        else if (s == ">=") r = x >= y || std::fabs(x - y) < k_epsilon;
        else r = x > y;
        a = Numeric::scalar(r ? 1.0 : 0.0);
    }
}

Numeric Evaluator::parse_additive(const Numeric* first) {
    Numeric a = parse_multiplicative(first);
    while (true) {
        const Token& op = peek_expr();
        if (!is_punct(op, "+") && !is_punct(op, "-")) return a;
        const bool plus = op.text == "+";
        next();
        const Numeric b = parse_multiplicative();
        a = combine(a, b, plus ? +[](double x, double y) { return x + y; } : +[](double x, double y) { return x - y; });
    }
}

Numeric Evaluator::parse_multiplicative(const Numeric* first) {
    Numeric a = parse_unary(first);
    while (true) {
        const Token& op = peek_expr();
        if (!is_punct(op, "*") && !is_punct(op, "/")) return a;
        const Token o = next();
        const Numeric b = parse_unary();
        if (o.text == "*") {
            a = combine(a, b, +[](double x, double y) { return x * y; });
        } else {
            const Numeric pb = b.promoted(std::max(a.n, b.n));
            bool by_zero = false;
            for (int i = 0; i < pb.n; ++i) by_zero |= pb.v[i] == 0.0;
            // POV-Ray compat: dividing by exactly zero warns and gives a huge positive value, whatever the sign.
            if (by_zero) {
                warn(o, "Divide by zero.");
                ++m_divisions_by_zero;
            }
            a = combine(a, b, +[](double x, double y) { return y == 0.0 ? HUGE_VAL : x / y; });
        }
    }
}

Numeric Evaluator::parse_unary(const Numeric* first) {
    if (first) return parse_postfix(first);
    const Token& t = peek();
    const NestingGuard guard(*this, t);
    if (is_punct(t, "-")) {
        next();
        Numeric a = parse_unary();
        for (int i = 0; i < a.n; ++i) a.v[i] = -a.v[i];
        return a;
    }
    if (is_punct(t, "+")) {
        next();
        return parse_unary();
    }
    if (is_punct(t, "!")) {
        const Token o = next();
        const Numeric a = parse_unary();
        if (a.n != 1) fail(o, "'!' needs a float operand");
        return Numeric::scalar(a.v[0] == 0.0 ? 1.0 : 0.0);
    }
    return parse_postfix();
}

Numeric Evaluator::parse_postfix(const Numeric* first) {
    Numeric a = first ? *first : parse_primary();
    while (is_punct(peek_expr(), ".")) {
        next();
        const Token item = expect_identifier();
        int index = -1;
        const TokenText& w = item.text;
        if (w == "x" || w == "u" || w == "red") index = 0;
        else if (w == "y" || w == "v" || w == "green") index = 1;
        else if (w == "z" || w == "blue") index = 2;
        else if (w == "t" || w == "filter") index = 3;
        else if (w == "transmit") index = 4;
        else if (w == "gray" || w == "grey") {
            const Numeric p = a.promoted(3);
            a = Numeric::scalar(0.297 * p.v[0] + 0.589 * p.v[1] + 0.114 * p.v[2]);
            continue;
        } else {
            fail(item, "unknown dot item '." + w + "'");
        }
        if (a.n != 1 && index >= a.n) fail(item, "'." + w + "' needs a vector with " + std::to_string(index + 1) +
                                                      " components but this one has " + std::to_string(a.n));
        a = Numeric::scalar(a.promoted(5).v[index]);
    }
    return a;
}

std::optional<Numeric> Evaluator::builtin_constant(const Token& t) {
    using Constant = Numeric (*)(const Evaluator&);
    auto one = [](const Evaluator&) { return Numeric::scalar(1.0); };
    auto zero = [](const Evaluator&) { return Numeric::scalar(0.0); };
    static const KeywordTable<Constant> constants = {
        {"pi", [](const Evaluator&) { return Numeric::scalar(std::numbers::pi); }},
        // tau (2 pi) is POV-Ray 3.8's; 3.7 does not reserve the word, so a scene's own tau is found first.
        {"tau", [](const Evaluator&) { return Numeric::scalar(2.0 * std::numbers::pi); }},
        {"true", one},
        {"yes", one},
        {"on", one},
        {"false", zero},
        {"no", zero},
        {"off", zero},
        {"x", [](const Evaluator&) { return Numeric::vector3({1, 0, 0}); }},
        {"y", [](const Evaluator&) { return Numeric::vector3({0, 1, 0}); }},
        {"z", [](const Evaluator&) { return Numeric::vector3({0, 0, 1}); }},
        {"t",
         [](const Evaluator&) {
             Numeric r;
             r.n = 4;
             r.v = {0, 0, 0, 1, 0};
             return r;
         }},
        {"u",
         [](const Evaluator&) {
             Numeric r;
             r.n = 2;
             r.v = {1.0, 0.0, 0, 0, 0};
             return r;
         }},
        {"v",
         [](const Evaluator&) {
             Numeric r;
             r.n = 2;
             r.v = {0.0, 1.0, 0, 0, 0};
             return r;
         }},
        // POV-Ray compat: a still image has all of these 0 but clock (+K); the app fills them in per frame.
        {"clock", [](const Evaluator& e) { return Numeric::scalar(e.m_options.animation.clock); }},
        {"clock_delta", [](const Evaluator& e) { return Numeric::scalar(e.m_options.animation.clock_delta); }},
        {"clock_on", [](const Evaluator& e) { return Numeric::scalar(e.m_options.animation.clock_on ? 1.0 : 0.0); }},
        {"frame_number", [](const Evaluator& e) { return Numeric::scalar(e.m_options.animation.frame_number); }},
        {"initial_frame", [](const Evaluator& e) { return Numeric::scalar(e.m_options.animation.initial_frame); }},
        {"final_frame", [](const Evaluator& e) { return Numeric::scalar(e.m_options.animation.final_frame); }},
        {"initial_clock", [](const Evaluator& e) { return Numeric::scalar(e.m_options.animation.initial_clock); }},
        {"final_clock", [](const Evaluator& e) { return Numeric::scalar(e.m_options.animation.final_clock); }},
        {"image_width", [](const Evaluator& e) { return Numeric::scalar(e.m_options.image_width); }},
        {"image_height", [](const Evaluator& e) { return Numeric::scalar(e.m_options.image_height); }},
        {"version", [](const Evaluator& e) { return Numeric::scalar(e.m_version); }},
        {"now", [](const Evaluator&) { return Numeric::scalar(days_since_2000()); }},
    };
    if (const Constant* constant = constants.find(t.text)) return (*constant)(*this);
    return std::nullopt;
}

Numeric Evaluator::parse_primary() {
    // Inside an operand directives run as they come (`(M(0)) + 1` with M's body in #if ... #else ... #end).
    ScopedSetting operand(m_directive_ends_value_at, k_directives_run);
    const Token t = peek();
    if (t.kind == TokenKind::Number) {
        next();
        return Numeric::scalar(t.number());
    }
    if (is_punct(t, "(")) {
        next();
        Numeric a = parse_conditional(true);
        expect(")");
        return a;
    }
    if (is_punct(t, "<")) {
        next();
        Numeric r;
        r.n = 0;
        while (true) {
            const Token at = peek();
            const Numeric c = parse_additive();
            if (c.n != 1) fail(at, "a vector component must be a float");
            if (r.n == 5) fail(at, "a vector has at most 5 components");
            r.v[r.n++] = c.v[0];
            // POV-Ray compat: the commas between components are optional.
            accept(",");
            if (accept(">")) break;
            if (peek().kind == TokenKind::EndOfFile) expect(">");
        }
        if (r.n < 2) fail(t, "a vector needs at least 2 components");
        return r;
    }
    if (t.kind != TokenKind::Identifier) fail(t, "expected a float or vector expression but found " + describe_token(t));

    if (const Value* v = lookup(t.text); v != nullptr && (m_macros.empty() || !m_macros.count(t.text))) {
        if (const auto* n = std::get_if<Numeric>(v)) {
            next();
            return *n;
        }
    }
    if (is_color_keyword(t)) return Numeric::color(parse_color());
    if (auto c = builtin_constant(t)) {
        next();
        return *c;
    }
    if (const auto m = m_macros.find(t.text); m != m_macros.end()) {
        next();
        invoke_macro(t, m->second);
        operand.restore();  // the body's first token is the operand; what follows it is at the caller's level
        return parse_unary();
    }
    if (auto element = take_array_element()) {
        if (const auto* n = std::get_if<Numeric>(&*element)) return *n;
        // POV-Ray compat: an array of functions is called element by element, `F[i](x, y)`.
        if (const auto* f = std::get_if<std::shared_ptr<const UserFunction>>(&*element)) {
            const std::shared_ptr<const UserFunction> keep = *f;
            return call_user_function(t, *keep);
        }
        fail(t, "expected a float or vector but this element of '" + t.text + "' is " + value_kind_name(*element));
    }
    if (const Value* v = lookup(t.text)) {
        next();
        if (const auto* n = std::get_if<Numeric>(v)) return *n;
        if (const auto* f = std::get_if<std::shared_ptr<const UserFunction>>(v)) {
            const std::shared_ptr<const UserFunction> keep = *f;
            return call_user_function(t, *keep);
        }
        if (const auto* s = std::get_if<Boxed<Spline>>(v)) {
            const Boxed<Spline> keep = *s;  // the call's arguments may end the scope that holds it
            return call_spline(t, *keep);
        }
        if (const auto* u = std::get_if<Unsupported>(v))
            fail(t, "'" + t.text + "' is a " + u->what + ", which is not supported yet");
        fail(t, "expected a float or vector but '" + t.text + "' is " + value_kind_name(*v));
    }
    if (is_keyword(t.text)) {
        next();
        return parse_function(t);
    }
    fail_undeclared(t);
}

}  // namespace wardray::parser
