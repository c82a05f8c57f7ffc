// JPEG files read with libjpeg, without loading OpenImageIO.
#pragma once

#include <filesystem>
#include <vector>

namespace wardray::render {

/// Reads a grey or colour (YCbCr or RGB) JPEG as RGB rows from the top, each sample the stored byte over 255 as
/// OpenImageIO scales it. Returns false, leaving the file to OpenImageIO, for anything else (not a JPEG, CMYK,
/// a damaged file). `grey`, when given, says whether the file has one channel.
bool read_jpeg_rgb(const std::filesystem::path& path, int& width, int& height, std::vector<float>& rgb,
                   bool* grey = nullptr);

}  // namespace wardray::render
