// PNG files read with libpng (already linked for writing), without loading OpenImageIO.
#pragma once

#include <filesystem>
#include <vector>

namespace wardray::render {

/// Reads an opaque PNG (grey, RGB or palette, 1 to 16 bits, no alpha channel and no tRNS chunk) as RGB rows from
/// the top, each sample the stored value scaled to [0, 1] as OpenImageIO scales it. Returns false, leaving the
/// file to OpenImageIO, for anything else: not a PNG, an alpha channel, a damaged file.
bool read_png_rgb(const std::filesystem::path& path, int& width, int& height, std::vector<float>& rgb);

/// Reads a PNG with an alpha channel (grey or RGB with alpha, 8 or 16 bits, no tRNS chunk) or a palette PNG with a
/// tRNS chunk (each entry's alpha, missing entries opaque) as OpenImageIO reads
/// it asked for straight alpha: RGB rows from the top (grey spread to all three) and each pixel's alpha, scaled
/// as read_png_rgb scales them. Returns false, leaving the file to OpenImageIO, for anything else.
bool read_png_rgba(const std::filesystem::path& path, int& width, int& height, std::vector<float>& rgb,
                   std::vector<float>& alpha);

}  // namespace wardray::render
