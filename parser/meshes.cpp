// Mesh statements: triangle and smooth_triangle faces, and the bodies of mesh and mesh2 (vertices, normals, uv
// vectors, textures and their index lists), as POV-Ray reads them.
#include <algorithm>
#include <cmath>
#include <string_view>
#include <unordered_map>
#include <utility>

#include "core/constants.h"
#include "parser/parser.h"
#include "parser/texture_mover.h"

namespace wardray::parser {

void Parser::parse_triangle(Mesh& mesh, bool smooth) {
    Mesh::Face face;
    for (int k = 0; k < 3; ++k) {
        if (k > 0) accept(",");
        face.v[k] = static_cast<int>(mesh.vertices.size());
        mesh.vertices.push_back(parse_vector());
        if (smooth) {
            accept(",");
            face.n[k] = static_cast<int>(mesh.normals.size());
            mesh.normals.push_back(parse_vector());
        }
    }
    mesh.faces.push_back(face);
}

Mesh Parser::parse_mesh_body(const Token& kw) {
    Mesh mesh;
    mesh.kind = Mesh::Kind::Mesh;
    while (true) {
        expand_macros();
        const Token t = peek();
        if (is_word(t, "hierarchy")) {
            next();
            parse_bool_optional();  // an acceleration hint: the renderer builds its own hierarchy
        } else if (is_word(t, "triangle") || is_word(t, "smooth_triangle")) {
            next();
            expect("{");
            parse_triangle(mesh, t.text == "smooth_triangle");
            // Per-triangle uv coordinates and textures (one, or one per corner in a texture_list).
            Mesh::Face& face = mesh.faces.back();
            while (!accept("}")) {
                const Token item = next();
                if (is_word(item, "texture")) {
                    // Triangles that each repeat one texture (`texture { T_Water }`) share one entry of the list
                    // rather than a 3 KB copy each.
                    Texture tx = parse_texture_body(item);
                    const auto& textures = std::as_const(mesh.textures);
                    if (textures.empty() || !interchangeable(textures.back(), tx))
                        mesh.textures.push_back(std::move(tx));
                    face.tex = {static_cast<int>(textures.size()) - 1, -1, -1};
                } else if (is_word(item, "texture_list")) {
                    // `texture_list { T1, T2, T3 }`: a texture at each corner, blended across the triangle.
                    expect("{");
                    for (int k = 0; k < 3; ++k) {
                        if (k > 0) accept(",");
                        const Token id = next();
                        const Value* v = id.kind == TokenKind::Identifier ? lookup(id.text) : nullptr;
                        const auto* tx = v != nullptr ? std::get_if<Boxed<Texture>>(v) : nullptr;
                        if (tx == nullptr) fail(id, "expected a texture identifier in a triangle's texture_list");
                        face.tex[k] = static_cast<int>(mesh.textures.size());
                        mesh.textures.push_back(**tx);
                    }
                    expect("}");
                } else if (is_word(item, "uv_vectors")) {
                    // `uv_vectors <u,v>, <u,v>, <u,v>`: one uv pair for each corner, for uv_mapping.
                    for (int k = 0; k < 3; ++k) {
                        if (k > 0) accept(",");
                        face.uv[k] = static_cast<int>(mesh.uvs.size());
                        const Vec3 uv = parse_vector();
                        mesh.uvs.push_back({uv.x, uv.y, 0.0});
                    }
                } else {
                    fail(item, "expected 'texture', 'texture_list', 'uv_vectors' or '}' in a mesh triangle but found " +
                                   describe_token(item));
                }
            }
        } else if (is_word(t, "inside_vector")) {
            next();
            mesh.inside_vector = parse_vector();
        } else {
            break;
        }
    }
    if (mesh.faces.empty()) fail(kw, "a mesh needs at least one triangle");
    return mesh;
}

// Reads `{ count, item, item, ... }` where `read_item` consumes one item.
template <typename F>
void Parser::parse_counted_list(const Token& kw, F read_item) {
    expect("{");
    const Token at = peek();
    const double count = parse_float();
    if (count < 0 || count != std::floor(count)) fail(at, "expected a non-negative whole count");
    for (int i = 0; i < static_cast<int>(count); ++i) {
        accept(",");
        read_item();
    }
    accept(",");
    if (!accept("}")) fail(peek(), "more items in '" + kw.text + "' than its count of " + std::to_string(int(count)));
}

Mesh Parser::parse_mesh2_body(const Token& kw) {
    Mesh mesh;
    mesh.kind = Mesh::Kind::Mesh2;
    std::vector<std::array<int, 3>> normal_indices;
    std::vector<std::array<int, 3>> uv_indices;
    auto read_index_triple = [&](std::array<int, 3>& out) {
        const Vec3 v = parse_vector();
        for (int k = 0; k < 3; ++k) out[k] = static_cast<int>(std::lround(v[k]));
    };
    while (true) {
        expand_macros();
        const Token t = peek();
        if (is_word(t, "hierarchy")) {
            next();
            parse_bool_optional();
        } else if (is_word(t, "vertex_vectors")) {
            next();
            parse_counted_list(t, [&] { mesh.vertices.push_back(parse_vector()); });
        } else if (is_word(t, "normal_vectors")) {
            next();
            parse_counted_list(t, [&] { mesh.normals.push_back(parse_vector()); });
        } else if (is_word(t, "uv_vectors")) {
            next();
            parse_counted_list(t, [&] {
                const Vec3 uv = parse_vector();
                mesh.uvs.push_back({uv.x, uv.y, 0.0});
            });
        } else if (is_word(t, "texture_list")) {
            next();
            parse_counted_list(t, [&] {
                const Token tex = next();
                if (!is_word(tex, "texture")) fail(tex, "expected 'texture' in texture_list");
                mesh.textures.push_back(parse_texture_body(tex));
            });
        } else if (is_word(t, "face_indices")) {
            next();
            parse_counted_list(t, [&] {
                Mesh::Face f;
                read_index_triple(f.v);
                // Optional texture indices after the triple: one or three floats; a vector (`F2+A` in shapes.inc's
                // height-field macros) is the next face.
                for (int k = 0;; ++k) {
                    accept(",");
                    const Token& p = peek();
                    const Value* v = p.kind == TokenKind::Identifier ? lookup(p.text) : nullptr;
                    const auto* n = v != nullptr ? std::get_if<Numeric>(v) : nullptr;
                    if (!(p.kind == TokenKind::Number || is_punct(p, "(") || (n != nullptr && n->n == 1))) break;
                    const int index = static_cast<int>(parse_float());
                    if (k < 3) f.tex[k] = index;
                }
                mesh.faces.push_back(f);
            });
        } else if (is_word(t, "normal_indices")) {
            next();
            parse_counted_list(t, [&] {
                std::array<int, 3> n{};
                read_index_triple(n);
                normal_indices.push_back(n);
            });
        } else if (is_word(t, "uv_indices")) {
            next();
            parse_counted_list(t, [&] {
                std::array<int, 3> uv{};
                read_index_triple(uv);
                uv_indices.push_back(uv);
            });
        } else if (is_word(t, "inside_vector")) {
            next();
            mesh.inside_vector = parse_vector();
        } else {
            break;
        }
    }
    if (mesh.vertices.empty() || mesh.faces.empty()) fail(kw, "mesh2 needs vertex_vectors and face_indices");
    const int nv = static_cast<int>(mesh.vertices.size());
    const int nn = static_cast<int>(mesh.normals.size());
    for (std::size_t i = 0; i < mesh.faces.size(); ++i) {
        Mesh::Face& f = mesh.faces[i];
        for (int k = 0; k < 3; ++k)
            if (f.v[k] < 0 || f.v[k] >= nv) fail(kw, "mesh2 face " + std::to_string(i) + " has a vertex index out of range");
        // POV-Ray compat: without normal_indices, normal_vectors pair with the vertices by index.
        if (i < normal_indices.size()) {
            f.n = normal_indices[i];
        } else if (nn == nv && normal_indices.empty()) {
            f.n = f.v;
        }
        for (int k = 0; k < 3; ++k)
            if (f.n[k] >= nn) fail(kw, "mesh2 face " + std::to_string(i) + " has a normal index out of range");
        // POV-Ray compat: without uv_indices, uv_vectors pair with the vertices by index.
        if (i < uv_indices.size()) f.uv = uv_indices[i];
        else if (uv_indices.empty() && !mesh.uvs.empty()) f.uv = f.v;
        for (int k = 0; k < 3; ++k)
            if (f.uv[k] >= static_cast<int>(mesh.uvs.size()))
                fail(kw, "mesh2 face " + std::to_string(i) + " has a uv index out of range");
        // A face's texture indices are a single one or one per corner.
        const int nt = static_cast<int>(mesh.textures.size());
        if (nt == 0) f.tex = {-1, -1, -1};
        for (int k = 0; k < 3; ++k)
            if (f.tex[k] >= nt) fail(kw, "mesh2 face " + std::to_string(i) + " has a texture index out of range");
        if (f.tex[0] >= 0 && (f.tex[1] < 0) != (f.tex[2] < 0)) f.tex[1] = f.tex[2] = -1;
    }
    return mesh;
}

}  // namespace wardray::parser
