// image_map pigments: the image file (read through ParseOptions::read_image), its gamma and its mapping.
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <string_view>
#include <vector>

#include "parser/parser.h"

namespace wardray::parser {

namespace {

/// The image file types POV-Ray names before the file; the name alone is enough for the reader.
bool is_image_type(const TokenText& w) {
    if (w.view().empty()) return false;
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
                                                          const std::optional<GammaCurve>& file_gamma, bool colour,
                                                          std::string_view type) {
    if (!m_options.read_image) fail(at, "image_map cannot read images here (no image reader)");
    // A name without its extension is also tried with the extensions of the type named before it, as POV-Ray does.
    std::optional<std::filesystem::path> where;
    for (const char* extension : image_extensions(type)) {
        where = find_readable(at, std::filesystem::path(name), extension, "image file");
        if (where) break;
    }
    if (!where) fail(at, "cannot open image file '" + name + "'");
    const std::filesystem::path& found = *where;
    // The working gamma the texels are taken into, and how the file was encoded (POV-Ray 3.7's rules, see
    // core/gamma.h): `gamma G` if given, else sRGB for 8- and 16-bit files and linear for float ones; a scene
    // for POV-Ray before 3.7 with assumed_gamma takes untagged files to be in the working gamma, and one
    // without gamma handling uses the values as they are. POV-Ray compat: the images of bump maps and material
    // maps (not `colour`) keep their stored values unless a `gamma` is given, which decodes them to linear.
    const bool handling = colour ? m_working_gamma.has_value() || (m_version_given && m_version >= 3.7)
                                 : file_gamma.has_value();
    const GammaCurve working = colour ? m_working_gamma.value_or(GammaCurve::neutral()) : GammaCurve::neutral();
    std::string key = found.string() + '\n' + (file_gamma ? std::to_string(file_gamma->gamma) : "file") +
                      std::to_string(static_cast<int>(file_gamma ? file_gamma->kind : GammaCurve::Kind::Neutral)) +
                      '\n' + std::to_string(working.gamma) + std::to_string(handling) +
                      std::to_string(m_version >= 3.7) + std::to_string(m_version_given) + (colour ? "c" : "v");
    if (auto it = m_images.find(key); it != m_images.end()) {
        if (it->second->has_alpha && it->second->palette_alpha.empty() && it->second->alpha.empty() && colour)
            warn_unsupported(at, "image_map alpha channel");
        return it->second;
    }
    bool encoded = false;
    std::string error;
    const std::shared_ptr<ImageData> image = m_options.read_image(found, encoded, error);
    if (!image) fail(at, "cannot read image file '" + found.string() + "': " + error);
    // POV-Ray takes transparency from an alpha channel (a true-colour image's alpha, a palette's tRNS); a reader
    // that returns neither is warned of. Bump maps and material maps use only the colours or indices.
    if (image->has_alpha && image->palette_alpha.empty() && image->alpha.empty() && colour)
        warn_unsupported(at, "image_map alpha channel");
    const GammaCurve srgb = GammaCurve::srgb();
    GammaCurve from = encoded ? srgb : GammaCurve::neutral();
    // POV-Ray compat: a scene with no #version is read as POV-Ray 3.62's, and a pre-3.7 scene with assumed_gamma
    // takes an untagged file to be in the working gamma. Only a PNG may carry its own gamma (gAMA, sRGB), which
    // POV-Ray honours there; a JPEG, GIF, TGA, BMP or PPM never does.
    const std::string extension = found.extension().string();
    const bool png = type == "png" || (type.empty() && (extension == ".png" || extension == ".PNG"));
    const bool pre_37 = png ? m_version < 3.7 : !(m_version_given && m_version >= 3.7);
    // POV-Ray compat: a PNG's own sRGB chunk, else its gAMA chunk, says how it is encoded (a pre-3.7 scene's
    // working-gamma default is only for a PNG that says neither).
    const bool declared = png && encoded && (image->declared_srgb || image->declared_file_gamma > 0.0);
    if (file_gamma) from = *file_gamma;
    else if (declared && image->declared_srgb) from = srgb;
    else if (declared) from = GammaCurve::power_law(1.0 / image->declared_file_gamma);
    else if (encoded && pre_37 && m_working_gamma) from = working;
    const GammaTranscoding to_working = transcoding(working, from);
    if (handling) {
        // Most texels are bytes over 255: each of the 256 is decoded once, the rest one by one.
        std::array<float, 256> byte_decoded;
        for (int k = 0; k < 256; ++k)
            byte_decoded[k] = static_cast<float>(to_working.decode(static_cast<float>(k) * (1.0f / 255.0f)));
        for (float& v : image->rgb) {
            const float k = std::nearbyint(v * 255.0f);
            if (k >= 0.0f && k <= 255.0f && k * (1.0f / 255.0f) == v) v = byte_decoded[static_cast<int>(k)];
            else v = static_cast<float>(to_working.decode(v));
        }
    }
    if (image->table_grey8) {
        // POV-Ray compat: such a file is read through a colour table of decoded values, and each texel is stored
        // in an 8-bit grey image as its entry's grey (weights 0.297, 0.589, 0.114 in float) times 255, cut: dark
        // linear values fall to whole levels of 255 (most to 0), and about a third of the others one level lower.
        for (float& v : image->rgb) {
            const float grey = v * 0.297f + v * 0.589f + v * 0.114f;
            v = static_cast<float>(static_cast<unsigned char>(std::clamp(grey, 0.0f, 1.0f) * 255.0f)) / 255.0f;
        }
    }
    m_images.emplace(std::move(key), image);
    return image;
}

ImageMap Parser::parse_image_block(const Token& kw, ImageBlock block, const std::function<bool(const Token&)>& item) {
    const std::size_t depth = m_brace_depth;
    ImageMap map;
    std::string type;
    if (peek().kind == TokenKind::Identifier && is_image_type(peek().text)) type = next().text.view();
    const Token file = peek();
    const std::string name = parse_string();
    std::optional<GammaCurve> file_gamma;
    // filter and transmit for one palette entry (-1: all), in the order given.
    struct PaletteSetting {
        Token at;
        bool transmit = false;
        int index = -1;
        double value = 0.0;
    };
    std::vector<PaletteSetting> palette;
    const bool image_map = block == ImageBlock::ImageMap;
    while (true) {
        expand_macros();
        const Token t = peek();
        if (is_punct(t, "}")) {
            next();
            break;
        }
        if (t.kind == TokenKind::EndOfFile) fail(kw, "'" + kw.text + "' has no closing '}'");
        if (item && item(t)) continue;
        next();
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
            if (map.interpolate == 3) warn_unsupported(t, kw.text + " interpolate 3 (bicubic)");
            else if (image_map && map.interpolate != 2 && map.interpolate != 4) fail(t, "Invalid interpolate value.");
            else if (map.interpolate != 0 && map.interpolate != 2 && map.interpolate != 4)
                warn_unsupported(t, kw.text + " interpolate " + std::to_string(map.interpolate));
        } else if (w == "map_type") {
            map.map_type = static_cast<int>(parse_float());
            const bool known = map.map_type == 0 || map.map_type == 1 || map.map_type == 2 || map.map_type == 5;
            // POV-Ray compat: only an image_map checks it; another value maps as planar elsewhere.
            if (!known && image_map) fail(t, "Invalid map_type value.");
            if (!known) map.map_type = 0;
        } else if (w == "use_color" || w == "use_colour") {
            map.use_index = false;
        } else if (w == "use_index") {
            map.use_index = true;
        } else if (image_map && (w == "filter" || w == "transmit" || w == "alpha")) {
            if (w == "alpha") warn(t, "Keyword ALPHA discontinued. Use FILTER instead.");
            PaletteSetting setting{t, w == "transmit"};
            if (!accept_keyword("all")) {
                setting.index = static_cast<int>(parse_float() + 0.01);
                accept(",");
            }
            setting.value = parse_float();
            palette.push_back(setting);
        } else if (w == "repeat" || w == "offset") {
            warn_unsupported(t, kw.text + " " + w);
            skip_to_close(kw, "}", depth);
            break;
        } else {
            fail(t, "expected a " + kw.text + " item but found '" + w + "'");
        }
    }
    map.image = read_image_file(file, name, file_gamma, image_map, type);
    const ImageData& img = *map.image;
    // POV-Ray compat: a palette PNG's alpha is each entry's transmit, 1 − alpha, which filter and transmit change.
    if (img.indexed() && !img.palette_alpha.empty()) {
        map.palette_ft.resize(static_cast<std::size_t>(img.palette_size));
        for (std::size_t i = 0; i < map.palette_ft.size() && i < img.palette_alpha.size(); ++i)
            map.palette_ft[i].transmit = 1.0f - img.palette_alpha[i];
    }
    for (const PaletteSetting& s : palette) {
        double& all = s.transmit ? map.transmit_all : map.filter_all;
        if (s.index < 0) all = s.value;
        if (!img.indexed()) {
            // POV-Ray reads GIF and other palette files with their palette; only PNG palettes are read here.
            if (s.index >= 0) warn_unsupported(s.at, "image_map " + s.at.text + " of a palette entry of a file other than a palette PNG");
            continue;
        }
        if (s.index >= img.palette_size) fail(s.at, s.transmit ? "TRANSMIT color register value out of range." : "FILTER color register value out of range.");
        // POV-Ray compat: a palette image keeps filter and transmit per entry, `all` setting every entry.
        if (map.palette_ft.empty()) map.palette_ft.resize(static_cast<std::size_t>(img.palette_size));
        for (int i = 0; i < img.palette_size; ++i) {
            if (s.index >= 0 && i != s.index) continue;
            (s.transmit ? map.palette_ft[i].transmit : map.palette_ft[i].filter) = static_cast<float>(s.value);
        }
    }
    if (img.indexed() && !map.palette_ft.empty()) map.filter_all = map.transmit_all = 0.0;
    return map;
}

void Parser::parse_image_map(const Token& kw, Pigment& p) {
    expect("{");
    if (peek().kind == TokenKind::Identifier && peek().text == "function") {
        warn_unsupported(peek(), "image_map function");
        skip_to_close(kw, "}", m_brace_depth);
        return;
    }
    p.image_map = parse_image_block(kw, ImageBlock::ImageMap, nullptr);
    p.color_map.clear();
    p.pigment_map.clear();
}

void Parser::parse_bump_map(const Token& kw, Normal& n) {
    expect("{");
    if (peek().kind == TokenKind::Identifier && peek().text == "function") {
        warn_unsupported(peek(), "bump_map function");
        skip_to_close(kw, "}", m_brace_depth);
        return;
    }
    n.bump_map = parse_image_block(kw, ImageBlock::BumpMap, [&](const Token& t) {
        if (!is_word(t, "bump_size")) return false;
        next();
        n.amount = static_cast<double>(static_cast<float>(parse_float()));  // POV-Ray compat: single precision
        return true;
    });
    n.pattern.type = Pattern::Type::None;
    n.normal_map.clear();
    n.slope_map.clear();
}

void Parser::parse_image_pattern(const Token& kw, Pattern& pat) {
    // POV-Ray's Parse_Image_Pattern: the image's stored values (no gamma unless given), grey or alpha.
    expect("{");
    Token alpha_at;
    bool alpha = false;
    ImageMap map = parse_image_block(kw, ImageBlock::BumpMap, [&](const Token& t) {
        if (!is_word(t, "use_alpha")) return false;
        alpha_at = next();
        alpha = true;
        return true;
    });
    map.use_alpha = alpha;
    // POV-Ray compat: with an alpha channel use_alpha takes it (a reader that does not return it is warned of).
    if (alpha && map.image->has_alpha && map.image->palette_alpha.empty() && map.image->alpha.empty())
        warn_unsupported(alpha_at, "image_pattern use_alpha of an image with an alpha channel");
    pat.params->image = std::make_shared<const ImageMap>(std::move(map));
    pat.params->frequency = 0.0;
}

void Parser::parse_material_map(const Token& kw, Texture& tx) {
    // POV-Ray's Parse_Material_Map: a new texture whose image picks one of the textures listed after it.
    expect("{");
    Texture result;
    bool textures = false;
    std::vector<TextureMapEntry> materials;
    ImageMap map = parse_image_block(kw, ImageBlock::MaterialMap, [&](const Token& t) {
        if (!is_word(t, "texture")) return false;
        next();
        materials.push_back({static_cast<double>(materials.size()), parse_texture_body(t)});
        textures = true;
        return true;
    });
    if (!textures) fail(kw, "a material_map needs at least one texture");
    result.material_map = std::move(map);
    result.texture_map = std::move(materials);
    tx = std::move(result);
}

}  // namespace wardray::parser
