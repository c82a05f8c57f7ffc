// The parametric statement: its three functions of u and v, the uv rectangle, container and solver settings, as
// POV-Ray 3.7 reads them (Parse_Parametric).
#include <algorithm>
#include <string_view>
#include <utility>

#include "parser/parser.h"

namespace wardray::parser {

Parametric Parser::read_parametric(const Token& kw) {
    Parametric par;
    par.noise_generator = m_builder.global().noise_generator;
    static constexpr const char* k_axis[3] = {"x", "y", "z"};
    for (int k = 0; k < 3; ++k) {
        if (k > 0) accept(",");
        const Token fn_kw = peek();
        if (!is_word(fn_kw, "function"))
            fail(fn_kw, std::string("a parametric needs three functions; expected function { ... } for ") +
                            k_axis[k] + " but found " + describe_token(fn_kw));
        next();
        const std::shared_ptr<const UserFunction> f = parse_user_function(fn_kw);
        if (f->kind != UserFunction::Kind::Float || !f->program)
            fail(fn_kw, "the functions of a parametric must be float functions");
        if (!f->program->unsupported().empty())
            warn(fn_kw, "parametric is not rendered yet: its " + f->program->unsupported());
        par.functions[static_cast<std::size_t>(k)] = f->program;
    }
    // POV-Ray compat: the corners are ordered per coordinate.
    const Vec3 uv1 = parse_vector();
    accept(",");
    const Vec3 uv2 = parse_vector();
    par.u_min = std::min(uv1.x, uv2.x);
    par.u_max = std::max(uv1.x, uv2.x);
    par.v_min = std::min(uv1.y, uv2.y);
    par.v_max = std::max(uv1.y, uv2.y);
    for (;;) {
        const Token t = peek();
        if (t.kind != TokenKind::Identifier) break;
        const std::string_view w = t.text.view();
        if (w == "accuracy") {
            next();
            par.accuracy = parse_float();
        } else if (w == "max_gradient") {
            next();
            par.max_gradient = parse_float();
        } else if (w == "precompute") {
            next();
            const Token at = peek();
            const double depth = parse_float();
            // POV-Ray compat: the axes are optional, each in the order x, y, z, commas optional.
            int axes = 0;
            for (int k = 0; k < 3; ++k) {
                accept(",");
                if (is_word(peek(), k_axis[k])) {
                    next();
                    axes |= 1 << k;
                }
            }
            const int d = static_cast<int>(depth);
            if (axes != 0 && (d < 1 || d > 20)) fail(at, "parametric precompute depth must be 1 to 20");
            par.precompute_depth = axes != 0 ? d : 0;
            par.precompute_axes = axes;
        } else if (w == "contained_by") {
            next();
            expect("{");
            const Token shape = next();
            expect("{");
            if (is_word(shape, "box")) {
                const Vec3 a = parse_vector();
                accept(",");
                const Vec3 b = parse_vector();
                par.sphere_container = false;
                par.corner1 = min(a, b);
                par.corner2 = max(a, b);
            } else if (is_word(shape, "sphere")) {
                par.center = parse_vector();
                accept(",");
                par.radius = parse_float();
                par.sphere_container = true;
                warn(shape, "parametric contained_by sphere is approximated: POV-Ray 3.7.0 hides parts of the surface "
                            "inside such a container whatever its radius, which wardray does not reproduce");
            } else {
                fail(shape, "contained_by takes a box or a sphere");
            }
            expect("}");
            expect("}");
        } else {
            break;
        }
    }
    return par;
}

}  // namespace wardray::parser
