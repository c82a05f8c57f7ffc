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

Ovus Parser::read_ovus(const Token& kw) {
    Ovus o;
    const Token at = peek();
    o.bottom_radius = parse_float();
    accept(",");
    o.top_radius = parse_float();
    if (o.bottom_radius < 0.0 || o.top_radius < 0.0) fail(at, "both ovus radii must be positive");
    // POV-Ray compat: POV-Ray 3.7.0 draws the top sphere alone then (geometry/ovus.cpp does the same).
    if (!(o.top_radius < 2.0 * o.bottom_radius))
        warn(kw, "ovus second radius should be less than twice first radius; a sphere is drawn instead, as "
                 "POV-Ray substitutes it");
    return o;
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
    node.interior.hollow = first.interior.hollow;
    // The union's own interior becomes the node's, which the parts that shared it inherit.
    node.interior_id = ov.interior_id;
    Csg csg;
    for (ObjectPart& part : ov.parts) {
        part.object.has_texture = part.has_texture;
        if (ov.interior_id != 0 && part.object.interior_id == ov.interior_id) {
            const bool hollow = node.interior.hollow;
            node.interior = part.object.interior;
            node.interior.hollow = hollow;
            part.object.interior_id = 0;
        }
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
    ov.interior_id = 0;
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

// Other shapes' roots are found alike with or without Sturm sequences; the flag reaches only polynomials.
void ObjectReader::read_sturm(ObjectReader& r, ObjectValue& ov, const Token&, ModifierState&) {
    const bool sturm = r.parse_bool_optional();
    for (ObjectPart& part : ov.parts) {
        if (auto* q = std::get_if<scene::Quartic>(&part.object.shape)) q->sturm = sturm;
        if (auto* p = std::get_if<scene::Poly>(&part.object.shape)) p->sturm = sturm;
    }
}

}  // namespace wardray::parser
