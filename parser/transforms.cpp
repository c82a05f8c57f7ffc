// Transformations: translate, rotate, scale, matrix and transform blocks or identifiers, composed in order.
#include <array>
#include <string>

#include "parser/evaluator.h"

namespace wardray::parser {

bool Evaluator::parse_transform_item(const Token& t, Transform& out) {
    if (t.kind != TokenKind::Identifier) return false;
    const TokenText& w = t.text;
    if (w == "translate") {
        next();
        out = out.then(Transform::translation(parse_vector()));
    } else if (w == "rotate") {
        next();
        out = out.then(Transform::rotation(parse_vector()));
    } else if (w == "scale") {
        next();
        Vec3 s = parse_vector();
        for (int i = 0; i < 3; ++i) {
            if (s[i] == 0.0) {
                // POV-Ray compat: a zero scale component is changed to 1 with a warning.
                warn(t, "scale by 0 changed to 1");
                s[i] = 1.0;
            }
        }
        out = out.then(Transform::scaling(s));
    } else if (w == "matrix") {
        next();
        expect("<");
        std::array<double, 12> m{};
        for (int i = 0; i < 12; ++i) {
            if (i > 0) expect(",");
            const Token at = peek();
            const Numeric c = parse_additive();
            if (c.n != 1) fail(at, "matrix entries must be floats");
            m[i] = c.v[0];
        }
        expect(">");
        for (int col = 0; col < 3; ++col) {
            if (m[col] != 0.0 || m[3 + col] != 0.0 || m[6 + col] != 0.0) continue;
            // POV-Ray compat: a zero column scales by 0; like `scale 0`, it becomes 1 with a warning.
            warn(t, "matrix column " + std::to_string(col + 1) + " is zero (a scale by 0); changed to 1");
            m[4 * col] = 1.0;
        }
        const auto tr = Transform::from_pov_matrix(m);
        // POV-Ray compat: POV-Ray stops with "Singular matrix" here too; it cannot place the object.
        if (!tr || !tr->is_invertible()) fail(t, "matrix is singular: it flattens space, so the object has no inverse");
        out = out.then(*tr);
    } else if (w == "transform") {
        next();
        if (is_punct(peek(), "{")) {
            out = out.then(parse_transform_body(t));
        } else {
            const Token id = expect_identifier();
            const Value* v = lookup(id.text);
            if (v == nullptr) fail_undeclared(id);
            const auto* tv = std::get_if<Boxed<Transform>>(v);
            if (tv == nullptr) fail(id, "'" + id.text + "' is not a transform");
            out = out.then(**tv);
        }
    } else {
        return false;
    }
    return true;
}

Transform Evaluator::parse_transform_body(const Token& kw) {
    expect("{");
    Transform result;
    while (true) {
        expand_macros();  // transforms.inc's macros stand where a transform item is expected
        const Token t = peek();
        if (parse_transform_item(t, result)) continue;
        next();
        if (is_punct(t, "}")) return result;
        if (is_word(t, "inverse")) {
            result = result.inverse();
        } else if (t.kind == TokenKind::Identifier && lookup(t.text) &&
                   std::holds_alternative<Boxed<Transform>>(*lookup(t.text))) {
            result = result.then(*std::get<Boxed<Transform>>(*lookup(t.text)));
        } else {
            fail(t, "expected a transformation but found '" + t.text + "'");
        }
    }
}

}  // namespace wardray::parser
