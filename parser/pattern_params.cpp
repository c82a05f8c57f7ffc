// Pattern parameters: what follows the fractal, quilted and spiral keywords, their modifiers (exponent, exterior,
// interior, control0, control1) and `warp { ... }` blocks, read as POV-Ray 3.7's Parse_Pattern and Parse_Warp do.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <memory>
#include <mutex>
#include <optional>

#include "core/constants.h"
#include "parser/parser.h"

namespace wardray::parser {

namespace {

using PType = Pattern::Type;

bool is_fractal(PType t) { return t == PType::Mandel || t == PType::Julia || t == PType::Magnet; }

// POV-Ray compat: quilted's controls, a repeat's width and turbulence's omega and lambda are single precision.
double single(double v) { return static_cast<double>(static_cast<float>(v)); }

}  // namespace

int Parser::parse_pattern_parameters(const Token& t, Pattern& pat) {
    switch (pat.type) {
        case PType::Mandel:
        case PType::Julia:
        case PType::Magnet:
            pat.params->interior_type = 0;
            pat.params->exterior_type = 1;
            pat.params->interior_factor = pat.params->exterior_factor = 1.0;
            pat.params->fractal_exponent = 2;
            if (pat.type == PType::Magnet) {
                const int kind = static_cast<int>(parse_float());
                if (kind != 1 && kind != 2) fail(t, "magnet type must be 1 or 2");
                pat.params->magnet_type = kind;
                const Token form = next();
                if (is_word(form, "julia")) pat.params->magnet_julia = true;
                else if (is_word(form, "mandel")) pat.params->magnet_julia = false;
                else fail(form, "expected 'mandel' or 'julia' after 'magnet " + std::to_string(kind) + "'");
            }
            if (pat.type == PType::Julia || (pat.type == PType::Magnet && pat.params->magnet_julia)) {
                const Numeric c = parse_numeric();
                pat.params->julia_re = c.v[0];
                pat.params->julia_im = c.n > 1 ? c.v[1] : c.v[0];
                accept(",");
            }
            pat.params->fractal_iterations = static_cast<int>(parse_float());
            return 0;
        case PType::PigmentPattern:
            pat.params->pigment.pigment = std::make_shared<const Pigment>(parse_pigment_body(t));
            return 0;
        case PType::DensityFile: {
            const Token df3 = next();
            if (!is_word(df3, "df3")) fail(df3, "expected 'df3' after density_file but found " + describe_token(df3));
            const Token at = peek();
            pat.params->density_file = read_density_file(at, parse_string());
            pat.params->density_interpolation = 0;
            return 0;
        }
        case PType::Slope:
            parse_slope_parameters(t, pat);
            return 0;
        case PType::ImagePattern:
            parse_image_pattern(t, pat);
            return 0;
        case PType::Quilted:
            pat.params->control0 = pat.params->control1 = 1.0;
            pat.params->frequency = 0.0;
            return 0;
        case PType::Spiral1:
        case PType::Spiral2:
            // POV-Ray compat: the arm count is a short, and spirals default to the triangle wave.
            pat.params->arms = static_cast<short>(parse_float());
            pat.params->wave = WaveType::Triangle;
            return 0;
        case PType::Tiling: {
            // POV-Ray compat: the tiling number is kept as an unsigned char (so 261 is tiling 5), then checked.
            const Token at = peek();
            const double n = parse_float();
            pat.params->tiling_type = static_cast<int>(static_cast<unsigned char>(static_cast<int>(n)));
            if (pat.params->tiling_type < 1 || pat.params->tiling_type > 27) fail(at, "Tiling number must be between 1 and 27.");
            return 0;
        }
        default:
            return 0;
    }
}

bool Parser::parse_pattern_extra(const Token& t, Pattern& pat) {
    const std::string w = t.text;
    if (w == "warp") {
        next();
        parse_warp(t, pat);
        return true;
    }
    if (w == "interpolate") {
        if (pat.type != PType::DensityFile) fail(t, "Cannot use interpolate with non-density_file.");
        next();
        pat.params->density_interpolation = static_cast<int>(parse_float());
        if (pat.params->density_interpolation % 10 == 2) warn_unsupported(t, "density_file interpolate 2 (tricubic)");
        return true;
    }
    if (w == "control0" || w == "control1") {
        if (pat.type != PType::Quilted) return false;
        next();
        (w == "control0" ? pat.params->control0 : pat.params->control1) = single(parse_float());
        return true;
    }
    if (w != "exponent" && w != "exterior" && w != "interior") return false;
    if (!is_fractal(pat.type) || (w == "exponent" && pat.type == PType::Magnet)) return false;
    next();
    const int v = static_cast<int>(parse_float());
    if (w == "exponent") {
        pat.params->fractal_exponent = v;
        if (v < 2 || v > 33) {
            warn(t, "invalid " + std::string(pat.type == PType::Mandel ? "mandel" : "julia") +
                        " pattern exponent; supported exponents are 2 to 33, using 2");
            pat.params->fractal_exponent = 2;
        }
        return true;
    }
    accept(",");
    const double factor = parse_float();
    if (w == "exterior") {
        if (v < 0 || v > 8) fail(t, "invalid fractal pattern exterior type; valid types are 0 to 8");
        pat.params->exterior_type = v;
        pat.params->exterior_factor = factor;
    } else {
        if (v < 0 || v > 6) fail(t, "invalid fractal pattern interior type; valid types are 0 to 6");
        pat.params->interior_type = v;
        pat.params->interior_factor = factor;
    }
    return true;
}

void Parser::parse_warp(const Token& kw, Pattern& pat) {
    expect("{");
    using WType = Warp::Type;
    Warp w;
    const Token t = next();
    if (is_word(t, "turbulence")) {
        w.type = WType::Turbulence;
        w.turbulence.amount = parse_vector();
        while (true) {
            if (accept_keyword("octaves")) w.turbulence.octaves = std::clamp(static_cast<int>(parse_float()), 1, 10);
            else if (accept_keyword("omega")) w.turbulence.omega = single(parse_float());
            else if (accept_keyword("lambda")) w.turbulence.lambda = single(parse_float());
            else break;
        }
    } else if (is_word(t, "repeat")) {
        w.type = WType::Repeat;
        const Vec3 v = parse_vector();
        int axes = 0;
        for (int i = 0; i < 3; ++i)
            if (v[i] != 0.0) w.axis = i, ++axes;
        if (axes == 0) fail(t, "no axis specified in repeat");
        if (axes > 1) fail(t, "can only repeat along 1 axis");
        w.width = single(v[w.axis]);  // POV-Ray compat: the repeat width is single precision
        while (true) {
            if (accept_keyword("offset")) {
                w.offset = parse_vector();
            } else if (accept_keyword("flip")) {
                const Vec3 f = parse_vector();
                for (int i = 0; i < 3; ++i) w.flip[i] = f[i] != 0.0 ? -1.0 : 1.0;
            } else {
                break;
            }
        }
    } else if (is_word(t, "black_hole")) {
        w.type = WType::BlackHole;
        w.center = parse_vector();
        accept(",");
        w.radius = parse_float();
        while (true) {
            if (accept_keyword("strength")) w.strength = parse_float();
            else if (accept_keyword("falloff")) w.falloff = parse_float();
            else if (accept_keyword("inverse")) w.inverse = true;
            else if (accept_keyword("type")) w.hole_type = static_cast<int>(parse_float());
            else if (accept_keyword("repeat")) w.repeat_vector = parse_vector(), w.repeat = true, check_black_hole(t, w);
            else if (accept_keyword("turbulence")) w.uncertainty = parse_vector(), w.uncertain = true, check_black_hole(t, w);
            else break;
        }
    } else if (is_word(t, "cylindrical") || is_word(t, "spherical") || is_word(t, "toroidal")) {
        w.type = t.text == "cylindrical" ? WType::Cylindrical : t.text == "spherical" ? WType::Spherical : WType::Toroidal;
        while (true) {
            if (accept_keyword("orientation")) w.orientation = normalize(parse_vector());
            else if (accept_keyword("dist_exp")) w.dist_exp = parse_float();
            else if (w.type == WType::Toroidal && accept_keyword("major_radius")) w.major_radius = parse_float();
            else break;
        }
    } else if (is_word(t, "planar")) {
        w.type = WType::Planar;
        if (!is_punct(peek(), "}")) {
            w.orientation = normalize(parse_vector());
            accept(",");
            w.plane_offset = parse_float();
        }
    } else if (is_word(t, "cubic")) {
        w.type = WType::Cubic;
    } else {
        fail(t, "expected a warp type (turbulence, repeat, black_hole, cylindrical, spherical, toroidal, planar or "
                "cubic) but found " + describe_token(t));
    }
    if (!accept("}")) fail(peek(), "expected '}' to close '" + kw.text + "' but found " + describe_token(peek()));
    // POV-Ray's warp list runs from the last item given to the first: the new warp goes in front, after the
    // transforms given so far (which become a transform warp of their own).
    if (!pat.transform.is_identity()) {
        Warp tr;
        tr.transform = pat.transform;
        pat.warps.insert(pat.warps.begin(), tr);
        pat.transform = Transform{};
    }
    pat.warps.insert(pat.warps.begin(), w);
}

std::vector<SlopeMapEntry> Parser::parse_slope_map() {
    // `slope_map { [value <height, slope>] ... }` (POV-Ray's SLOPE_TYPE blend map).
    expect("{");
    std::vector<SlopeMapEntry> map;
    while (!accept("}")) {
        expect("[");
        SlopeMapEntry e;
        e.value = static_cast<double>(static_cast<float>(parse_float()));
        accept(",");
        const Numeric hs = parse_numeric();
        e.height = hs.v[0];
        e.slope = hs.n > 1 ? hs.v[1] : hs.v[0];
        expect("]");
        map.push_back(e);
    }
    return map;
}

void Parser::check_black_hole(const Token& at, Warp& w) {
    // POV-Ray's Check_BH_Parameters: a repeated hole stays inside its cell.
    if (!w.repeat) return;
    for (int i = 0; i < 3; ++i) {
        if (w.repeat_vector[i] <= 0.0) continue;
        if (w.center[i] < w.radius) w.center[i] = w.radius;
        const double least = w.center[i] + w.radius + w.uncertainty[i];
        if (w.repeat_vector[i] < least) {
            w.repeat_vector[i] = least;
            warn(at, "black hole repeat vector too small; increased to " + std::to_string(least));
        }
        if (w.repeat_vector[i] < kPovEpsilon) w.repeat_vector[i] = 0.0;
    }
}

}  // namespace wardray::parser

namespace wardray::parser {

std::shared_ptr<const DensityFile> Parser::read_density_file(const Token& at, const std::string& name) {
    // Found like an include file, and only inside the folders the scene may read (parser/read_access.h).
    const std::optional<std::filesystem::path> where = find_readable(at, std::filesystem::path(name), "", "density file");
    if (!where) fail(at, "Cannot read media density file.");
    const std::filesystem::path found = *where;
    if (auto it = m_density_files.find(found.string()); it != m_density_files.end()) return it->second;
    // Parses alive at the same time share one copy of a file, so their scenes compare equal (patterns compare
    // density files by identity).
    static std::mutex shared_mutex;
    static std::map<std::string, std::weak_ptr<const DensityFile>> shared;
    const std::lock_guard<std::mutex> lock(shared_mutex);
    if (auto it = shared.find(found.string()); it != shared.end())
        if (std::shared_ptr<const DensityFile> alive = it->second.lock()) {
            m_density_files.emplace(found.string(), alive);
            return alive;
        }
    std::ifstream in(found, std::ios::binary);
    const std::vector<unsigned char> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    if (bytes.size() < 6) fail(at, "Error reading density_file");
    // POV-Ray's Read_Density_File: three big-endian 16-bit sizes, then 8-, 16- or 32-bit values by file length.
    auto d = std::make_shared<DensityFile>();
    d->nx = (bytes[0] << 8) | bytes[1];
    d->ny = (bytes[2] << 8) | bytes[3];
    d->nz = (bytes[4] << 8) | bytes[5];
    const std::size_t count = static_cast<std::size_t>(d->nx) * d->ny * d->nz;
    const std::size_t len = bytes.size() - 6;
    std::size_t width = 0;
    if (count * 4 == len) width = 4, d->max = 4294967295.0;
    else if (count * 2 == len) width = 2, d->max = 65535.0;
    else if (count == len) width = 1, d->max = 255.0;
    else fail(at, "Invalid density file size");
    d->raw.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
        std::uint32_t v = 0;
        for (std::size_t b = 0; b < width; ++b) v = (v << 8) | bytes[6 + i * width + b];
        d->raw[i] = v;
    }
    m_density_files.emplace(found.string(), d);
    shared[found.string()] = d;
    return d;
}

}  // namespace wardray::parser
