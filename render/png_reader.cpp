// PNG files read with libpng, so a scene whose image maps are PNGs does not pay OpenImageIO's 0.7 s load.
#include "render/png_reader.h"

#include <png.h>

#include <csetjmp>
#include <cstdint>
#include <cstdio>
#include <memory>

namespace wardray::render {

namespace {

struct FileCloser {
    void operator()(std::FILE* f) const { std::fclose(f); }
};

/// What the libpng calls fill; owned by the caller so nothing with a destructor lives in the frame that calls
/// setjmp (libpng reports errors by longjmp).
struct PngRows {
    png_uint_32 width = 0;
    png_uint_32 height = 0;
    int bit_depth = 0;
    int channels = 3;                  ///< 3, or 4 with alpha
    std::vector<unsigned char> bytes;  ///< height rows of width RGB(A) samples, 8 or 16 bits each (host order)
    std::vector<png_bytep> rows;
};

void quiet_warning(png_structp, png_const_charp) {}

/// Reads the whole image as RGB, or returns false: a libpng error, or a file with an alpha channel or a tRNS
/// chunk (left to OpenImageIO, whose alpha handling the rest of the program expects). With `alpha`, reads only a
/// file with an alpha channel (grey or RGB, no tRNS) or a palette with a tRNS chunk, as RGBA.
bool read_rows(std::FILE* file, PngRows& out, bool alpha) {
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, quiet_warning);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (!info) {
        png_destroy_read_struct(&png, nullptr, nullptr);
        return false;
    }
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_read_struct(&png, &info, nullptr);
        return false;
    }
    png_init_io(png, file);
    png_read_info(png, info);
    const int color_type = png_get_color_type(png, info);
    const bool trns = png_get_valid(png, info, PNG_INFO_tRNS) != 0;
    // A palette's tRNS chunk gives each entry an alpha: OpenImageIO reads such a file as RGBA (bumpmap_.png).
    const bool palette_alpha = color_type == PNG_COLOR_TYPE_PALETTE && trns;
    const bool channel_alpha = (color_type & PNG_COLOR_MASK_ALPHA) != 0;
    if (alpha ? !(palette_alpha || (channel_alpha && !trns)) : (channel_alpha || trns)) {
        png_destroy_read_struct(&png, &info, nullptr);
        return false;
    }
    if (color_type == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png);
    if (palette_alpha) png_set_tRNS_to_alpha(png);
    if (color_type == PNG_COLOR_TYPE_GRAY && png_get_bit_depth(png, info) < 8) png_set_expand_gray_1_2_4_to_8(png);
    if (color_type == PNG_COLOR_TYPE_GRAY || color_type == PNG_COLOR_TYPE_GRAY_ALPHA) png_set_gray_to_rgb(png);
    if (png_get_bit_depth(png, info) == 16) png_set_swap(png);  // host (little-endian) order
    png_set_interlace_handling(png);
    png_read_update_info(png, info);
    out.width = png_get_image_width(png, info);
    out.height = png_get_image_height(png, info);
    out.bit_depth = png_get_bit_depth(png, info);
    const std::size_t row_bytes = png_get_rowbytes(png, info);
    out.channels = alpha ? 4 : 3;
    if (png_get_channels(png, info) != out.channels ||
        row_bytes != out.width * static_cast<unsigned>(out.channels) * (out.bit_depth == 16 ? 2u : 1u)) {
        png_destroy_read_struct(&png, &info, nullptr);
        return false;
    }
    out.bytes.resize(row_bytes * out.height);
    out.rows.resize(out.height);
    for (png_uint_32 y = 0; y < out.height; ++y) out.rows[y] = out.bytes.data() + row_bytes * y;
    png_read_image(png, out.rows.data());
    png_read_end(png, nullptr);
    png_destroy_read_struct(&png, &info, nullptr);
    return true;
}

/// Reads `path` into `rows` (see read_rows), or returns false.
bool read_png_file(const std::filesystem::path& path, PngRows& rows, bool alpha) {
    const std::unique_ptr<std::FILE, FileCloser> file(std::fopen(path.c_str(), "rb"));
    if (!file) return false;
    unsigned char signature[8] = {0};
    if (std::fread(signature, 1, 8, file.get()) != 8 || png_sig_cmp(signature, 0, 8) != 0) return false;
    std::rewind(file.get());
    return read_rows(file.get(), rows, alpha) && rows.width != 0 && rows.height != 0;
}

/// Sample `i` of `rows` as OpenImageIO converts integer samples to float: the value times 1 / its maximum, in
/// single precision.
float sample(const PngRows& rows, std::size_t i) {
    if (rows.bit_depth == 16)
        return static_cast<float>(reinterpret_cast<const std::uint16_t*>(rows.bytes.data())[i]) * (1.0f / 65535.0f);
    return static_cast<float>(rows.bytes[i]) * (1.0f / 255.0f);
}

}  // namespace

bool read_png_rgb(const std::filesystem::path& path, int& width, int& height, std::vector<float>& rgb) {
    PngRows rows;
    if (!read_png_file(path, rows, false)) return false;
    width = static_cast<int>(rows.width);
    height = static_cast<int>(rows.height);
    const std::size_t n = static_cast<std::size_t>(rows.width) * rows.height * 3;
    rgb.resize(n);
    for (std::size_t i = 0; i < n; ++i) rgb[i] = sample(rows, i);
    return true;
}

bool read_png_rgba(const std::filesystem::path& path, int& width, int& height, std::vector<float>& rgb,
                   std::vector<float>& alpha) {
    PngRows rows;
    if (!read_png_file(path, rows, true)) return false;
    width = static_cast<int>(rows.width);
    height = static_cast<int>(rows.height);
    const std::size_t n = static_cast<std::size_t>(rows.width) * rows.height;
    rgb.resize(n * 3);
    alpha.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t c = 0; c < 3; ++c) rgb[i * 3 + c] = sample(rows, i * 4 + c);
        alpha[i] = sample(rows, i * 4 + 3);
    }
    return true;
}

}  // namespace wardray::render
