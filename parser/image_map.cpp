// image_map pigments: the image file (read through ParseOptions::read_image), its gamma and its mapping.
#include <cmath>
#include <string_view>
#include <vector>

#include "parser/parser.h"

namespace wardray::parser {

namespace {

/// The image file types POV-Ray names before the file; the name alone is enough for the reader.
bool is_image_type(const TokenText& w) {
    static const char* const types[] = {"gif", "tga", "iff", "ppm", "pgm", "png", "jpeg", "tiff", "sys", "exr", "hdr"};
    for (const char* t : types)
        if (w == t) return true;
    return false;
}

/// The extensions POV-Ray appends to a name without one, by the image type named before it.
std::vector<const char*> image_extensions(std::string_view type) {
    if (type == "tga") return {".tga", ".TGA"};
    if (type == "png") return {".png", ".PNG"};
    if (type == "ppm") return {".ppm", ".PPM"};
    if (type == "pgm") return {".pgm", ".PGM"};
    if (type == "gif") return {".gif", ".GIF"};
    if (type == "iff") return {".iff", ".IFF", ".lbm", ".LBM"};
    if (type == "jpeg") return {".jpg", ".JPG", ".jpeg", ".JPEG"};
    if (type == "tiff") return {".tif", ".TIF", ".tiff", ".TIFF"};
    if (type == "exr") return {".exr", ".EXR"};
    if (type == "hdr") return {".hdr", ".HDR"};
    return {""};
}

}  // namespace

std::shared_ptr<const ImageData> Parser::read_image_file(const Token& at, const std::string& name,
                                                          const std::optional<GammaCurve>& file_gamma,
                                                          std::string_view type) {
    if (!m_options.read_image) fail(at, "image_map cannot read images here (no image reader)");
    std::filesystem::path found;
    for (const char* extension : image_extensions(type)) {
        for (const SearchCandidate& candidate : search_candidates(std::filesystem::path(name), extension)) {
            std::error_code ec;
            if (std::filesystem::is_regular_file(candidate.path, ec)) {
                found = candidate.path;
                break;
            }
        }
        if (!found.empty()) break;
    }
    if (found.empty()) fail(at, "cannot open image file '" + name + "'");
    // The working gamma the texels are taken into, and how the file was encoded (POV-Ray 3.7's rules, see
    // core/gamma.h): `gamma G` if given, else sRGB for 8- and 16-bit files and linear for float ones; a scene
    // for POV-Ray before 3.7 with assumed_gamma takes untagged files to be in the working gamma, and one
    // without gamma handling uses the values as they are.
    const bool handling = m_working_gamma.has_value() || (m_version_given && m_version >= 3.7);
    const GammaCurve working = m_working_gamma.value_or(GammaCurve::neutral());
    std::string key = found.string() + '\n' + (file_gamma ? std::to_string(file_gamma->gamma) : "file") +
                      std::to_string(static_cast<int>(file_gamma ? file_gamma->kind : GammaCurve::Kind::Neutral)) +
                      '\n' + std::to_string(working.gamma) + std::to_string(handling) +
                      std::to_string(m_version >= 3.7);
    if (auto it = m_images.find(key); it != m_images.end()) {
        if (it->second->has_alpha) warn_unsupported(at, "image_map alpha channel");
        return it->second;
    }
    bool encoded = false;
    std::string error;
    const std::shared_ptr<const ImageData> stored = m_options.read_image(found, encoded, error);
    if (!stored) fail(at, "cannot read image file '" + found.string() + "': " + error);
    // POV-Ray takes transparency from an alpha channel; the reader does not return it.
    if (stored->has_alpha) warn_unsupported(at, "image_map alpha channel");
    auto image = std::make_shared<ImageData>(*stored);
    const GammaCurve srgb = GammaCurve::srgb();
    GammaCurve from = encoded ? srgb : GammaCurve::neutral();
    if (file_gamma) from = *file_gamma;
    else if (encoded && m_version < 3.7 && m_working_gamma) from = working;
    const GammaTranscoding to_working = transcoding(working, from);
    if (handling)
        for (float& v : image->rgb) v = static_cast<float>(to_working.decode(v));
    m_images.emplace(std::move(key), image);
    return image;
}

void Parser::parse_image_map(const Token& kw, Pigment& p) {
    expect("{");
    const std::size_t depth = m_brace_depth;
    ImageMap map;
    if (peek().kind == TokenKind::Identifier && peek().text == "function") {
        warn_unsupported(peek(), "image_map function");
        skip_to_close(kw, "}", depth);
        return;
    }
    std::string type;
    if (peek().kind == TokenKind::Identifier && is_image_type(peek().text)) type = next().text.view();
    const Token file = peek();
    const std::string name = parse_string();
    std::optional<GammaCurve> file_gamma;
    while (true) {
        expand_macros();
        const Token t = next();
        if (is_punct(t, "}")) break;
        if (t.kind == TokenKind::EndOfFile) fail(kw, "'image_map' has no closing '}'");
        const TokenText& w = t.text;
        if (w == "gamma") {
            if (accept_keyword("srgb")) {
                file_gamma = GammaCurve::srgb();
            } else {
                const double g = parse_float();
                if (!(g > 0.0)) fail(t, "gamma value must be positive");
                file_gamma = GammaCurve::power_law(g);
            }
        } else if (w == "premultiplied") {
            parse_bool_optional();
        } else if (w == "once") {
            map.once = true;
        } else if (w == "interpolate") {
            map.interpolate = static_cast<int>(parse_float());
            if (map.interpolate != 2 && map.interpolate != 4) {
                if (map.interpolate == 3) warn_unsupported(t, "image_map interpolate 3 (bicubic)");
                else fail(t, "Invalid interpolate value.");
            }
        } else if (w == "map_type") {
            map.map_type = static_cast<int>(parse_float());
            if (map.map_type != 0 && map.map_type != 1 && map.map_type != 2 && map.map_type != 5)
                fail(t, "Invalid map_type value.");
        } else if (w == "use_color" || w == "use_colour") {
            // the default for an image_map
        } else if ((w == "filter" || w == "transmit") && accept_keyword("all")) {
            (w == "filter" ? map.filter_all : map.transmit_all) = parse_float();
        } else if (w == "filter" || w == "transmit" || w == "use_index" || w == "repeat" || w == "offset" ||
                   w == "alpha") {
            warn_unsupported(t, "image_map " + w);
            skip_to_close(kw, "}", depth);
            break;
        } else {
            fail(t, "expected an image_map item but found '" + w + "'");
        }
    }
    map.image = read_image_file(file, name, file_gamma, type);
    p.image_map = std::move(map);
    p.color_map.clear();
    p.pigment_map.clear();
}

}  // namespace wardray::parser
