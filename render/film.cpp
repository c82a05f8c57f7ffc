// Film: pixel storage and image files (the only file that includes OpenImageIO).
#include "render/film.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cmath>
#include <csignal>
#include <cstring>
#include <system_error>
#include <unistd.h>

namespace wardray::render {

namespace {

const char* oiio_format_name(ImageFormat format) {
    switch (format) {
        case ImageFormat::Png: return "png";
        case ImageFormat::Exr: return "openexr";
        case ImageFormat::Hdr: return "hdr";
    }
    return "png";
}

// The temporary file being written, for the signal handler; empty when none. A fixed buffer, because a
// signal handler may only touch async-signal-safe state.
char g_partial_path[4096] = {0};
std::atomic<bool> g_partial_active{false};

extern "C" void remove_partial_and_exit(int signal_number) {
    if (g_partial_active.load()) ::unlink(g_partial_path);
    ::_exit(128 + signal_number);
}

// Marks `path` as being written for as long as it lives.
class PartialFileGuard {
public:
    explicit PartialFileGuard(const std::filesystem::path& path) {
        const std::string s = path.string();
        if (s.size() < sizeof(g_partial_path)) {
            std::memcpy(g_partial_path, s.c_str(), s.size() + 1);
            g_partial_active.store(true);
        }
    }
    ~PartialFileGuard() { g_partial_active.store(false); }
    PartialFileGuard(const PartialFileGuard&) = delete;
    PartialFileGuard& operator=(const PartialFileGuard&) = delete;
};

// A temporary name beside the target, keeping the folder so the final rename is atomic.
std::filesystem::path temporary_name(const std::filesystem::path& path) {
    std::filesystem::path tmp = path;
    tmp.replace_filename("." + path.filename().string() + ".part" + std::to_string(::getpid()));
    return tmp;
}

}  // namespace

std::optional<ImageFormat> format_from_extension(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    if (ext == ".png") return ImageFormat::Png;
    if (ext == ".exr") return ImageFormat::Exr;
    if (ext == ".hdr" || ext == ".pic") return ImageFormat::Hdr;
    return std::nullopt;
}

const char* extension_of(ImageFormat format) {
    switch (format) {
        case ImageFormat::Png: return ".png";
        case ImageFormat::Exr: return ".exr";
        case ImageFormat::Hdr: return ".hdr";
    }
    return ".png";
}

Film::Film(int width, int height)
    : m_width(width), m_height(height), m_rgb(static_cast<std::size_t>(width) * height * 3, 0.0f) {}

Vec3 Film::pixel(int x, int y) const {
    const std::size_t i = (static_cast<std::size_t>(y) * m_width + x) * 3;
    return {m_rgb[i], m_rgb[i + 1], m_rgb[i + 2]};
}

void Film::set_pixel(int x, int y, const Vec3& rgb) {
    const std::size_t i = (static_cast<std::size_t>(y) * m_width + x) * 3;
    m_rgb[i] = static_cast<float>(rgb.x);
    m_rgb[i + 1] = static_cast<float>(rgb.y);
    m_rgb[i + 2] = static_cast<float>(rgb.z);
}

double srgb_encode(double v) {
    return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
}

double srgb_decode(double v) {
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

void remove_partial_output_on_signal() {
    for (int s : {SIGINT, SIGTERM, SIGHUP}) std::signal(s, remove_partial_and_exit);
}

std::optional<std::string> write_image(const Film& film, const std::filesystem::path& path, ImageFormat format) {
    const std::filesystem::path tmp = temporary_name(path);
    const PartialFileGuard guard(tmp);
    auto out = OIIO::ImageOutput::create(oiio_format_name(format));
    if (!out) return "cannot create an image writer: " + OIIO::geterror();

    bool ok = false;
    if (format == ImageFormat::Png) {
        // POV-Ray compat: 8-bit output is sRGB-encoded and quantised as floor(clip(x) * 255 + 0.5).
        OIIO::ImageSpec spec(film.width(), film.height(), 3, OIIO::TypeDesc::UINT8);
        spec.attribute("oiio:ColorSpace", "sRGB");
        std::vector<unsigned char> bytes(film.data().size());
        std::transform(film.data().begin(), film.data().end(), bytes.begin(), [](float v) {
            const double clipped = std::isfinite(v) ? std::clamp(static_cast<double>(v), 0.0, 1.0) : 0.0;
            return static_cast<unsigned char>(std::floor(srgb_encode(clipped) * 255.0 + 0.5));
        });
        ok = out->open(tmp.string(), spec) && out->write_image(OIIO::TypeDesc::UINT8, bytes.data());
    } else {
        OIIO::ImageSpec spec(film.width(), film.height(), 3,
                             format == ImageFormat::Exr ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::FLOAT);
        spec.attribute("oiio:ColorSpace", "Linear");
        ok = out->open(tmp.string(), spec) && out->write_image(OIIO::TypeDesc::FLOAT, film.data().data());
    }
    const std::string write_error = ok ? std::string() : out->geterror();
    ok = out->close() && ok;
    out.reset();
    std::error_code ec;
    if (!ok) {
        std::filesystem::remove(tmp, ec);
        return "cannot write '" + path.string() + "': " + (write_error.empty() ? "write failed" : write_error);
    }
    std::filesystem::rename(tmp, path, ec);
    if (ec) {
        std::filesystem::remove(tmp, ec);
        return "cannot write '" + path.string() + "': " + ec.message();
    }
    return std::nullopt;
}

std::optional<Film> read_image(const std::filesystem::path& path, std::string& error) {
    auto in = OIIO::ImageInput::open(path.string());
    if (!in) {
        error = "cannot read '" + path.string() + "': " + OIIO::geterror();
        return std::nullopt;
    }
    const OIIO::ImageSpec& spec = in->spec();
    const int channels = spec.nchannels;
    std::vector<float> pixels(static_cast<std::size_t>(spec.width) * spec.height * channels);
    if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, pixels.data())) {
        error = "cannot read '" + path.string() + "': " + in->geterror();
        return std::nullopt;
    }
    const bool encoded = spec.format.basetype == OIIO::TypeDesc::UINT8 ||
                         spec.format.basetype == OIIO::TypeDesc::UINT16;
    Film film(spec.width, spec.height);
    for (int y = 0; y < spec.height; ++y) {
        for (int x = 0; x < spec.width; ++x) {
            const float* p = &pixels[(static_cast<std::size_t>(y) * spec.width + x) * channels];
            Vec3 rgb{p[0], channels > 1 ? p[1] : p[0], channels > 2 ? p[2] : p[0]};
            if (encoded) rgb = {srgb_decode(rgb.x), srgb_decode(rgb.y), srgb_decode(rgb.z)};
            film.set_pixel(x, y, rgb);
        }
    }
    return film;
}

}  // namespace wardray::render
