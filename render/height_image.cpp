// Height field images read as POV-Ray 3.7's image_height_at sees them: libpng for PNG (palette indices), the
// OpenImageIO module for the rest.
#include "render/height_image.h"

#include <png.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <vector>

#include "render/film.h"
#include "render/gif_reader.h"

namespace wardray::render {

namespace {

// POV-Ray's heights from an 8-bit or 16-bit grey value v of `max` (GetGrayValue in float, times 65535, cut).
std::uint16_t grey_height(unsigned v, unsigned max) {
    const float grey = static_cast<float>(v) / static_cast<float>(max);
    return static_cast<std::uint16_t>(grey * 65535.0f);
}

// POV-Ray compat: a grey PNG of 8 bits or fewer is read through a colour table of v / max in float, and each texel
// is stored in its 8-bit grey image as the table colour's grey (old weights 0.297, 0.589, 0.114 in float) times 255,
// cut: for about a third of the levels the sum falls just below v / 255, and the texel is one level lower.
unsigned grey8_stored(unsigned v, unsigned max) {
    const float f = static_cast<float>(v) / static_cast<float>(max);
    const float grey = f * 0.297f + f * 0.589f + f * 0.114f;
    return static_cast<unsigned char>(grey * 255.0f);
}

// 16-bit colour: POV-Ray's old grey weights.
std::uint16_t colour16_height(unsigned r, unsigned g, unsigned b) {
    const double grey = 0.297 * (static_cast<float>(r) / 65535.0f) + 0.589 * (static_cast<float>(g) / 65535.0f) +
                        0.114 * (static_cast<float>(b) / 65535.0f);
    return static_cast<std::uint16_t>(grey * 65535.0f);
}

// 8-bit and float colour: red the high byte, green the low byte ((r * 256 + g) * 255, cut to 16 bits).
std::uint16_t colour8_height(float r, float g) {
    const double v = (static_cast<double>(r) * 256.0 + g) * 255.0;
    return static_cast<std::uint16_t>(static_cast<long long>(v));
}

std::string file_head(const std::filesystem::path& path, std::size_t n) {
    std::ifstream in(path, std::ios::binary);
    std::string head(n, '\0');
    in.read(head.data(), static_cast<std::streamsize>(n));
    head.resize(static_cast<std::size_t>(in.gcount()));
    return head;
}

struct PngReader {
    png_structp png = nullptr;
    png_infop info = nullptr;
    std::FILE* file = nullptr;
    ~PngReader() {
        if (png) png_destroy_read_struct(&png, info ? &info : nullptr, nullptr);
        if (file) std::fclose(file);
    }
};

// Rows from the top, through libpng: each pixel's height as image_height_at gives it.
std::shared_ptr<scene::HeightGrid> read_png(const std::filesystem::path& path, std::string& error) {
    PngReader r;
    r.file = std::fopen(path.c_str(), "rb");
    if (!r.file) {
        error = "cannot open the file";
        return nullptr;
    }
    r.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    if (!r.png) return nullptr;
    r.info = png_create_info_struct(r.png);
    if (!r.info) return nullptr;
    if (setjmp(png_jmpbuf(r.png))) {
        error = "not a readable PNG file";
        return nullptr;
    }
    png_init_io(r.png, r.file);
    png_read_info(r.png, r.info);
    const int width = static_cast<int>(png_get_image_width(r.png, r.info));
    const int height = static_cast<int>(png_get_image_height(r.png, r.info));
    const int colour_type = png_get_color_type(r.png, r.info);
    const int bit_depth = png_get_bit_depth(r.png, r.info);
    const bool palette = colour_type == PNG_COLOR_TYPE_PALETTE;
    const bool grey = (colour_type & PNG_COLOR_MASK_COLOR) == 0;
    if (bit_depth < 8) png_set_packing(r.png);  // one byte per pixel, values unscaled
    if (bit_depth == 16) png_set_swap(r.png);  // little-endian 16-bit samples
    png_set_interlace_handling(r.png);
    png_read_update_info(r.png, r.info);
    const std::size_t row_bytes = png_get_rowbytes(r.png, r.info);
    std::vector<png_byte> data(row_bytes * static_cast<std::size_t>(height));
    std::vector<png_bytep> rows(static_cast<std::size_t>(height));
    for (int y = 0; y < height; ++y) rows[static_cast<std::size_t>(y)] = data.data() + row_bytes * y;
    png_read_image(r.png, rows.data());
    const int channels = png_get_channels(r.png, r.info);
    auto grid = std::make_shared<scene::HeightGrid>();
    grid->width = width;
    grid->height = height;
    grid->heights.resize(static_cast<std::size_t>(width) * height);
    const unsigned low_max = (1u << bit_depth) - 1u;
    for (int y = 0; y < height; ++y) {
        const png_byte* row = rows[static_cast<std::size_t>(y)];
        const int z = height - 1 - y;
        for (int x = 0; x < width; ++x) {
            auto sample = [&](int c) -> unsigned {
                if (bit_depth == 16) {
                    const png_byte* p = row + 2 * (static_cast<std::size_t>(x) * channels + c);
                    return static_cast<unsigned>(p[0]) | (static_cast<unsigned>(p[1]) << 8);
                }
                return row[static_cast<std::size_t>(x) * channels + c];
            };
            std::uint16_t h = 0;
            if (palette) {
                // POV-Ray compat: a palette image's height is its index times 256 (not 257).
                h = static_cast<std::uint16_t>(sample(0) * 256u);
            } else if (grey && bit_depth <= 8) {
                h = grey_height(grey8_stored(sample(0), low_max), 255);
            } else if (grey) {
                h = grey_height(sample(0), 65535u);
            } else if (bit_depth == 16) {
                h = colour16_height(sample(0), sample(1), sample(2));
            } else {
                h = colour8_height(static_cast<float>(sample(0)) / 255.0f, static_cast<float>(sample(1)) / 255.0f);
            }
            grid->heights[static_cast<std::size_t>(z) * width + x] = h;
        }
    }
    return grid;
}

}  // namespace

std::shared_ptr<const scene::HeightGrid> read_height_grid(const std::filesystem::path& path, std::string& error,
                                                          std::string& unsupported, std::uint64_t max_pixels) {
    if (const auto oversized = oversized_image(path, max_pixels)) {
        error = *oversized;
        return nullptr;
    }
    const std::string head = file_head(path, 18);
    if (head.size() >= 8 && head.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0) return read_png(path, error);
    if (head.size() >= 4 && head.compare(0, 4, "GIF8") == 0) {
        // POV-Ray compat: a GIF's height is its palette index times 256, as for any palette image.
        const std::optional<GifIndices> gif = read_gif_indices(path, error);
        if (!gif) return nullptr;
        auto grid = std::make_shared<scene::HeightGrid>();
        grid->width = gif->width;
        grid->height = gif->height;
        grid->heights.resize(gif->index.size());
        for (int y = 0; y < gif->height; ++y)
            for (int x = 0; x < gif->width; ++x)
                grid->heights[static_cast<std::size_t>(gif->height - 1 - y) * gif->width + x] =
                    static_cast<std::uint16_t>(gif->index[static_cast<std::size_t>(y) * gif->width + x] * 256u);
        return grid;
    }
    const std::string ext = path.extension().string();
    if ((ext == ".tga" || ext == ".TGA") && head.size() >= 3 && (head[2] == 1 || head[2] == 9)) {
        unsupported = "height_field colour-mapped Targa image";
        return nullptr;
    }
    bool stored = false, alpha = false, grey = false, bits16 = false;
    const std::optional<Film> film = read_image(path, error, &stored, &alpha, &grey, &bits16, nullptr, max_pixels);
    if (!film) return nullptr;
    auto grid = std::make_shared<scene::HeightGrid>();
    grid->width = film->width();
    grid->height = film->height();
    grid->heights.resize(static_cast<std::size_t>(grid->width) * grid->height);
    const unsigned max = bits16 ? 65535u : 255u;
    for (int y = 0; y < grid->height; ++y) {
        const int z = grid->height - 1 - y;
        for (int x = 0; x < grid->width; ++x) {
            const Vec3 c = film->pixel(x, y);
            // Integer files: the stored integers back from OpenImageIO's [0, 1] floats.
            auto value = [&](double v) { return static_cast<unsigned>(std::lround(std::fmin(std::fmax(v, 0.0), 1.0) * max)); };
            std::uint16_t h = 0;
            if (stored && grey) h = grey_height(value(c.x), max);
            else if (stored && bits16) h = colour16_height(value(c.x), value(c.y), value(c.z));
            else if (stored) h = colour8_height(static_cast<float>(value(c.x)) / 255.0f, static_cast<float>(value(c.y)) / 255.0f);
            else h = colour8_height(static_cast<float>(c.x), static_cast<float>(c.y));
            grid->heights[static_cast<std::size_t>(z) * grid->width + x] = h;
        }
    }
    return grid;
}

}  // namespace wardray::render
