// Image file writers with a small start-up cost: libpng, OpenEXR and a Radiance RGBE encoder.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "core/gamma.h"
#include "render/film.h"

namespace wardray::render {

/// 8-bit sRGB PNG through libpng; returns an error message or nothing.
std::optional<std::string> write_png(const Film& film, const std::filesystem::path& path);
/// 8-bit PNG whose values are `encoding.encode(x)`, tagged (sRGB or gAMA chunk) as encoded with `file_gamma`.
std::optional<std::string> write_png(const Film& film, const std::filesystem::path& path,
                                     const GammaTranscoding& encoding, const GammaCurve& file_gamma);
/// Linear half-float OpenEXR through the OpenEXR library.
std::optional<std::string> write_exr(const Film& film, const std::filesystem::path& path);
/// Linear Radiance RGBE (.hdr), run-length encoded scanlines as Radiance itself writes them.
std::optional<std::string> write_hdr(const Film& film, const std::filesystem::path& path);

/// The 8-bit value POV-Ray writes for a linear channel: floor(clip(srgb(x)) * 255 + 0.5); NaN becomes 0.
unsigned char encode_srgb8(float linear);
/// The 8-bit value POV-Ray writes for `x` through `encoding`: floor(clip(encoding(x)) * 255 + 0.5); NaN becomes 0.
unsigned char encode8(const GammaTranscoding& encoding, float x);

}  // namespace wardray::render
