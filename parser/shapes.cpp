// Shape statements: one reader per keyword of WARDRAY_SHAPES (POV-Ray's primitives, meshes and polygons), and the
// building of CSG nodes (object modifiers are in statements.cpp).
#include <algorithm>
#include <cmath>
#include <string_view>
#include <unordered_map>

#include "core/constants.h"
#include "parser/parser.h"
#include "parser/truetype.h"

namespace wardray::parser {

bool is_shape_keyword(std::string_view w) {
    return std::find(k_shape_keywords.begin(), k_shape_keywords.end(), w) != k_shape_keywords.end();
}

Shape Parser::parse_shape_parameters(const Token& kw) {
    // The keyword's reader, from WARDRAY_SHAPES (callers check is_shape_keyword first).
    using Reader = Shape (*)(Parser&, const Token&);
#define WARDRAY_SHAPE_ENTRY(keyword, Type) \
    {#keyword, [](Parser& p, const Token& k) -> Shape { return p.read_##keyword(k); }},
    static const std::unordered_map<std::string_view, Reader> readers = {WARDRAY_SHAPES(WARDRAY_SHAPE_ENTRY)};
#undef WARDRAY_SHAPE_ENTRY
    return readers.at(kw.text.view())(*this, kw);
}

Sphere Parser::read_sphere(const Token& kw) {
    Sphere s;
    s.center = parse_vector();
    accept(",");  // POV-Ray compat: commas between parameters are optional
    s.radius = parse_float();
    return s;
}

Box Parser::read_box(const Token& kw) {
    Box b;
    b.corner1 = parse_vector();
    accept(",");
    b.corner2 = parse_vector();
    return b;
}

Plane Parser::read_plane(const Token& kw) {
    Plane p;
    const Token at = peek();
    p.normal = parse_vector();
    if (length(p.normal) == 0.0) fail(at, "plane normal must not be zero");
    accept(",");
    p.distance = parse_float();
    return p;
}

Cylinder Parser::read_cylinder(const Token& kw) {
    Cylinder c;
    c.base = parse_vector();
    accept(",");
    c.cap = parse_vector();
    accept(",");
    c.radius = parse_float();
    if (c.base == c.cap) warn(kw, "degenerate cylinder: base and cap are the same point");
    return c;
}

Cone Parser::read_cone(const Token& kw) {
    Cone c;
    c.base = parse_vector();
    accept(",");
    c.base_radius = parse_float();
    accept(",");
    c.cap = parse_vector();
    accept(",");
    c.cap_radius = parse_float();
    if (c.base == c.cap) warn(kw, "degenerate cone: base and cap are the same point");
    return c;
}

Disc Parser::read_disc(const Token& kw) {
    Disc d;
    d.center = parse_vector();
    accept(",");
    d.normal = parse_vector();
    accept(",");
    d.radius = parse_float();
    if (accept(",")) d.hole_radius = parse_float();
    return d;
}

Torus Parser::read_torus(const Token& kw) {
    Torus t;
    t.major = parse_float();
    accept(",");
    t.minor = parse_float();
    return t;
}

Mesh Parser::read_triangle(const Token& kw) {
    Mesh m;
    m.kind = Mesh::Kind::Triangle;
    parse_triangle(m, false);
    return m;
}

Mesh Parser::read_smooth_triangle(const Token& kw) {
    Mesh m;
    m.kind = Mesh::Kind::SmoothTriangle;
    parse_triangle(m, true);
    return m;
}

Mesh Parser::read_mesh(const Token& kw) { return parse_mesh_body(kw); }

Mesh Parser::read_mesh2(const Token& kw) { return parse_mesh2_body(kw); }

Polygon Parser::read_polygon(const Token& kw) {
    Polygon p;
    const Token at = peek();
    const int n = static_cast<int>(std::lround(parse_float()));
    if (n < 3) fail(at, "a polygon needs at least 3 points");
    for (int i = 0; i < n; ++i) {
        accept(",");
        p.points.push_back(parse_vector());  // POV-Ray compat: 2-D points lie in the z = 0 plane
    }
    return p;
}

Quadric Parser::read_quadric(const Token& kw) {
    Quadric q;
    q.squares = parse_vector();
    accept(",");
    q.mixed = parse_vector();
    accept(",");
    q.linear = parse_vector();
    accept(",");
    q.constant = parse_float();
    return q;
}

Prism Parser::read_prism(const Token& kw) {
    Prism p;
    while (true) {
        const Token t = peek();
        if (is_word(t, "linear_spline")) {
            next();
            p.spline = Prism::Spline::Linear;
        } else if (is_word(t, "linear_sweep")) {
            next();
            p.conic = false;
        } else if (is_word(t, "conic_sweep")) {
            next();
            p.conic = true;
        } else if (is_word(t, "quadratic_spline")) {
            next();
            p.spline = Prism::Spline::Quadratic;
        } else if (is_word(t, "cubic_spline")) {
            next();
            p.spline = Prism::Spline::Cubic;
        } else if (is_word(t, "bezier_spline")) {
            next();
            p.spline = Prism::Spline::Bezier;
        } else {
            break;
        }
    }
    p.height1 = parse_float();
    accept(",");
    p.height2 = parse_float();
    accept(",");
    const Token at = peek();
    const int n = static_cast<int>(std::lround(parse_float()));
    // POV-Ray compat: its minimum point counts per spline type.
    switch (p.spline) {
        case Prism::Spline::Linear:
            if (n < 3) fail(at, "a prism with linear_spline needs at least 3 points");
            break;
        case Prism::Spline::Quadratic:
            if (n < 5) fail(at, "a prism with quadratic_spline needs at least 5 points");
            break;
        case Prism::Spline::Cubic:
            if (n < 6) fail(at, "a prism with cubic_spline needs at least 6 points");
            break;
        case Prism::Spline::Bezier:
            if (n <= 0 || n % 4 != 0) fail(at, "a prism with bezier_spline needs 4 points per segment");
            break;
    }
    for (int i = 0; i < n; ++i) {
        accept(",");
        const Vec3 uv = parse_vector();
        p.points.push_back({uv.x, uv.y, 0.0});
    }
    return p;
}

Text Parser::read_text(const Token& kw) { return parse_text_parameters(kw); }

Lathe Parser::read_lathe(const Token& kw) { return parse_lathe_parameters(kw); }

Sor Parser::read_sor(const Token& kw) { return parse_sor_parameters(kw); }

Quartic Parser::read_quartic(const Token& kw) {
    // Thirty-five coefficients in one vector: read them one by one so no 5-component limit applies.
    Quartic q;
    expect("<");
    for (std::size_t i = 0; i < q.coefficients.size(); ++i) {
        // POV-Ray compat: the commas are optional (primitiv.pov and hyptorus.pov leave some out).
        if (i > 0) accept(",");
        // The additive level, as in `matrix`: a '>' here closes the vector, it is no comparison.
        const Token at = peek();
        const Numeric c = parse_additive();
        if (c.n != 1) fail(at, "quartic coefficients must be floats");
        q.coefficients[i] = c.v[0];
    }
    expect(">");
    return q;
}

Superellipsoid Parser::read_superellipsoid(const Token& kw) {
    Superellipsoid s;
    const Vec3 en = parse_vector();
    s.e = en.x;
    s.n = en.y;
    return s;
}

namespace {

// The characters of a text string: ASCII, or UTF-8 sequences under `charset utf8` (bad sequences as bytes).
// POV-Ray compat: under the default `charset ascii` every byte beyond ASCII becomes a space; `replaced` tells.
std::vector<std::uint32_t> text_characters(const std::string& s, bool utf8, bool& replaced) {
    std::vector<std::uint32_t> out;
    replaced = false;
    for (std::size_t i = 0; i < s.size();) {
        const auto b = static_cast<unsigned char>(s[i]);
        if (!utf8 && b >= 0x80) {
            out.push_back(' ');
            replaced = true;
            ++i;
            continue;
        }
        const int extra = !utf8 || b < 0xC0 ? 0 : b < 0xE0 ? 1 : b < 0xF0 ? 2 : 3;
        std::uint32_t c = extra == 0 ? b : b & (0x3F >> extra);
        bool ok = i + extra < s.size();
        for (int k = 1; ok && k <= extra; ++k) {
            const auto cont = static_cast<unsigned char>(s[i + k]);
            ok = (cont & 0xC0) == 0x80;
            c = (c << 6) | (cont & 0x3F);
        }
        if (!ok) c = b;
        out.push_back(c);
        i += ok ? extra + 1 : 1;
    }
    return out;
}

}  // namespace

Text Parser::parse_text_parameters(const Token& kw) {
    const Token kind = next();
    std::string name;
    if (is_word(kind, "ttf")) {
        name = parse_string();
    } else if (is_word(kind, "internal")) {
        // POV-Ray 3.7's built-in fonts are the fonts Debian installs in its include folder.
        const int id = static_cast<int>(parse_float());
        name = id == 1 ? "timrom.ttf" : id == 2 ? "cyrvetic.ttf" : id == 3 ? "crystal.ttf" : "povlogo.ttf";
    } else {
        fail(kind, "expected 'ttf' or 'internal' in text but found " + describe_token(kind));
    }
    accept(",");
    const std::string str = parse_string();
    accept(",");
    Text text;
    text.thickness = parse_float();
    accept(",");
    const Vec3 offset = parse_vector();

    // POV-Ray compat: fonts are searched like include files, and ".ttf" is tried for a name without extension.
    const std::filesystem::path requested(name);
    std::shared_ptr<TrueTypeFont> font;
    std::string error = "No such file or directory";
    for (const SearchCandidate& candidate : search_candidates(requested, ".ttf")) {
        const std::filesystem::path& c = candidate.path;
        std::error_code ec;
        if (!std::filesystem::is_regular_file(c, ec)) continue;
        require_readable(kind, c, "font file");
        const std::string key = std::filesystem::weakly_canonical(c, ec).string();
        if (auto it = m_fonts.find(key); it != m_fonts.end()) {
            font = it->second;
            break;
        }
        std::string load_error;
        auto loaded = TrueTypeFont::load(c, load_error);
        if (!loaded) fail(kind, "cannot read font file '" + c.string() + "': " + load_error);
        font = std::make_shared<TrueTypeFont>(std::move(*loaded));
        m_fonts.emplace(key, font);
        break;
    }
    if (!font) fail(kind, "cannot open font file '" + name + "': " + error);
    bool replaced = false;
    const auto chars = text_characters(str, m_charset_utf8, replaced);
    if (replaced)
        warn(kw, "non-ASCII characters in the text are replaced by spaces, as POV-Ray does under charset ascii "
                 "(global_settings { charset utf8 } reads them as UTF-8)");
    auto glyphs = font->layout(chars, offset, m_charset_utf8, error);
    if (!glyphs) fail(kw, "cannot read the glyphs of '" + name + "': " + error);
    text.glyphs = std::move(*glyphs);
    return text;
}

Lathe Parser::parse_lathe_parameters(const Token& kw) {
    Lathe lathe;
    while (true) {
        const Token& t = peek();
        if (is_word(t, "linear_spline")) lathe.spline = Lathe::Spline::Linear;
        else if (is_word(t, "quadratic_spline")) lathe.spline = Lathe::Spline::Quadratic;
        else if (is_word(t, "cubic_spline")) lathe.spline = Lathe::Spline::Cubic;
        else if (is_word(t, "bezier_spline")) lathe.spline = Lathe::Spline::Bezier;
        else break;
        next();
    }
    const Token at = peek();
    const int n = static_cast<int>(parse_float());
    switch (lathe.spline) {
        case Lathe::Spline::Linear:
            if (n < 2) fail(at, "a lathe with linear_spline needs at least 2 points");
            break;
        case Lathe::Spline::Quadratic:
            if (n < 3) fail(at, "a lathe with quadratic_spline needs at least 3 points");
            break;
        case Lathe::Spline::Cubic:
            if (n < 4) fail(at, "a lathe with cubic_spline needs at least 4 points");
            break;
        case Lathe::Spline::Bezier:
            if (n <= 0 || n % 4 != 0) fail(at, "a lathe with bezier_spline needs 4 points per segment");
            break;
    }
    for (int i = 0; i < n; ++i) {
        accept(",");
        const Token pt = peek();
        const Vec3 uv = parse_vector();
        // POV-Ray compat: only the first and the last point may lie left of the axis.
        if (i > 0 && i < n - 1 && uv.x < 0.0) fail(pt, "incorrect point in lathe: negative radius");
        lathe.points.push_back({uv.x, uv.y, 0.0});
    }
    return lathe;
}

Sor Parser::parse_sor_parameters(const Token& kw) {
    Sor sor;
    const Token at = peek();
    const int n = static_cast<int>(parse_float());
    if (n < 4) fail(at, "a surface of revolution needs at least 4 points");
    for (int i = 0; i < n; ++i) {
        accept(",");
        const Token pt = peek();
        const Vec3 uv = parse_vector();
        // POV-Ray compat: radii are not negative and the inner points climb strictly.
        if (uv.x < 0.0 || (i > 1 && i < n - 1 && uv.y <= sor.points.back().y))
            fail(pt, "incorrect point in surface of revolution");
        sor.points.push_back({uv.x, uv.y, 0.0});
    }
    for (int i = 0; i + 3 < n; ++i)
        if (std::fabs(sor.points[i + 2].y - sor.points[i].y) < kPovEpsilon ||
            std::fabs(sor.points[i + 3].y - sor.points[i + 1].y) < kPovEpsilon)
            fail(kw, "incorrect point in surface of revolution: two heights too close");
    if (is_word(peek(), "open")) {
        next();
        sor.open = true;
    }
    return sor;
}

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
                    face.tex = {static_cast<int>(mesh.textures.size()), -1, -1};
                    mesh.textures.push_back(parse_texture_body(item));
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

std::optional<Object> Parser::as_single_object(ObjectValue& ov) {
    if (ov.parts.empty()) return std::nullopt;
    if (!ov.compound && ov.parts.size() == 1) {
        Object o = std::move(ov.parts.front().object);
        o.has_texture = ov.parts.front().has_texture;
        return o;
    }
    // The union's transforms are already in its parts, so the node itself sits at the identity.
    Object node;
    node.loc = ov.parts.front().object.loc;
    const Object& first = ov.parts.front().object;
    node.no_shadow = first.no_shadow;
    node.no_image = first.no_image;
    node.no_reflection = first.no_reflection;
    node.no_radiosity = first.no_radiosity;
    node.has_texture = ov.texture.has_value();
    node.texture = ov.texture.value_or(default_texture());
    Csg csg;
    for (ObjectPart& part : ov.parts) {
        part.object.has_texture = part.has_texture;
        csg.children.push_back(std::move(part.object));
    }
    node.shape = std::move(csg);
    return node;
}

void Parser::make_union_node(ObjectValue& ov) {
    if (!ov.compound) return;
    auto node = as_single_object(ov);
    ov.parts.clear();
    ov.compound = false;
    ov.texture.reset();
    if (!node) return;
    ObjectPart part;
    part.has_texture = node->has_texture;
    part.object = std::move(*node);
    ov.parts.push_back(std::move(part));
}

std::vector<Object> Parser::parse_object_list(const Token& kw, const std::vector<Object>* bounded_by) {
    expect("{");
    std::vector<Object> list;
    while (true) {
        expand_macros();
        Transform tr;
        if (!list.empty() && parse_transform_item(peek(), tr)) {
            // POV-Ray compat: transforms after the objects move all of them (Parse_Bound_Clip).
            for (Object& o : list) o.transform = o.transform.then(tr);
            continue;
        }
        const Token t = next();
        if (is_punct(t, "}")) return list;
        if (bounded_by != nullptr && is_word(t, "bounded_by")) {
            // POV-Ray compat: `clipped_by { bounded_by }` clips by the bounding objects.
            list.insert(list.end(), bounded_by->begin(), bounded_by->end());
        } else if (bounded_by == nullptr && is_word(t, "clipped_by")) {
            // `bounded_by { clipped_by }`: bounds are only an optimisation, nothing to record.
        } else if (is_object_start(t)) {
            ObjectValue child = parse_object(t);
            if (auto o = as_single_object(child)) list.push_back(std::move(*o));
        } else {
            fail(t, "expected an object in '" + kw.text + "' but found " + describe_token(t));
        }
    }
}

}  // namespace wardray::parser
