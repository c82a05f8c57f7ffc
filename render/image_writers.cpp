// Image file writers. OpenImageIO is not used here on purpose: loading it costs about 0.7 s per process
// (its dependency chain: OpenCV, ffmpeg, OpenVDB, ...), against about 10 ms for libpng and OpenEXR, and
// every render writes an image. OpenImageIO remains the reader (image_reader.cpp).
#include "render/image_writers.h"

#include <ImfRgbaFile.h>
#include <png.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

namespace wardray::render {

namespace {

struct FileCloser {
    void operator()(std::FILE* f) const { std::fclose(f); }
};
using File = std::unique_ptr<std::FILE, FileCloser>;

// Radiance's shared-exponent encoding of one RGB triple (Ward, "Real Pixels", Graphics Gems II).
void to_rgbe(float r, float g, float b, unsigned char out[4]) {
    auto clean = [](float v) { return std::isfinite(v) && v > 0.0f ? v : 0.0f; };
    r = clean(r);
    g = clean(g);
    b = clean(b);
    const float v = std::max({r, g, b});
    if (v < 1e-32f) {
        out[0] = out[1] = out[2] = out[3] = 0;
        return;
    }
    int e = 0;
    const float scale = std::frexp(v, &e) * 256.0f / v;
    out[0] = static_cast<unsigned char>(r * scale);
    out[1] = static_cast<unsigned char>(g * scale);
    out[2] = static_cast<unsigned char>(b * scale);
    out[3] = static_cast<unsigned char>(e + 128);
}

// Appends one component of a scanline in Radiance's run-length form: runs of 4 or more equal bytes as
// (128 + n, byte), everything else as literal chunks (n, bytes...), n ≤ 127 / 128.
void append_rle_component(const std::vector<unsigned char>& data, std::vector<unsigned char>& out) {
    std::size_t i = 0;
    while (i < data.size()) {
        std::size_t run = 1;
        while (i + run < data.size() && run < 127 && data[i + run] == data[i]) ++run;
        if (run >= 4) {
            out.push_back(static_cast<unsigned char>(128 + run));
            out.push_back(data[i]);
            i += run;
            continue;
        }
        // A literal chunk up to the next run of 4 or the chunk limit.
        std::size_t end = i;
        while (end < data.size() && end - i < 128) {
            std::size_t r = 1;
            while (end + r < data.size() && r < 4 && data[end + r] == data[end]) ++r;
            if (r >= 4) break;
            ++end;
        }
        out.push_back(static_cast<unsigned char>(end - i));
        out.insert(out.end(), data.begin() + i, data.begin() + end);
        i = end;
    }
}

}  // namespace

unsigned char encode_srgb8(float v) {
    const double clipped = std::isfinite(v) ? std::clamp(static_cast<double>(v), 0.0, 1.0) : 0.0;
    return static_cast<unsigned char>(std::floor(srgb_encode(clipped) * 255.0 + 0.5));
}

unsigned char encode8(const GammaTranscoding& encoding, float v) {
    if (encoding == transcoding(GammaCurve::neutral(), GammaCurve::srgb())) return encode_srgb8(v);
    // POV-Ray compat: quantised in single precision, as POV-Ray does, so values on a half level round alike.
    const float encoded = std::isfinite(v) ? static_cast<float>(encoding.encode(v)) : 0.0f;
    return static_cast<unsigned char>(std::floor(std::clamp(encoded, 0.0f, 1.0f) * 255.0f + 0.5f));
}

namespace {

// The libpng calls, in a function of their own: libpng reports errors by longjmp, so only plain locals may
// live across its setjmp (the caller owns the file and the row buffer). Returns false on a libpng error.
bool write_png_rows(std::FILE* file, const Film& film, const Film* alpha, unsigned char* row,
                    const GammaTranscoding& encoding, const GammaCurve& file_gamma) {
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (!info) {
        png_destroy_write_struct(&png, nullptr);
        return false;
    }
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        return false;
    }
    png_init_io(png, file);
    png_set_IHDR(png, info, film.width(), film.height(), 8, alpha ? PNG_COLOR_TYPE_RGB_ALPHA : PNG_COLOR_TYPE_RGB,
                 PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    if (file_gamma.kind == GammaCurve::Kind::Srgb)
        png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
    else
        png_set_gAMA(png, info, 1.0 / file_gamma.approximate_gamma());
    png_write_info(png, info);
    const float* data = film.data().data();
    const std::size_t row_size = static_cast<std::size_t>(film.width()) * 3;
    const bool plain_srgb = encoding == transcoding(GammaCurve::neutral(), GammaCurve::srgb());
    for (int y = 0; y < film.height(); ++y) {
        const float* src = data + static_cast<std::size_t>(y) * row_size;
        if (alpha) {
            const float* a_src = alpha->data().data() + static_cast<std::size_t>(y) * row_size;
            for (int x = 0; x < film.width(); ++x) {
                float r = src[3 * x], g = src[3 * x + 1], b = src[3 * x + 2], a = a_src[3 * x];
                unassociate_alpha(r, g, b, a);
                unsigned char* out = row + 4 * static_cast<std::size_t>(x);
                out[0] = encode8(encoding, r);
                out[1] = encode8(encoding, g);
                out[2] = encode8(encoding, b);
                out[3] = encode8(transcoding(GammaCurve::neutral(), GammaCurve::neutral()), a);
            }
            png_write_row(png, row);
            continue;
        }
        if (plain_srgb)
            for (std::size_t i = 0; i < row_size; ++i) row[i] = encode_srgb8(src[i]);
        else
            for (std::size_t i = 0; i < row_size; ++i) row[i] = encode8(encoding, src[i]);
        png_write_row(png, row);
    }
    png_write_end(png, info);
    png_destroy_write_struct(&png, &info);
    return true;
}

}  // namespace

std::optional<std::string> write_png(const Film& film, const std::filesystem::path& path) {
    return write_png(film, path, transcoding(GammaCurve::neutral(), GammaCurve::srgb()), GammaCurve::srgb());
}

void unassociate_alpha(float& r, float& g, float& b, float& a) {
    const float bright = 0.297f * r + 0.589f * g + 0.114f * b;
    if (bright > a) a = std::min(1.0f, bright);
    const float divisor = a == 0.0f ? 1.0e-6f : a;
    r /= divisor;
    g /= divisor;
    b /= divisor;
}

std::optional<std::string> write_png(const Film& film, const std::filesystem::path& path,
                                     const GammaTranscoding& encoding, const GammaCurve& file_gamma,
                                     const Film* alpha) {
    File file(std::fopen(path.c_str(), "wb"));
    if (!file) return std::string("cannot open for writing");
    std::vector<unsigned char> row(static_cast<std::size_t>(film.width()) * (alpha ? 4 : 3));
    if (!write_png_rows(file.get(), film, alpha, row.data(), encoding, file_gamma))
        return std::string("libpng failed while writing");
    if (std::fflush(file.get()) != 0 || std::ferror(file.get())) return std::string("write failed");
    return std::nullopt;
}

std::optional<std::string> write_exr(const Film& film, const std::filesystem::path& path, const Film* alpha) {
    try {
        std::vector<Imf::Rgba> pixels(static_cast<std::size_t>(film.width()) * film.height());
        const std::vector<float>& data = film.data();
        for (std::size_t i = 0; i < pixels.size(); ++i)
            pixels[i] = Imf::Rgba(data[3 * i], data[3 * i + 1], data[3 * i + 2], alpha ? alpha->data()[3 * i] : 1.0f);
        Imf::RgbaOutputFile out(path.c_str(), film.width(), film.height(), alpha ? Imf::WRITE_RGBA : Imf::WRITE_RGB);
        out.setFrameBuffer(pixels.data(), 1, film.width());
        out.writePixels(film.height());
    } catch (const std::exception& e) {
        return std::string(e.what());
    }
    return std::nullopt;
}

std::optional<std::string> write_hdr(const Film& film, const std::filesystem::path& path) {
    File file(std::fopen(path.c_str(), "wb"));
    if (!file) return std::string("cannot open for writing");
    std::fprintf(file.get(), "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y %d +X %d\n", film.height(), film.width());
    const int w = film.width();
    // Run-length scanlines need 8 <= width < 32768; other widths are written flat.
    const bool rle = w >= 8 && w < 32768;
    std::vector<unsigned char> rgbe(static_cast<std::size_t>(w) * 4);
    std::vector<unsigned char> component(w);
    std::vector<unsigned char> line;
    const std::vector<float>& data = film.data();
    for (int y = 0; y < film.height(); ++y) {
        const float* src = &data[static_cast<std::size_t>(y) * w * 3];
        for (int x = 0; x < w; ++x) to_rgbe(src[3 * x], src[3 * x + 1], src[3 * x + 2], &rgbe[4 * x]);
        if (!rle) {
            std::fwrite(rgbe.data(), 1, rgbe.size(), file.get());
            continue;
        }
        line = {2, 2, static_cast<unsigned char>(w >> 8), static_cast<unsigned char>(w & 0xFF)};
        for (int c = 0; c < 4; ++c) {
            for (int x = 0; x < w; ++x) component[x] = rgbe[4 * x + c];
            append_rle_component(component, line);
        }
        std::fwrite(line.data(), 1, line.size(), file.get());
    }
    if (std::fflush(file.get()) != 0 || std::ferror(file.get())) return std::string("write failed");
    return std::nullopt;
}

}  // namespace wardray::render
