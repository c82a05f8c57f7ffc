// The blob reader: threshold, sphere and cylinder components (old `component` syntax too) with their transforms
// and textures.
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
    std::vector<Texture> textures;
    // Reads a new-syntax component's `[strength] s` and its modifiers up to its closing brace.
    auto read_component_rest = [&](Blob::Component& c) {
        accept(",");
        accept_keyword("strength");
        c.strength = parse_float();
        while (true) {
            expand_macros();
            const Token t = peek();
            Transform step;
            if (parse_transform_item(t, step)) {
                // POV-Ray compat (Transform_Blob_Element): the component's texture moves with it.
                c.transform = c.transform.then(step);
                if (c.texture >= 0) transform_texture(textures[static_cast<std::size_t>(c.texture)], step);
                continue;
            }
            next();
            if (is_punct(t, "}")) return;
            if (is_word(t, "texture")) {
                Texture tx = parse_texture_body(t);
                if (c.texture < 0) {
                    c.texture = static_cast<int>(textures.size());
                    textures.push_back(std::move(tx));
                } else {
                    add_layers(textures[static_cast<std::size_t>(c.texture)], std::move(tx));
                }
                continue;
            }
            if (is_word(t, "pigment") || is_word(t, "normal") || is_word(t, "finish")) {
                // POV-Ray compat (Parse_Blob_Element_Mods): these start from the default texture, a new layer of
                // it over a texture map.
                if (c.texture < 0) {
                    c.texture = static_cast<int>(textures.size());
                    textures.push_back(default_texture());
                } else if (!top_layer(textures[static_cast<std::size_t>(c.texture)]).texture_map.empty()) {
                    add_layers(textures[static_cast<std::size_t>(c.texture)], default_texture());
                }
                Texture& top = top_layer(textures[static_cast<std::size_t>(c.texture)]);
                if (t.text == "pigment") top.pigment = parse_pigment_body(t, &top.pigment);
                else if (t.text == "normal") top.normal = parse_normal_body(t, &top.normal);
                else top.finish = parse_finish_body(t, &top.finish);
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
    if (!textures.empty()) blob.textures = std::move(textures);
    return blob;
}

}  // namespace wardray::parser
