// Palette PNG files: the colour index of each texel, which image maps, bump maps and material maps may use
// (POV-Ray's "color-mapped" images); OpenImageIO gives only the colours.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

namespace wardray::render {

/// The palette indices of a palette PNG (colour type 3), one byte per texel, rows from the top, and the number of
/// palette entries. False (nothing set) for a file that is not a palette PNG or cannot be read. With
/// `entry_rgb` and `entry_alpha`, also each entry's colour (r, g, b as stored, over 255) and its alpha (its tRNS
/// value over 255; 1 past the tRNS entries); `entry_alpha` is left empty for a file without tRNS.
bool read_png_palette_indices(const std::filesystem::path& path, int& width, int& height,
                              std::vector<std::uint8_t>& indices, int& palette_size,
                              std::vector<float>* entry_rgb = nullptr, std::vector<float>* entry_alpha = nullptr);

}  // namespace wardray::render
