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
/// With `alpha` (each pixel's alpha in its red channel, `film` holding colours associated with it) the PNG is
/// RGBA with straight alpha, as POV-Ray 3.7 writes it (see unassociate_alpha).
std::optional<std::string> write_png(const Film& film, const std::filesystem::path& path,
                                     const GammaTranscoding& encoding, const GammaCurve& file_gamma,
                                     const Film* alpha = nullptr);
/// Linear half-float OpenEXR through the OpenEXR library; with `alpha`, RGBA with the colours associated.
std::optional<std::string> write_exr(const Film& film, const std::filesystem::path& path,
                                     const Film* alpha = nullptr);

/// POV-Ray 3.7's PNG alpha (GetEncodedRGBAValue): a colour associated with alpha `a` becomes straight. A pixel
/// brighter (grey level) than its alpha has the alpha raised to that brightness (at most 1), so highlights on glass
/// survive; then the colour is divided by the alpha (by 1e-6 where it is 0). In single precision, as POV-Ray.
void unassociate_alpha(float& r, float& g, float& b, float& a);
/// Linear Radiance RGBE (.hdr), run-length encoded scanlines as Radiance itself writes them.
std::optional<std::string> write_hdr(const Film& film, const std::filesystem::path& path);

/// The 8-bit value POV-Ray writes for a linear channel: floor(clip(srgb(x)) * 255 + 0.5); NaN becomes 0.
unsigned char encode_srgb8(float linear);
/// The 8-bit value POV-Ray writes for `x` through `encoding`: floor(clip(encoding(x)) * 255 + 0.5); NaN becomes 0.
unsigned char encode8(const GammaTranscoding& encoding, float x);

}  // namespace wardray::render
