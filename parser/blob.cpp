// The blob reader: threshold, sphere and cylinder components (old `component` syntax too) with their transforms.
#include <algorithm>
#include <cmath>

#include "parser/parser.h"

namespace wardray::parser {

namespace {

// POV-Ray's EPSILON: a cylinder component shorter than this is an error.
constexpr double k_epsilon = 1e-10;

}  // namespace

Blob Parser::read_blob(const Token& kw) {
    Blob blob;
    // Reads a new-syntax component's `[strength] s` and its modifiers up to its closing brace.
    auto read_component_rest = [&](Blob::Component& c) {
        accept(",");
        accept_keyword("strength");
        c.strength = parse_float();
        while (true) {
            expand_macros();
            const Token t = peek();
            if (parse_transform_item(t, c.transform)) continue;
            next();
            if (is_punct(t, "}")) return;
            if (is_word(t, "texture") || is_word(t, "pigment") || is_word(t, "normal") || is_word(t, "finish")) {
                // POV-Ray blends the component textures by density; the blob's own texture is used here.
                warn_unsupported(t, "blob component texture");
                skip_block(t);
                continue;
            }
            fail(t, "expected a transformation, a texture or '}' in a blob component but found " +
                        describe_token(t));
        }
    };
    while (true) {
        expand_macros();
        const Token t = peek();
        if (is_word(t, "threshold")) {
            next();
            blob.threshold = parse_float();
        } else if (is_word(t, "component")) {
            // The old syntax: `component strength, radius, <centre>`.
            next();
            Blob::Component c;
            c.strength = parse_float();
            accept(",");
            c.radius = parse_float();
            accept(",");
            c.a = parse_vector();
            blob.components.push_back(c);
        } else if (is_word(t, "sphere")) {
            next();
            expect("{");
            Blob::Component c;
            c.a = parse_vector();
            accept(",");
            c.radius = parse_float();
            read_component_rest(c);
            blob.components.push_back(c);
        } else if (is_word(t, "cylinder")) {
            next();
            expect("{");
            Blob::Component c;
            c.cylinder = true;
            c.a = parse_vector();
            accept(",");
            c.b = parse_vector();
            accept(",");
            c.radius = parse_float();
            if (length(c.b - c.a) < k_epsilon) fail(t, "degenerate cylindrical component in blob: its ends coincide");
            read_component_rest(c);
            blob.components.push_back(c);
        } else if (is_word(t, "sturm")) {
            next();  // the roots are bracketed exactly anyway
        } else if (is_word(t, "hierarchy")) {
            next();
            parse_bool_optional();  // an acceleration hint: the result is the same
        } else {
            break;
        }
    }
    if (blob.components.empty()) fail(kw, "a blob needs at least one component");
    // POV-Ray compat: the components are kept last first; the densities are summed in that order.
    std::reverse(blob.components.begin(), blob.components.end());
    return blob;
}

}  // namespace wardray::parser
