// The size an image file's header claims, read before any pixel is: a few hostile bytes can claim billions.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

namespace wardray::render {

/// No limit on the pixels of an image read (the default of the readers that take one).
constexpr std::uint64_t kAnyPixelCount = ~std::uint64_t{0};

/// Width and height as a file's header gives them.
struct ClaimedSize {
    std::uint64_t width = 0;
    std::uint64_t height = 0;
};

/// The size the header of `path` claims, from its first bytes: PNG (IHDR), GIF (the screen, and the largest image
/// descriptor), JPEG (the frame header), binary and text PNM (P1-P6) and, by the name's extension, Targa. Nothing
/// for another format (OpenImageIO's reader checks those itself) or a header too short to say.
std::optional<ClaimedSize> claimed_image_size(const std::filesystem::path& path);

/// What a PNG's header chunks say of its colours: IHDR's colour type and bit depth, and the encoding it declares
/// (an sRGB chunk, else a gAMA chunk's file gamma, as POV-Ray 3.7 honours them in that order).
struct PngColourInfo {
    int colour_type = 0;
    int bit_depth = 0;
    bool srgb = false;        ///< an sRGB chunk
    double file_gamma = 0.0;  ///< a gAMA chunk's value (the encoding exponent, such as 0.45455); 0 without one
};

/// The chunks before the image data of a PNG; nothing for any other file or a header too short to say.
std::optional<PngColourInfo> png_colour_info(const std::filesystem::path& path);

/// The error for an image whose header claims more than `max_pixels` pixels ("it claims W x H pixels, ..."),
/// checked before anything is allocated; nothing when it claims fewer or does not say.
std::optional<std::string> oversized_image(const std::filesystem::path& path, std::uint64_t max_pixels);

/// The same message for a size known another way (OpenImageIO's header).
std::string oversized_message(std::uint64_t width, std::uint64_t height, std::uint64_t max_pixels);

}  // namespace wardray::render
