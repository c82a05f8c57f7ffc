// The isosurface statement: its function, container and the solver's settings, as POV-Ray 3.7 reads them.
#include <algorithm>
#include <cmath>
#include <string_view>

#include "parser/parser.h"

namespace wardray::parser {

namespace {

// POV-Ray's ISOSURFACE_MAXTRACE: the most crossings one ray finds (all_intersections).
constexpr int k_max_trace = 10;

}  // namespace

Isosurface Parser::read_isosurface(const Token& kw) {
    Isosurface iso;
    const Token fn_kw = peek();
    if (!is_word(fn_kw, "function")) fail(fn_kw, "an isosurface starts with its function { ... }");
    next();
    const std::shared_ptr<const UserFunction> f = parse_user_function(fn_kw);
    if (f->kind != UserFunction::Kind::Float || !f->program)
        fail(fn_kw, "the function of an isosurface must be a float function");
    iso.function = f->program;
    iso.function_loc = make_diagnostic(Severity::Note, fn_kw, "").loc;
    iso.noise_generator = m_builder.global().noise_generator;
    if (!f->program->unsupported().empty()) warn(fn_kw, "isosurface is not rendered yet: its " + f->program->unsupported());
    for (;;) {
        const Token t = peek();
        if (t.kind != TokenKind::Identifier) break;
        const std::string_view w = t.text.view();
        if (w == "contained_by") {
            next();
            expect("{");
            const Token shape = next();
            expect("{");
            if (is_word(shape, "box")) {
                const Vec3 a = parse_vector();
                accept(",");
                const Vec3 b = parse_vector();
                iso.sphere_container = false;
                iso.corner1 = min(a, b);
                iso.corner2 = max(a, b);
            } else if (is_word(shape, "sphere")) {
                iso.center = parse_vector();
                accept(",");
                iso.radius = parse_float();
                iso.sphere_container = true;
            } else {
                fail(shape, "contained_by takes a box or a sphere");
            }
            expect("}");
            expect("}");
        } else if (w == "threshold") {
            next();
            iso.threshold = parse_float();
        } else if (w == "accuracy") {
            next();
            iso.accuracy = parse_float();
        } else if (w == "max_gradient") {
            next();
            iso.max_gradient = parse_float();
        } else if (w == "max_trace") {
            next();
            const Token at = peek();
            const double n = parse_float();
            if (n < 1 || n > k_max_trace) fail(at, "isosurface max_trace must be 1 to 10");
            iso.max_trace = static_cast<int>(n);
        } else if (w == "all_intersections") {
            next();
            iso.max_trace = k_max_trace;
        } else if (w == "evaluate") {
            next();
            iso.evaluate = true;
            warn(t, "isosurface 'evaluate' is approximated: the gradient adapts along each ray, not across the "
                    "render as in POV-Ray");
            for (int i = 0; i < 3; ++i) {
                if (i > 0) accept(",");
                iso.eval[static_cast<std::size_t>(i)] = parse_float();
            }
        } else if (w == "open") {
            next();
            iso.open = true;
        } else {
            break;
        }
    }
    // POV-Ray compat: non-positive settings fall back to the defaults with a warning.
    if (!(iso.accuracy > 0.0)) {
        warn(kw, "isosurface 'accuracy' is not positive; using 0.001 (the default)");
        iso.accuracy = 0.001;
    }
    if (!(iso.max_gradient > 0.0)) {
        warn(kw, "isosurface 'max_gradient' is not positive; using 1.1 (the default)");
        iso.max_gradient = 1.1;
    }
    return iso;
}

}  // namespace wardray::parser
