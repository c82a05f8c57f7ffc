// Built-in functions: the float, vector and string functions of the scene language.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>

#include "parser/parser.h"
#include "parser/trace_sensitivity.h"

namespace wardray::parser {

namespace {

// Rotation of v about a unit axis by `degrees`, with the same handedness as POV-Ray's rotate.
Vec3 axis_rotate(const Vec3& v, const Vec3& axis, double degrees) {
    const Vec3 k = normalize(axis);
    const double a = degrees * std::numbers::pi / 180.0;
    const double c = std::cos(a);
    const double s = std::sin(a);
    return v * c + cross(k, v) * s + k * (dot(k, v) * (1.0 - c));
}

// POV-Ray's str(A, L, P): minimum length |L| padded with blanks (L > 0) or zeros (L < 0); P digits after the
// point, or the default precision when P is negative.
std::string format_str(double value, int min_length, int precision) {
    const int width = std::clamp(std::abs(min_length), 0, 64);
    const int digits = precision < 0 ? 6 : std::clamp(precision, 0, 32);
    char buf[160];
    if (min_length < 0)
        std::snprintf(buf, sizeof buf, "%0*.*f", width, digits, value);
    else
        std::snprintf(buf, sizeof buf, "%*.*f", width, digits, value);
    return buf;
}

}  // namespace

std::string Evaluator::parse_string() {
    const NestingGuard guard(*this, peek());
    const Token t = next();
    if (t.kind == TokenKind::String) return t.text;
    if (t.kind != TokenKind::Identifier) fail(t, "expected a string but found " + describe_token(t));
    const TokenText& w = t.text;
    if (w == "concat") {
        expect("(");
        std::string s = parse_string();
        while (accept(",")) {
            s += parse_string();
            if (s.size() > m_options.max_string_length)
                fail(t, "string longer than the limit of " + std::to_string(m_options.max_string_length) +
                            " characters; raise it with --max-string-length");
        }
        expect(")");
        return s;
    }
    if (w == "str") {
        expect("(");
        const double value = parse_float();
        expect(",");
        const int width = static_cast<int>(parse_float());
        expect(",");
        const int precision = static_cast<int>(parse_float());
        expect(")");
        return format_str(value, width, precision);
    }
    if (w == "vstr") {
        // vstr(N, V, separator, width, precision): N components of V, each as str() would write it.
        expect("(");
        const int n = static_cast<int>(parse_float());
        expect(",");
        const Numeric v = parse_numeric().promoted(5);
        expect(",");
        const std::string sep = parse_string();
        expect(",");
        const int width = static_cast<int>(parse_float());
        expect(",");
        const int precision = static_cast<int>(parse_float());
        expect(")");
        std::string s;
        for (int i = 0; i < std::clamp(n, 0, 5); ++i) s += (i > 0 ? sep : std::string()) + format_str(v.v[i], width, precision);
        return s;
    }
    if (w == "chr") {
        expect("(");
        const double c = parse_float();
        expect(")");
        return std::string(1, static_cast<char>(static_cast<int>(c)));
    }
    if (w == "substr") {
        expect("(");
        const std::string s = parse_string();
        expect(",");
        const double start = parse_float();
        expect(",");
        const double len = parse_float();
        expect(")");
        if (start < 1 || len < 0 || start - 1 + len > static_cast<double>(s.size()))
            fail(t, "substr range is outside the string");
        return s.substr(static_cast<std::size_t>(start - 1), static_cast<std::size_t>(len));
    }
    if (w == "strupr" || w == "strlwr") {
        expect("(");
        std::string s = parse_string();
        expect(")");
        for (char& c : s) c = static_cast<char>(w == "strupr" ? std::toupper(static_cast<unsigned char>(c))
                                                               : std::tolower(static_cast<unsigned char>(c)));
        return s;
    }
    if (const auto m = m_macros.find(w); m != m_macros.end()) {
        invoke_macro(t, m->second);
        return parse_string();
    }
    // POV-Ray compat: the identifier's value is taken before the token after it is read, since that token may be
    // the #end of the macro whose #local it is (`#macro M() #local S = "a"; S #end`).
    std::optional<std::string> held;
    if (const Value* found = lookup(w); found && std::holds_alternative<std::string>(*found))
        held = std::get<std::string>(*found);
    if (is_punct(peek_expr(), "[") && t.file == m_file && m_pos > 0 &&
        m_files[m_file]->tokens[m_pos - 1].column == t.column && m_files[m_file]->tokens[m_pos - 1].line == t.line) {
        --m_pos;  // the identifier was just read from this file: read it again as an array element
        const auto element = take_array_element();
        if (!element) fail(t, "'" + w + "' is not an array");
        if (const auto* s = std::get_if<std::string>(&*element)) return *s;
        fail(t, "expected a string but this element of '" + w + "' is " + value_kind_name(*element));
    }
    if (held) return *held;
    const Value* v = lookup(w);
    if (v == nullptr) fail_undeclared(t);
    if (const auto* s = std::get_if<std::string>(v)) return *s;
    fail(t, "expected a string but '" + w + "' is " + value_kind_name(*v));
}

Numeric Evaluator::parse_function(const Token& name) {
    const TokenText& f = name.text;
    auto arg_list = [&](std::size_t min_args, std::size_t max_args) {
        expect("(");
        std::vector<Numeric> args;
        if (!is_punct(peek(), ")")) {
            do {
                args.push_back(parse_conditional(true));
            } while (accept(","));
        }
        expect(")");
        if (args.size() < min_args || args.size() > max_args) {
            fail(name, "'" + f + "' takes " +
                           (min_args == max_args ? std::to_string(min_args)
                                                 : std::to_string(min_args) + " or more") +
                           " argument(s) but " + std::to_string(args.size()) + " were given");
        }
        return args;
    };
    auto scalar_arg = [&](const Numeric& a) {
        if (a.n != 1) fail(name, "'" + f + "' needs float arguments");
        return a.v[0];
    };
    auto vector_arg = [&](const Numeric& a) { return a.vec3(); };

    // String-taking functions first.
    if (f == "strlen" || f == "val" || f == "file_exists" || f == "asc") {
        expect("(");
        const std::string s = parse_string();
        expect(")");
        if (f == "strlen") return Numeric::scalar(static_cast<double>(s.size()));
        // The code of the first character (0 for an empty string).
        if (f == "asc") return Numeric::scalar(s.empty() ? 0.0 : static_cast<unsigned char>(s[0]));
        if (f == "val") return Numeric::scalar(std::atof(s.c_str()));
        std::error_code ec;
        bool found = std::filesystem::exists(std::filesystem::path(m_files[m_file]->path.str()).parent_path() / s, ec);
        for (const auto& dir : m_options.library_paths) found = found || std::filesystem::exists(dir / s, ec);
        return Numeric::scalar(found ? 1.0 : 0.0);
    }
    if (f == "strcmp") {
        expect("(");
        const std::string a = parse_string();
        expect(",");
        const std::string b = parse_string();
        expect(")");
        const int c = a.compare(b);
        return Numeric::scalar(c < 0 ? -1.0 : (c > 0 ? 1.0 : 0.0));
    }
    if (f == "defined") {
        expect("(");
        const Token id = expect_identifier();
        const Value* v = lookup(id.text);
        bool found = v != nullptr || m_macros.count(id.text) > 0;
        if (const auto* array = v ? std::get_if<std::shared_ptr<ArrayValue>>(v) : nullptr) {
            if (is_punct(peek_expr(), "[")) found = (*array)->elements[parse_array_index(**array, id)].has_value();
        }
        expect(")");
        return Numeric::scalar(found ? 1.0 : 0.0);
    }
    if (f == "dimensions" || f == "dimension_size") {
        expect("(");
        const Token id = expect_identifier();
        const Value* v = lookup(id.text);
        if (v == nullptr) fail_undeclared(id);
        const auto* array = std::get_if<std::shared_ptr<ArrayValue>>(v);
        if (array == nullptr) fail(id, "'" + id.text + "' is not an array");
        const std::vector<std::size_t> dims = (*array)->dims;
        if (f == "dimensions") {
            expect(")");
            return Numeric::scalar(static_cast<double>(dims.size()));
        }
        expect(",");
        const Token at = peek();
        const double d = parse_float();
        expect(")");
        if (d < 1 || d > static_cast<double>(dims.size())) fail(at, "dimension_size: no such dimension");
        return Numeric::scalar(static_cast<double>(dims[static_cast<std::size_t>(d) - 1]));
    }

    using Fn = double (*)(double);
    static const std::pair<const char*, Fn> unary[] = {
        {"abs", [](double a) { return std::fabs(a); }},
        {"ceil", [](double a) { return std::ceil(a); }},
        {"floor", [](double a) { return std::floor(a); }},
        {"int", [](double a) { return std::trunc(a); }},
        {"sqrt", [](double a) { return std::sqrt(a); }},
        {"sin", [](double a) { return std::sin(a); }},
        {"cos", [](double a) { return std::cos(a); }},
        {"tan", [](double a) { return std::tan(a); }},
        {"asin", [](double a) { return std::asin(a); }},
        {"acos", [](double a) { return std::acos(a); }},
        {"sinh", [](double a) { return std::sinh(a); }},
        {"cosh", [](double a) { return std::cosh(a); }},
        {"tanh", [](double a) { return std::tanh(a); }},
        {"asinh", [](double a) { return std::asinh(a); }},
        {"acosh", [](double a) { return std::acosh(a); }},
        {"atanh", [](double a) { return std::atanh(a); }},
        {"exp", [](double a) { return std::exp(a); }},
        {"ln", [](double a) { return std::log(a); }},
        {"log", [](double a) { return std::log10(a); }},
        {"radians", [](double a) { return a * std::numbers::pi / 180.0; }},
        {"degrees", [](double a) { return a * 180.0 / std::numbers::pi; }},
    };
    for (const auto& [fname, fn] : unary) {
        if (f != fname) continue;
        const auto args = arg_list(1, 1);
        const double a = scalar_arg(args[0]);
        if ((f == "sqrt" && a < 0) || ((f == "ln" || f == "log") && a <= 0) ||
            ((f == "asin" || f == "acos") && std::fabs(a) > 1))
            fail(name, "'" + f + "' argument out of range");
        return Numeric::scalar(fn(a));
    }
    if (f == "atan") {
        // atan(a) or atan(a, b) (the latter is atan2 in POV-Ray 3.7).
        const auto args = arg_list(1, 2);
        if (args.size() == 2) return Numeric::scalar(std::atan2(scalar_arg(args[0]), scalar_arg(args[1])));
        return Numeric::scalar(std::atan(scalar_arg(args[0])));
    }
    if (f == "atan2" || f == "pow" || f == "mod" || f == "div") {
        const auto args = arg_list(2, 2);
        const double a = scalar_arg(args[0]);
        const double b = scalar_arg(args[1]);
        if (f == "atan2") return Numeric::scalar(std::atan2(a, b));
        if (f == "pow") return Numeric::scalar(std::pow(a, b));
        if (b == 0.0) fail(name, "'" + f + "' by zero");
        if (f == "mod") return Numeric::scalar(std::fmod(a, b));
        return Numeric::scalar(std::trunc(a / b));
    }
    if (f == "min" || f == "max") {
        const auto args = arg_list(1, 64);
        double r = scalar_arg(args[0]);
        for (const auto& a : args) r = f == "min" ? std::min(r, scalar_arg(a)) : std::max(r, scalar_arg(a));
        return Numeric::scalar(r);
    }
    if (f == "select") {
        const auto args = arg_list(3, 4);
        const double s = scalar_arg(args[0]);
        if (args.size() == 3) return s < 0 ? args[1] : args[2];
        return s < 0 ? args[1] : (s == 0 ? args[2] : args[3]);
    }
    if (f == "vlength") return Numeric::scalar(length(vector_arg(arg_list(1, 1)[0])));
    if (f == "vnormalize") {
        const Vec3 v = vector_arg(arg_list(1, 1)[0]);
        if (length(v) == 0.0) fail(name, "cannot normalize a zero-length vector");
        return Numeric::vector3(normalize(v));
    }
    if (f == "vdot") {
        const auto args = arg_list(2, 2);
        return Numeric::scalar(dot(vector_arg(args[0]), vector_arg(args[1])));
    }
    if (f == "vcross") {
        const auto args = arg_list(2, 2);
        return Numeric::vector3(cross(vector_arg(args[0]), vector_arg(args[1])));
    }
    if (f == "vrotate") {
        const auto args = arg_list(2, 2);
        return Numeric::vector3(Transform::rotation(vector_arg(args[1])).vector(vector_arg(args[0])));
    }
    if (f == "vaxis_rotate") {
        const auto args = arg_list(3, 3);
        return Numeric::vector3(axis_rotate(vector_arg(args[0]), vector_arg(args[1]), scalar_arg(args[2])));
    }
    if (f == "seed") {
        const auto args = arg_list(1, 1);
        m_rand_streams.push_back(static_cast<std::uint32_t>(static_cast<std::int64_t>(scalar_arg(args[0]))));
        return Numeric::scalar(static_cast<double>(m_rand_streams.size() - 1));
    }
    if (f == "rand") {
        const auto args = arg_list(1, 1);
        const double stream = scalar_arg(args[0]);
        if (stream < 0 || stream >= static_cast<double>(m_rand_streams.size()))
            fail(name, "rand needs a stream made by seed()");
        // POV-Ray 3.7 compat: a 32-bit linear congruential generator whose whole state, over 2^32 - 1, is the
        // value (3.7 returns all 32 bits; older versions returned 15).
        std::uint32_t& state = m_rand_streams[static_cast<std::size_t>(stream)];
        state = state * 1812433253u + 12345u;
        return Numeric::scalar(static_cast<double>(state) / 4294967295.0);
    }
    if (f == "trace" || f == "inside" || f == "min_extent" || f == "max_extent") return parse_geometry_query(name);
    if (f == "vturbulence") {
        // vturbulence(Lambda, Omega, Octaves, V): the vector fBm that displaces points in `turbulence`.
        const auto args = arg_list(4, 4);
        if (!m_options.vector_turbulence)
            fail(name, "vturbulence() needs the lighting layer, which this program did not provide");
        // POV-Ray compat: the octaves are truncated and kept within 1..10.
        const int octaves = std::clamp(static_cast<int>(scalar_arg(args[2])), 1, 10);
        return Numeric::vector3(
            m_options.vector_turbulence(vector_arg(args[3]), octaves, scalar_arg(args[1]), scalar_arg(args[0])));
    }
    if (f == "bitwise_and" || f == "bitwise_or" || f == "bitwise_xor") {
        // POV-Ray compat: each argument is truncated to an int, then all are combined left to right.
        const auto args = arg_list(1, SIZE_MAX);
        int bits = static_cast<int>(scalar_arg(args[0]));
        for (std::size_t i = 1; i < args.size(); ++i) {
            const int b = static_cast<int>(scalar_arg(args[i]));
            bits = f == "bitwise_and" ? (bits & b) : f == "bitwise_or" ? (bits | b) : (bits ^ b);
        }
        return Numeric::scalar(bits);
    }
    // POV-Ray compat: sum() and prod() exist only in the function language.
    if (f == "sum" || f == "prod")
        fail(name, "'" + f + "' can only be used inside a function body, e.g. function(n) { " + f + "(i, 1, n, i) }");
    static const char* const unsupported[] = {"eval_pigment", "datetime"};
    for (const char* u : unsupported)
        if (f == u) fail(name, "'" + f + "' is not supported yet");
    fail(name, "expected a float or vector expression but found keyword '" + f + "'");
}

Numeric Evaluator::parse_geometry_query(const Token& name) {
    const TokenText& f = name.text;
    expect("(");
    const Token obj_at = peek();
    const Value obj = parse_rvalue();
    const auto* boxed = std::get_if<Boxed<ObjectValue>>(&obj);
    if (boxed == nullptr) fail(obj_at, "the first argument of '" + f + "' must be an object");
    const ObjectValue* ov = &**boxed;
    std::optional<Vec3> origin;
    std::optional<Vec3> direction;
    std::optional<Token> normal_var;
    if (f == "trace" || f == "inside") {
        expect(",");
        origin = parse_vector();
    }
    if (f == "trace") {
        expect(",");
        direction = parse_vector();
        if (accept(",")) normal_var = expect_identifier();
    }
    expect(")");
    // The parser knows no geometry: it asks the layer that does.
    if (m_options.query == nullptr) fail(name, f + "() needs the geometry layer, which this program did not provide");
    const SceneQuery& q = *m_options.query;
    if (f == "trace") {
        // The nearest hit over the parts of the (flattened) object. POV-Ray compat: a zero direction normalises
        // to NaN there and finds nothing, a miss.
        std::optional<QueryHit> best;
        double best_distance = 0.0;
        const bool no_direction = length(*direction) == 0.0;
        for (const ObjectPart& part : ov->parts) {
            if (no_direction) break;
            // POV-Ray compat: the direction is normalised first, so an isosurface's solver, which steps by the
            // ray's length, finds the same first root whatever length the scene gives.
            const std::optional<QueryHit> hit = q.trace(part.object, *origin, normalize(*direction));
            if (!hit) continue;
            const double d = length(hit->point - *origin);
            if (!best || d < best_distance) {
                best = hit;
                best_distance = d;
            }
        }
        // The sensitivity check's second parse: every hit moved a little along its ray.
        if (best && m_options.trace_nudge != 0.0) {
            const double scale = std::max({1.0, length(*origin), length(best->point)});
            best->point = best->point + normalize(*direction) * (m_options.trace_nudge * scale);
        }
        // POV-Ray compat: a miss returns <0,0,0> and sets the normal to <0,0,0>.
        if (normal_var) assign_existing_or_global(normal_var->text, Numeric::vector3(best ? best->normal : Vec3{}));
        const Vec3 result = best ? best->point : Vec3{};
        if (TraceObserver* observer = m_options.trace_observer) {
            if (observer->seen(make_diagnostic(Severity::Note, name, "").loc, result))
                observer->describe(make_diagnostic(Severity::Warning, name, ""));
        }
        return Numeric::vector3(result);
    }
    if (f == "inside") {
        bool in = false;
        for (const ObjectPart& part : ov->parts) in = in || q.inside(part.object, *origin);
        return Numeric::scalar(in ? 1.0 : 0.0);
    }
    // Extents: the union of the parts' boxes; unbounded parts give POV-Ray's huge bound.
    constexpr double k_huge = 1e10;  // POV-Ray compat: what min_extent/max_extent report for infinite objects
    Vec3 lo{k_huge, k_huge, k_huge};
    Vec3 hi{-k_huge, -k_huge, -k_huge};
    for (const ObjectPart& part : ov->parts) {
        const auto box = q.extent(part.object);
        const Vec3 a = box ? box->first : Vec3{-k_huge, -k_huge, -k_huge};
        const Vec3 b = box ? box->second : Vec3{k_huge, k_huge, k_huge};
        lo = {std::min(lo.x, a.x), std::min(lo.y, a.y), std::min(lo.z, a.z)};
        hi = {std::max(hi.x, b.x), std::max(hi.y, b.y), std::max(hi.z, b.z)};
    }
    if (ov->parts.empty()) lo = hi = Vec3{};
    return Numeric::vector3(f == "min_extent" ? lo : hi);
}

}  // namespace wardray::parser
