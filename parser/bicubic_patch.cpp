// The bicubic_patch reader: type, flatness, u_steps and v_steps (keywords, or POV-Ray 1's leading floats), then
// the 16 control points.
#include <cmath>

#include "parser/parser.h"

namespace wardray::parser {

BicubicPatch Parser::read_bicubic_patch(const Token& kw) {
    BicubicPatch patch;
    // Subdivision doubles the triangles per step in each direction: beyond this the mesh would not fit in memory.
    constexpr int k_max_steps = 12;
    auto read_steps = [&](int& out) {
        const Token at = peek();
        const double v = parse_float();
        if (!(v >= 0.0 && v <= k_max_steps)) fail(at, "bicubic_patch steps must be between 0 and 12");
        out = static_cast<int>(v);
    };
    while (true) {
        expand_macros();
        const Token t = peek();
        if (is_word(t, "type")) {
            next();
            patch.type = static_cast<int>(parse_float());
        } else if (is_word(t, "flatness")) {
            next();
            patch.flatness = parse_float();
        } else if (is_word(t, "u_steps")) {
            next();
            read_steps(patch.u_steps);
        } else if (is_word(t, "v_steps")) {
            next();
            read_steps(patch.v_steps);
        } else if (is_word(t, "accuracy")) {
            next();
            parse_float();  // POV-Ray reads it for bicubic patches and never uses it
        } else if (is_word(t, "uv_vectors")) {
            next();
            for (int k = 0; k < 4; ++k) {
                if (k > 0) accept(",");
                const Vec3 uv = parse_vector();
                patch.uv_vectors[k] = {uv.x, uv.y, 0.0};
            }
        } else if (t.kind == TokenKind::Number) {
            // POV-Ray 1's syntax: type, [flatness for types 2 and 3,] u_steps, v_steps as bare floats.
            patch.type = static_cast<int>(parse_float());
            accept(",");
            patch.flatness = patch.type == 2 || patch.type == 3 ? parse_float() : 0.1;
            accept(",");
            read_steps(patch.u_steps);
            accept(",");
            read_steps(patch.v_steps);
            break;
        } else {
            break;
        }
    }
    if (patch.type > 1) {
        warn(kw, "bicubic_patch type " + std::to_string(patch.type) + " is no longer supported; type 1 is used");
        patch.type = 1;
    }
    if (patch.type < 0) fail(kw, "undefined bicubic_patch type");
    accept(",");
    for (Vec3& p : patch.points) {
        p = parse_vector();
        accept(",");
    }
    return patch;
}

}  // namespace wardray::parser
