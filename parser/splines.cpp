// Splines of the scene language: reading `spline { ... }`, calling `S(t)`, and the interpolation of POV-Ray 3.7.
#include "parser/splines.h"

#include <algorithm>
#include <optional>
#include <string>

#include "parser/keywords.h"
#include "parser/parser.h"

namespace wardray::parser {

namespace {

using Components = std::array<double, 5>;

/// POV-Ray 3.7's segment search: 0 when t is at or before the first point, the point count when t is at or after
/// the last, else the index of the first point whose T is not below t (the end of t's segment).
std::size_t segment_end(const std::vector<Spline::Point>& points, double t) {
    if (t <= points.front().t) return 0;
    if (t >= points.back().t) return points.size();
    const auto it = std::lower_bound(points.begin(), points.end(), t,
                                     [](const Spline::Point& p, double x) { return p.t < x; });
    return static_cast<std::size_t>(it - points.begin());
}

Components linear(const std::vector<Spline::Point>& p, std::size_t i, double t) {
    Components r;
    const double f = (t - p[i].t) / (p[i + 1].t - p[i].t);
    for (int k = 0; k < 5; ++k) r[k] = p[i].v[k] + f * (p[i + 1].v[k] - p[i].v[k]);
    return r;
}

/// The parabola through points a, a+1 and a+2 at t (Lagrange form).
Components parabola(const std::vector<Spline::Point>& p, std::size_t a, double t) {
    const double t0 = p[a].t, t1 = p[a + 1].t, t2 = p[a + 2].t;
    const double w0 = (t - t1) * (t - t2) / ((t0 - t1) * (t0 - t2));
    const double w1 = (t - t0) * (t - t2) / ((t1 - t0) * (t1 - t2));
    const double w2 = (t - t0) * (t - t1) / ((t2 - t0) * (t2 - t1));
    Components r;
    for (int k = 0; k < 5; ++k) r[k] = w0 * p[a].v[k] + w1 * p[a + 1].v[k] + w2 * p[a + 2].v[k];
    return r;
}

/// POV-Ray's cubic_spline on segment i..i+1: a cubic Hermite curve whose tangent at each end is the mean of the
/// slopes of the two chords meeting there (so points i-1 and i+2 only steer the tangents).
Components catmull_rom(const std::vector<Spline::Point>& p, std::size_t i, double t) {
    const double dt = p[i + 1].t - p[i].t;
    const double u = (t - p[i].t) / dt;
    const double h00 = (2 * u - 3) * u * u + 1;
    const double h01 = (3 - 2 * u) * u * u;
    const double h10 = ((u - 2) * u + 1) * u;
    const double h11 = (u - 1) * u * u;
    Components r;
    for (int k = 0; k < 5; ++k) {
        const double before = (p[i].v[k] - p[i - 1].v[k]) / (p[i].t - p[i - 1].t);
        const double chord = (p[i + 1].v[k] - p[i].v[k]) / dt;
        const double after = (p[i + 2].v[k] - p[i + 1].v[k]) / (p[i + 2].t - p[i + 1].t);
        const double m0 = 0.5 * (before + chord) * dt;
        const double m1 = 0.5 * (chord + after) * dt;
        r[k] = h00 * p[i].v[k] + h01 * p[i + 1].v[k] + h10 * m0 + h11 * m1;
    }
    return r;
}

/// Second derivatives of the natural cubic spline at every point (zero at both ends), per component: the
/// tridiagonal system h[i-1] M[i-1] + 2 (h[i-1] + h[i]) M[i] + h[i] M[i+1] = 6 (slope[i] - slope[i-1]) solved by
/// forward elimination and back substitution.
std::vector<Components> natural_second_derivatives(const std::vector<Spline::Point>& p) {
    const std::size_t n = p.size();
    std::vector<Components> m(n, Components{});
    if (n < 3) return m;
    std::vector<double> h(n - 1), slope(n - 1), diag(n - 1), rhs(n - 1);
    for (int k = 0; k < 5; ++k) {
        for (std::size_t i = 0; i + 1 < n; ++i) {
            h[i] = p[i + 1].t - p[i].t;
            slope[i] = (p[i + 1].v[k] - p[i].v[k]) / h[i];
        }
        diag[1] = 2 * (h[0] + h[1]);
        rhs[1] = 6 * (slope[1] - slope[0]);
        for (std::size_t i = 2; i + 1 < n; ++i) {
            const double w = h[i - 1] / diag[i - 1];
            diag[i] = 2 * (h[i - 1] + h[i]) - w * h[i - 1];
            rhs[i] = 6 * (slope[i] - slope[i - 1]) - w * rhs[i - 1];
        }
        for (std::size_t i = n - 2; i > 0; --i) m[i][k] = (rhs[i] - h[i] * m[i + 1][k]) / diag[i];
    }
    return m;
}

/// The natural cubic on segment i..i+1 from the values and second derivatives at its ends.
Components natural(const std::vector<Spline::Point>& p, const std::vector<Components>& m, std::size_t i, double t) {
    const double h = p[i + 1].t - p[i].t;
    const double d = t - p[i].t;
    Components r;
    for (int k = 0; k < 5; ++k) {
        const double slope = (p[i + 1].v[k] - p[i].v[k]) / h - h * (m[i + 1][k] + 2 * m[i][k]) / 6;
        const double curve = m[i][k] / 2 + d * (m[i + 1][k] - m[i][k]) / (6 * h);
        r[k] = p[i].v[k] + d * (slope + d * curve);
    }
    return r;
}

}  // namespace

bool spline_type_from_keyword(std::string_view word, Spline::Type& type) {
    if (word == "linear_spline") type = Spline::Type::Linear;
    else if (word == "quadratic_spline") type = Spline::Type::Quadratic;
    else if (word == "cubic_spline") type = Spline::Type::Cubic;
    else if (word == "natural_spline") type = Spline::Type::Natural;
    else return false;
    return true;
}

const char* spline_type_keyword(Spline::Type type) {
    switch (type) {
        case Spline::Type::Linear: return "linear_spline";
        case Spline::Type::Quadratic: return "quadratic_spline";
        case Spline::Type::Cubic: return "cubic_spline";
        case Spline::Type::Natural: return "natural_spline";
    }
    return "spline";
}

std::size_t spline_min_points(Spline::Type type) {
    switch (type) {
        case Spline::Type::Linear: return 2;
        case Spline::Type::Quadratic: return 3;
        case Spline::Type::Cubic: return 4;
        case Spline::Type::Natural: return 3;
    }
    return 2;
}

void insert_spline_point(Spline& spline, double t, const Components& value) {
    auto& points = spline.points;
    if (points.empty()) {
        points.push_back({t, value});
        return;
    }
    const std::size_t i = segment_end(points, t);
    if (i == points.size()) {
        // POV-Ray compat: 3.7 writes a repeat of the largest T past the end of its list, where it is lost.
        if (points.back().t != t) points.push_back({t, value});
        return;
    }
    if (points[i].t == t) points[i].v = value;
    else points.insert(points.begin() + static_cast<std::ptrdiff_t>(i), {t, value});
}

Components evaluate_spline(const Spline& spline, Spline::Type type, double t) {
    const auto& p = spline.points;
    const std::size_t n = p.size();
    if (n == 1) return p[0].v;
    const std::size_t i = segment_end(p, t);
    if (type == Spline::Type::Cubic) {
        // POV-Ray compat: the first and last points only shape the tangents; before the second point the value
        // is the second point's, after the next-to-last the next-to-last's; two points give their mean.
        if (n == 2) {
            Components r;
            for (int k = 0; k < 5; ++k) r[k] = 0.5 * (p[0].v[k] + p[1].v[k]);
            return r;
        }
        if (i < 2) return p[1].v;
        if (i >= n - 1) return p[n - 2].v;
        return catmull_rom(p, i - 1, t);
    }
    // Outside the points' range the other types hold the end value.
    if (i == 0) return p[0].v;
    if (i >= n) return p[n - 1].v;
    switch (type) {
        case Spline::Type::Quadratic:
            // Too few points for a parabola: a line; the first segment uses the parabola of the first three.
            if (n == 2) return linear(p, 0, t);
            return parabola(p, i > 1 ? i - 2 : 0, t);
        case Spline::Type::Natural: return natural(p, natural_second_derivatives(p), i - 1, t);
        default: return linear(p, i - 1, t);
    }
}

Numeric spline_value(const Spline& spline, Spline::Type type, double t) {
    const Components v = evaluate_spline(spline, type, t);
    Numeric r;
    r.n = spline.terms;
    for (int k = 0; k < 5; ++k) r.v[k] = k < r.n ? v[k] : 0.0;
    return r;
}

// ---------------------------------------------------------------------------------------------------------------
// Parsing

void Evaluator::warn_few_spline_points(const Token& at, const Spline& spline, Spline::Type type) {
    const std::size_t n = spline.points.size();
    if (n >= spline_min_points(type) || n == 1) return;
    std::string result = "it interpolates linearly";
    if (type == Spline::Type::Cubic)
        result = n == 2 ? "it is the mean of the two points everywhere" : "it is the second point everywhere";
    warn_once(at, std::string("a ") + spline_type_keyword(type) + " needs at least " +
                      std::to_string(spline_min_points(type)) + " points; with " + std::to_string(n) + ", " + result +
                      ", as in POV-Ray");
}

Spline Evaluator::parse_spline_body(const Token& kw) {
    expect("{");
    Spline spline;
    expand_macros();
    // The first point's T when the block starts with an array element holding a float.
    std::optional<Numeric> first_time;
    if (is_array_element_next()) {
        // meshmaker.inc copies splines out of arrays: `spline { SplineArray[I] }`.
        const Token first = peek();
        const Value element = *take_array_element();
        if (const auto* declared = std::get_if<Boxed<Spline>>(&element)) spline = **declared;
        else if (const auto* n = std::get_if<Numeric>(&element)) first_time = parse_additive(n);
        else
            fail(first, "this element of '" + first.text + "' is " + value_kind_name(element) +
                            ", not a spline or a float");
    } else if (const Token& first = peek(); first.kind == TokenKind::Identifier && !is_keyword(first.text)) {
        // A declared spline to copy (and extend, or give another type); a float identifier starts a point.
        const Value* v = lookup(first.text);
        if (v != nullptr && std::holds_alternative<Boxed<Spline>>(*v)) {
            spline = *std::get<Boxed<Spline>>(*v);
            next();
        } else if (v != nullptr && !std::holds_alternative<Numeric>(*v)) {
            fail(first, "'" + first.text + "' is " + value_kind_name(*v) + ", not a spline or a float");
        }
    }
    // POV-Ray compat: components a value does not give keep those of the point before it (3.7 reuses one buffer).
    Components buffer{};
    std::size_t read = 0;
    while (true) {
        Numeric time;
        expand_macros();
        const Token t = peek();
        if (first_time) {
            time = *first_time;
            first_time.reset();
        } else if (is_punct(t, "}")) {
            next();
            break;
        } else if (Spline::Type type; t.kind == TokenKind::Identifier && spline_type_from_keyword(t.text, type)) {
            if (read > 0)
                fail(t, "the spline type must come before the first point ('" + t.text +
                            "' after a point is an error in POV-Ray 3.7)");
            next();
            spline.type = type;
            continue;
        } else {
            if (t.kind == TokenKind::EndOfFile || starts_string(t) || is_punct(t, "{") || is_punct(t, "["))
                fail(t, "expected a spline point (a float T, then its value) or '}' but found " + describe_token(t));
            time = parse_numeric();
        }
        if (time.n != 1) fail(t, "a spline point's T must be a float but this is a vector");
        accept(",");
        expand_macros();
        if (const Token& after = peek(); is_punct(after, "}"))
            fail(after, "the spline point at T = " + std::to_string(time.v[0]) + " has no value");
        const Numeric value = parse_numeric();
        accept(",");
        // POV-Ray compat: a float value counts as two equal components, so the result is at least a 2-vector.
        const int written = std::max(2, value.n);
        const Numeric given = value.promoted(written);
        for (int k = 0; k < written; ++k) buffer[k] = given.v[k];
        spline.terms = std::max(spline.terms, written);
        insert_spline_point(spline, time.v[0], buffer);
        ++read;
    }
    if (spline.points.empty()) fail(kw, "a spline needs at least one point (a float T, then its value)");
    warn_few_spline_points(kw, spline, spline.type);
    return spline;
}

Numeric Evaluator::call_spline(const Token& name, const Spline& spline) {
    if (!is_punct(peek(), "("))
        fail(name, "'" + name.text + "' is a spline: call it with a parameter, as " + name.text + "(t)");
    next();
    const Token at = peek();
    const Numeric t = parse_numeric();
    if (t.n != 1) fail(at, "the parameter of a spline call must be a float but this is a vector");
    Spline::Type type = spline.type;
    if (accept(",")) {
        const Token kw = next();
        if (kw.kind != TokenKind::Identifier || !spline_type_from_keyword(kw.text, type))
            fail(kw, "expected linear_spline, quadratic_spline, cubic_spline or natural_spline but found " +
                         describe_token(kw));
        if (type != spline.type) warn_few_spline_points(kw, spline, type);
    }
    expect(")");
    return spline_value(spline, type, t.v[0]);
}

}  // namespace wardray::parser
