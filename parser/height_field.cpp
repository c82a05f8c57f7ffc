// The height_field statement: its image (read through ParseOptions::read_height_grid) or its function image, and
// smooth, water_level and hierarchy, as POV-Ray 3.7 reads them.
#include <cmath>
#include <array>
#include <cstdint>

#include "parser/parser.h"

namespace wardray::parser {

namespace {

/// The image file types POV-Ray names before a height field's file.
bool is_height_image_type(const TokenText& w) {
    static const char* const types[] = {"gif", "tga", "iff", "ppm", "pgm", "png", "jpeg", "tiff", "sys", "exr", "hdr",
                                        "pot", "bmp"};
    for (const char* t : types)
        if (w == t) return true;
    return false;
}

/// How POV-Ray 3.7 stores a function value in its 16-bit function image: clipped, times 65535 in float, cut.
std::uint16_t encode16(double v) {
    const float x = std::fmin(std::fmax(static_cast<float>(v), 0.0f), 1.0f);
    // POV-Ray compat: 3.7.0's 16-bit image cuts (gray * 65535.0f) rather than rounding it (IntEncode); its
    // heights of f = 0.035043 are 2296 (float and grey pigment functions), not 2297.
    return static_cast<std::uint16_t>(x * 65535.0f);
}

/// The height POV-Ray takes from a grey 16-bit function image texel (image_height_at: grey * 65535 in float, cut).
std::uint16_t grey16_height(std::uint16_t g) {
    const float grey = static_cast<float>(g) / 65535.0f;
    return static_cast<std::uint16_t>(grey * 65535.0f);
}

/// The height from a 16-bit colour texel: POV-Ray's old grey weights (0.297, 0.589, 0.114), times 65535, cut.
std::uint16_t colour16_height(std::uint16_t r, std::uint16_t g, std::uint16_t b) {
    const double grey = 0.297 * (static_cast<float>(r) / 65535.0f) + 0.589 * (static_cast<float>(g) / 65535.0f) +
                        0.114 * (static_cast<float>(b) / 65535.0f);
    return static_cast<std::uint16_t>(grey * 65535.0f);
}

/// A POT file (a GIF of twice the width): the left half's palette index is each height's high byte, the right
/// half's its low byte, taken as a 16-bit grey image (POV-Ray's Gif::Read for POT files). The GIF reader gives
/// heights of index * 256.
std::shared_ptr<const HeightGrid> pot_heights(const HeightGrid& gif) {
    auto grid = std::make_shared<HeightGrid>();
    grid->width = gif.width / 2;
    grid->height = gif.height;
    grid->heights.resize(static_cast<std::size_t>(grid->width) * grid->height);
    for (int z = 0; z < grid->height; ++z)
        for (int x = 0; x < grid->width; ++x) {
            const unsigned high = gif.at(x, z) / 256u, low = gif.at(x + grid->width, z) / 256u;
            grid->heights[static_cast<std::size_t>(z) * grid->width + x] =
                grey16_height(static_cast<std::uint16_t>(high << 8 | low));
        }
    return grid;
}

}  // namespace

HeightField Parser::read_height_field(const Token& kw) {
    HeightField hf;
    expand_macros();
    const Token first = peek();
    if (is_word(first, "function")) {
        next();
        // POV-Ray compat: `function W, H { ... }` samples the function at x = i/(W-1), y = j/(H-1), z = 0 into a
        // 16-bit image (grey for a float function, RGB for a pigment), image row j = 0 being the top.
        const Token at_w = peek();
        const int width = static_cast<int>(parse_float() + 0.5);
        accept(",");
        const int height = static_cast<int>(parse_float() + 0.5);
        if (width < 2 || height < 2 || width > 32768 || height > 32768)
            fail(at_w, "a height_field function image needs 2 to 32768 pixels each way");
        const Token fn_kw = peek();
        if (!is_punct(fn_kw, "{")) fail(fn_kw, "expected '{' after the height_field function's size");
        const std::shared_ptr<const UserFunction> f = parse_user_function(first);
        auto grid = std::make_shared<HeightGrid>();
        grid->width = width;
        grid->height = height;
        grid->heights.resize(static_cast<std::size_t>(width) * height);
        const int noise_generator = m_builder.global().noise_generator;
        const bool pigment = f->kind == UserFunction::Kind::Pigment;
        if (f->kind == UserFunction::Kind::Float && !f->program)
            fail(fn_kw, "the height_field function must be a float or pigment function");
        if (f->kind == UserFunction::Kind::Transform || f->kind == UserFunction::Kind::Spline)
            fail(fn_kw, "the height_field function must be a float or pigment function");
        if (pigment && !m_options.pigment_value) fail(fn_kw, "pigment functions cannot be evaluated here");
        if (f->kind == UserFunction::Kind::Pattern && !m_options.pattern_value)
            fail(fn_kw, "pattern functions cannot be evaluated here");
        if (f->kind == UserFunction::Kind::Float && !f->program->unsupported().empty())
            warn(fn_kw, "height_field is not rendered yet: its " + f->program->unsupported());
        for (int j = 0; j < height; ++j) {
            const double py = static_cast<double>(j) / (height - 1);
            const int z = height - 1 - j;
            for (int i = 0; i < width; ++i) {
                const Vec3 p{static_cast<double>(i) / (width - 1), py, 0.0};
                std::uint16_t h = 0;
                if (pigment) {
                    const Color c = m_options.pigment_value(*f->pigment, p, noise_generator);
                    h = colour16_height(encode16(c.r), encode16(c.g), encode16(c.b));
                } else if (f->kind == UserFunction::Kind::Pattern) {
                    h = grey16_height(encode16(m_options.pattern_value(f->pigment->pattern, p, noise_generator)));
                } else {
                    const std::array<double, 3> args{p.x, p.y, p.z};
                    h = grey16_height(encode16(f->program->evaluate(args, EvalContext{noise_generator})));
                }
                grid->heights[static_cast<std::size_t>(z) * width + i] = h;
            }
        }
        hf.grid = std::move(grid);
    } else {
        const bool pot = is_word(first, "pot");
        if (first.kind == TokenKind::Identifier && is_height_image_type(first.text)) next();
        const Token file = peek();
        const std::string name = parse_string();
        if (!m_options.read_height_grid) fail(file, "height_field cannot read images here (no image reader)");
        const std::optional<std::filesystem::path> where =
            find_readable(file, std::filesystem::path(name), "", "height_field image");
        const std::filesystem::path found = where ? *where : std::filesystem::path();
        if (found.empty()) fail(file, "cannot open height_field image '" + name + "'");
        const std::string key = "height_field\n" + found.string();
        if (auto it = m_height_grids.find(key); it != m_height_grids.end()) {
            hf.grid = it->second;
        } else {
            std::string error, unsupported;
            hf.grid = m_options.read_height_grid(found, error, unsupported);
            if (!hf.grid && !unsupported.empty()) {
                // Left out of the picture (the geometry skips a height field without a grid), with a warning.
                warn_unsupported(file, unsupported);
            } else if (!hf.grid) {
                fail(file, "cannot read height_field image '" + found.string() + "': " + error);
            } else {
                m_height_grids.emplace(key, hf.grid);
            }
        }
        if (hf.grid && pot) {
            if (hf.grid->width % 2 != 0) fail(file, "Invalid width for POT file");
            hf.grid = pot_heights(*hf.grid);
        }
        if (hf.grid && (hf.grid->width < 2 || hf.grid->height < 2))
            fail(file, "a height_field image needs at least 2 by 2 pixels");
        if (is_word(peek(), "gamma") || is_word(peek(), "premultiplied")) {
            const Token g = next();
            warn_unsupported(g, "height_field image " + g.text);
            if (!accept_keyword("srgb")) parse_float();
        }
    }
    for (;;) {
        expand_macros();
        const Token t = peek();
        if (is_word(t, "smooth")) {
            next();
            hf.smooth = true;
        } else if (is_word(t, "water_level")) {
            next();
            hf.water_level = parse_float();
            // POV-Ray compat: scenes before version 2.0 gave the level in 0..256.
            if (m_version_given && m_version < 2.0) hf.water_level /= 256.0;
        } else if (is_word(t, "hierarchy")) {
            next();
            parse_bool_optional();  // an acceleration hint: the picture is the same
        } else {
            break;
        }
    }
    (void)kw;
    return hf;
}

}  // namespace wardray::parser
