// GIF images as palette indices: the first image of a GIF file, LZW-decoded (POV-Ray 3.7 reads GIF height fields
// and POT files by their indices).
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace wardray::render {

/// The palette index of each pixel of a GIF image, rows from the top in the order stored.
struct GifIndices {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> index;
    int screen_width = 0;   ///< the logical screen the image is placed on
    int screen_height = 0;
    int left = 0;           ///< the image's position on the screen
    int top = 0;
    std::vector<std::uint8_t> palette;  ///< the colour table the image uses (local, else global), RGB bytes
    int transparent = -1;   ///< the transparent index of its graphic control extension, -1 without
};

/// Reads the first image of the GIF file at `path` (GIF87a and GIF89a); nothing, with `error` set, when it cannot.
std::optional<GifIndices> read_gif_indices(const std::filesystem::path& path, std::string& error);

/// The first image of a GIF file as OpenImageIO gives it, so image maps need not load it: RGB on the logical
/// screen (rows from the top), each sample the byte over 255, transparent and uncovered pixels black. Returns
/// false, leaving the file to OpenImageIO, when it is not a GIF it can read or an index lies outside the colour
/// table.
bool read_gif_rgb(const std::filesystem::path& path, int& width, int& height, std::vector<float>& rgb);

}  // namespace wardray::render
