// Palette PNG files: the colour index of each texel, which image maps, bump maps and material maps may use
// (POV-Ray's "color-mapped" images); OpenImageIO gives only the colours.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

namespace wardray::render {

/// The palette indices of a palette PNG (colour type 3), one byte per texel, rows from the top, and the number of
/// palette entries. False (nothing set) for a file that is not a palette PNG or cannot be read.
bool read_png_palette_indices(const std::filesystem::path& path, int& width, int& height,
                              std::vector<std::uint8_t>& indices, int& palette_size);

}  // namespace wardray::render
