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
};

/// Reads the first image of the GIF file at `path` (GIF87a and GIF89a); nothing, with `error` set, when it cannot.
std::optional<GifIndices> read_gif_indices(const std::filesystem::path& path, std::string& error);

}  // namespace wardray::render
