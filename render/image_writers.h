// Image file writers with a small start-up cost: libpng, OpenEXR and a Radiance RGBE encoder.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "render/film.h"

namespace wardray::render {

/// 8-bit sRGB PNG through libpng; returns an error message or nothing.
std::optional<std::string> write_png(const Film& film, const std::filesystem::path& path);
/// Linear half-float OpenEXR through the OpenEXR library.
std::optional<std::string> write_exr(const Film& film, const std::filesystem::path& path);
/// Linear Radiance RGBE (.hdr), run-length encoded scanlines as Radiance itself writes them.
std::optional<std::string> write_hdr(const Film& film, const std::filesystem::path& path);

/// The 8-bit value POV-Ray writes for a linear channel: floor(clip(srgb(x)) * 255 + 0.5); NaN becomes 0.
unsigned char encode_srgb8(float linear);

}  // namespace wardray::render
