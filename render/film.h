// Film: the linear RGB image a render produces, and its reading and writing through OpenImageIO.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/vec3.h"
#include "render/image_header.h"

namespace wardray::render {

/// Output file formats, as POV-Ray's +F switch names them.
enum class ImageFormat {
    Png,  ///< +FN: 8-bit, sRGB-encoded as POV-Ray 3.7 writes it
    Exr,  ///< +FE: OpenEXR, linear half float
    Hdr,  ///< +FH: Radiance RGBE, linear
};

/// The format an extension names (.png .exr .hdr, case-insensitive), or nothing.
std::optional<ImageFormat> format_from_extension(const std::filesystem::path& path);
/// The usual extension of a format, with its dot.
const char* extension_of(ImageFormat format);

/// A linear RGB image, rows from the top.
class Film {
public:
    Film() = default;
    Film(int width, int height);
    /// A film holding `rgb` (width * height float RGB triples, rows from the top) without copying it.
    Film(int width, int height, std::vector<float> rgb);

    int width() const { return m_width; }
    int height() const { return m_height; }
    Vec3 pixel(int x, int y) const;
    void set_pixel(int x, int y, const Vec3& rgb);
    /// The samples as float RGB triples, row-major from the top-left pixel.
    const std::vector<float>& data() const { return m_rgb; }
    /// Hands the samples over without copying them; the film is left empty (0 x 0).
    std::vector<float> take_data() {
        m_width = m_height = 0;
        return std::move(m_rgb);
    }

private:
    int m_width = 0;
    int m_height = 0;
    std::vector<float> m_rgb;
};

/// Writes a file the way every output of wardray is written: `write` fills a temporary file beside `path`
/// (returning an error message or nothing), which is renamed over `path` only when complete and removed
/// otherwise, also when a signal interrupts the run (see remove_partial_output_on_signal).
std::optional<std::string> write_atomically(
    const std::filesystem::path& path,
    const std::function<std::optional<std::string>(const std::filesystem::path& temporary)>& write);

/// Writes `film` to `path` in `format`: first under a temporary name in the same folder, renamed over `path`
/// only when complete, so a failed write never leaves a partial image. Returns an error message or nothing.
/// With `alpha` (Output_Alpha: each pixel's alpha in its red channel, the colours associated with it), PNG and EXR
/// get an alpha channel; HDR has none and holds the associated colours.
std::optional<std::string> write_image(const Film& film, const std::filesystem::path& path, ImageFormat format,
                                       const Film* alpha = nullptr);

/// Installs SIGINT/SIGTERM/SIGHUP handlers that delete an image file still being written, then exit with
/// 128 + the signal number, so an interrupted run never leaves a partial file behind.
void remove_partial_output_on_signal();

/// Reads any image OpenImageIO reads as linear RGB (8-bit sRGB files are decoded to linear).
/// On failure returns nothing and sets `error`. With `stored`, the values are left as the file stores them
/// (8- and 16-bit ones scaled to [0, 1]) and `*stored` says whether they are encoded (integer) values. `*alpha`
/// says whether the file has an alpha channel; `*grey` whether it has one colour channel and `*bits16` whether it
/// stores 16-bit values. With an alpha channel the colours are straight (not premultiplied) and `alpha_values`
/// receives each pixel's alpha, rows from the top. A file whose header claims more than `max_pixels` pixels is
/// refused before anything is allocated (render/image_header.h).
std::optional<Film> read_image(const std::filesystem::path& path, std::string& error, bool* stored = nullptr,
                               bool* alpha = nullptr, bool* grey = nullptr, bool* bits16 = nullptr,
                               std::vector<float>* alpha_values = nullptr, std::uint64_t max_pixels = kAnyPixelCount);
/// read_image through OpenImageIO only (read_image takes PNGs but palette ones with a tRNS chunk, JPEGs and, for
/// colours, GIFs through libpng, libjpeg and render/gif_reader.h, giving the same values).
std::optional<Film> read_image_with_oiio(const std::filesystem::path& path, std::string& error,
                                         bool* stored = nullptr, bool* alpha = nullptr, bool* grey = nullptr,
                                         bool* bits16 = nullptr, std::vector<float>* alpha_values = nullptr,
                                         std::uint64_t max_pixels = kAnyPixelCount);

/// sRGB transfer function, linear to encoded, for one channel in [0, 1].
double srgb_encode(double linear);
double srgb_decode(double encoded);

}  // namespace wardray::render
