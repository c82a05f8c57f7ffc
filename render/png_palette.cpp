// Palette PNG files read through libpng without expanding the palette.
#include "render/png_palette.h"

#include <png.h>

#include <csetjmp>
#include <cstdio>
#include <memory>

namespace wardray::render {

bool read_png_palette_indices(const std::filesystem::path& path, int& width, int& height,
                              std::vector<std::uint8_t>& indices, int& palette_size, std::vector<float>* entry_rgb,
                              std::vector<float>* entry_alpha) {
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"), &std::fclose);
    if (!file) return false;
    png_byte signature[8];
    if (std::fread(signature, 1, 8, file.get()) != 8 || png_sig_cmp(signature, 0, 8) != 0) return false;
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (!info) {
        png_destroy_read_struct(&png, nullptr, nullptr);
        return false;
    }
    std::vector<std::uint8_t> data;
    std::vector<png_bytep> rows;
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_read_struct(&png, &info, nullptr);
        return false;
    }
    png_init_io(png, file.get());
    png_set_sig_bytes(png, 8);
    png_read_info(png, info);
    if (png_get_color_type(png, info) != PNG_COLOR_TYPE_PALETTE) {
        png_destroy_read_struct(&png, &info, nullptr);
        return false;
    }
    // One byte per index whatever the bit depth.
    png_set_packing(png);
    png_set_interlace_handling(png);
    png_read_update_info(png, info);
    const png_uint_32 w = png_get_image_width(png, info), h = png_get_image_height(png, info);
    png_colorp palette = nullptr;
    int entries = 0;
    png_get_PLTE(png, info, &palette, &entries);
    if (entry_rgb) {
        entry_rgb->clear();
        for (int i = 0; i < entries; ++i)
            for (png_byte c : {palette[i].red, palette[i].green, palette[i].blue})
                entry_rgb->push_back(static_cast<float>(c) / 255.0f);
    }
    png_bytep trans = nullptr;
    int trans_count = 0;
    if (entry_alpha) {
        entry_alpha->clear();
        if (png_get_tRNS(png, info, &trans, &trans_count, nullptr) != 0 && trans != nullptr) {
            entry_alpha->assign(static_cast<std::size_t>(entries), 1.0f);
            for (int i = 0; i < trans_count && i < entries; ++i) (*entry_alpha)[i] = static_cast<float>(trans[i]) / 255.0f;
        }
    }
    data.resize(static_cast<std::size_t>(w) * h);
    rows.resize(h);
    for (png_uint_32 y = 0; y < h; ++y) rows[y] = data.data() + static_cast<std::size_t>(y) * w;
    png_read_image(png, rows.data());
    png_destroy_read_struct(&png, &info, nullptr);
    width = static_cast<int>(w);
    height = static_cast<int>(h);
    palette_size = entries;
    indices = std::move(data);
    return true;
}

}  // namespace wardray::render
