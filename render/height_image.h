// Height field images: the 16-bit heights POV-Ray 3.7 takes from each pixel of an image file.
#pragma once

#include <filesystem>
#include <memory>
#include <string>

#include "render/image_header.h"
#include "scene/shapes.h"

namespace wardray::render {

/// Reads `path` as POV-Ray reads a height field's image (no gamma): palette images give index * 256, grey images
/// their value scaled to 0..65535, 16-bit colour images their grey (0.297 R + 0.589 G + 0.114 B), 8-bit and float
/// colour images red as the high byte and green as the low byte. PNG through libpng, GIF (and POT, a GIF the
/// parser recombines) by its own decoder, the rest through OpenImageIO. Nothing, with `error` set, for an
/// unreadable file; `unsupported` names a kind of file read but not as POV-Ray reads it (colour-mapped Targa),
/// then nothing is returned.
/// A file whose header claims more than `max_pixels` pixels is refused before anything is allocated.
std::shared_ptr<const scene::HeightGrid> read_height_grid(const std::filesystem::path& path, std::string& error,
                                                          std::string& unsupported,
                                                          std::uint64_t max_pixels = kAnyPixelCount);

}  // namespace wardray::render
