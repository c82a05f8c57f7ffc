// The julia_fractal statement: the Julia parameter, algebra, function, iterations, precision and slice, as
// POV-Ray 3.7 reads them (Parse_Julia_Fractal).
#include <cmath>
#include <string_view>
#include <utility>

#include "core/constants.h"
#include "parser/parser.h"

namespace wardray::parser {

namespace {

using Function = JuliaFractal::Function;

// The function keywords after the Julia parameter (pwr, which takes its exponent, is read apart).
constexpr std::pair<std::string_view, Function> k_functions[] = {
    {"sqr", Function::Sqr},     {"cube", Function::Cube},   {"reciprocal", Function::Reciprocal},
    {"exp", Function::Exp},     {"ln", Function::Ln},       {"sin", Function::Sin},
    {"asin", Function::Asin},   {"cos", Function::Cos},     {"acos", Function::Acos},
    {"tan", Function::Tan},     {"atan", Function::Atan},   {"sinh", Function::Sinh},
    {"asinh", Function::Asinh}, {"cosh", Function::Cosh},   {"acosh", Function::Acosh},
    {"tanh", Function::Tanh},   {"atanh", Function::Atanh}};

}  // namespace

JuliaFractal Parser::read_julia_fractal(const Token& kw) {
    JuliaFractal f;
    const Numeric c = parse_numeric().promoted(4);
    for (int i = 0; i < 4; ++i) f.c[i] = c.v[i];
    Token function_at = kw;
    for (;;) {
        const Token t = peek();
        if (t.kind != TokenKind::Identifier) break;
        const std::string_view w = t.text.view();
        bool is_function = false;
        for (const auto& [name, fn] : k_functions)
            if (w == name) {
                f.function = fn;
                is_function = true;
            }
        if (is_function) {
            next();
            function_at = t;
        } else if (w == "pwr") {
            next();
            function_at = t;
            f.function = Function::Pwr;
            expect("(");
            f.exponent_re = parse_float();
            expect(",");
            f.exponent_im = parse_float();
            expect(")");
        } else if (w == "quaternion") {
            next();
            f.algebra = JuliaFractal::Algebra::Quaternion;
        } else if (w == "hypercomplex") {
            next();
            f.algebra = JuliaFractal::Algebra::Hypercomplex;
        } else if (w == "max_iteration") {
            next();
            // POV-Ray compat: the count is floored, and at least 1.
            f.max_iteration = static_cast<int>(std::fmax(1.0, std::floor(parse_float())));
        } else if (w == "precision") {
            next();
            // POV-Ray compat: precisions below 1 count as 1.
            f.step = 1.0 / std::fmax(1.0, parse_float());
        } else if (w == "slice") {
            next();
            const Token at = peek();
            const Numeric s = parse_numeric().promoted(4);
            accept(",");
            f.slice_distance = parse_float();
            double norm2 = 0.0;
            for (int i = 0; i < 4; ++i) norm2 += s.v[i] * s.v[i];
            if (std::fabs(norm2) < kPovEpsilon) fail(at, "the slice vector of a julia_fractal is zero");
            if (std::fabs(s.v[3]) < kPovEpsilon) fail(at, "the t component of a julia_fractal's slice vector is zero");
            // The normal is kept unit length; the distance stays as written.
            for (int i = 0; i < 4; ++i) f.slice[i] = s.v[i] / std::sqrt(norm2);
        } else {
            break;
        }
    }
    if (f.algebra == JuliaFractal::Algebra::Quaternion && f.function != Function::Sqr && f.function != Function::Cube)
        fail(function_at, "a quaternion julia_fractal takes only sqr or cube (use hypercomplex for the others)");
    return f;
}

}  // namespace wardray::parser
