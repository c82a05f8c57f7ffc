// The OpenImageIO reader as a loadable module: loading OpenImageIO costs about 0.7 s, so only runs that
// read an image (wardray diff, image maps, tests) pay for it. C entry points keep the boundary ABI-stable.
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "render/image_header.h"

namespace {

void set_error(char* error, std::size_t size, const std::string& message) {
    if (size == 0) return;
    std::strncpy(error, message.c_str(), size - 1);
    error[size - 1] = '\0';
}

}  // namespace

/// Reads `path` as float RGB rows from the top; `*pixels` is malloc'd (free with wardray_oiio_free).
/// `*encoded` has bit 0 set when the file stores 8- or 16-bit values (to be decoded from sRGB) and bit 1 when it has
/// an alpha channel, bit 2 when it is grey (one channel, or grey and alpha) and bit 3 when it stores 16-bit values.
/// With an alpha channel the colours are straight, as the file stores them (OpenImageIO would premultiply them),
/// and `*alpha` (malloc'd, else null) holds each pixel's alpha. A file of more than `max_pixels` pixels is refused
/// before its pixels are allocated. Returns 1 on success.
extern "C" int wardray_oiio_read_bounded(const char* path, unsigned long long max_pixels, int* width, int* height,
                                          int* encoded, float** pixels, float** alpha, char* error,
                                          std::size_t error_size) {
    try {
        *alpha = nullptr;
        OIIO::ImageSpec config;
        config.attribute("oiio:UnassociatedAlpha", 1);
        auto in = OIIO::ImageInput::open(path, &config);
        if (!in) {
            set_error(error, error_size, OIIO::geterror());
            return 0;
        }
        const OIIO::ImageSpec& spec = in->spec();
        const int channels = spec.nchannels;
        const auto pixel_count = static_cast<unsigned long long>(std::max(spec.width, 0)) *
                                 static_cast<unsigned long long>(std::max(spec.height, 0));
        if (pixel_count > max_pixels || spec.width <= 0 || spec.height <= 0 || channels <= 0) {
            set_error(error, error_size,
                      pixel_count > max_pixels
                          ? wardray::render::oversized_message(spec.width, spec.height, max_pixels)
                          : "the file has no pixels");
            return 0;
        }
        std::vector<float> all(static_cast<std::size_t>(spec.width) * spec.height * channels);
        if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, all.data())) {
            set_error(error, error_size, in->geterror());
            return 0;
        }
        const std::size_t n = static_cast<std::size_t>(spec.width) * spec.height;
        float* rgb = static_cast<float*>(std::malloc(n * 3 * sizeof(float)));
        if (!rgb) {
            set_error(error, error_size, "out of memory");
            return 0;
        }
        // A grey file (with or without alpha) gives its one channel to all three.
        for (std::size_t i = 0; i < n; ++i)
            for (int c = 0; c < 3; ++c) rgb[3 * i + c] = all[i * channels + (channels <= 2 ? 0 : c)];
        const int alpha_channel =
            spec.alpha_channel >= 0 ? spec.alpha_channel : channels == 4 ? 3 : channels == 2 ? 1 : -1;
        if (alpha_channel >= 0 && alpha_channel < channels) {
            *alpha = static_cast<float*>(std::malloc(n * sizeof(float)));
            if (!*alpha) {
                std::free(rgb);
                set_error(error, error_size, "out of memory");
                return 0;
            }
            for (std::size_t i = 0; i < n; ++i) (*alpha)[i] = all[i * channels + alpha_channel];
        }
        *width = spec.width;
        *height = spec.height;
        const bool integer =
            spec.format.basetype == OIIO::TypeDesc::UINT8 || spec.format.basetype == OIIO::TypeDesc::UINT16;
        *encoded = (integer ? 1 : 0) | (alpha_channel >= 0 ? 2 : 0) | (channels <= 2 ? 4 : 0) |
                   (spec.format.basetype == OIIO::TypeDesc::UINT16 ? 8 : 0);
        *pixels = rgb;
        return 1;
    } catch (const std::exception& e) {
        set_error(error, error_size, e.what());
        return 0;
    }
}

extern "C" void wardray_oiio_free(float* pixels) { std::free(pixels); }
