// Film: pixel storage, and image files written by format and read through the OpenImageIO module.
#include "render/film.h"
#include "render/gif_reader.h"
#include "render/jpeg_reader.h"
#include "render/png_reader.h"

#include "render/image_writers.h"

#include <dlfcn.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cmath>
#include <csignal>
#include <cstring>
#include <mutex>
#include <system_error>
#include <unistd.h>

namespace wardray::render {

namespace {

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

// The OpenImageIO reader module's entry points (render/oiio_reader_module.cpp).
struct OiioReader {
    int (*read)(const char*, unsigned long long, int*, int*, int*, float**, float**, char*, std::size_t) = nullptr;
    void (*release)(float*) = nullptr;
};

// Loads the reader module once: beside the executable, else in the build folder this was built in.
const OiioReader* oiio_reader(std::string& error) {
    static OiioReader reader;
    static std::string load_error;
    static std::once_flag once;
    std::call_once(once, [] {
        std::error_code ec;
        const std::filesystem::path exe_dir = std::filesystem::read_symlink("/proc/self/exe", ec).parent_path();
        std::string tried;
        for (const std::filesystem::path& dir : {exe_dir, std::filesystem::path(WARDRAY_MODULE_DIR)}) {
            const std::filesystem::path module = dir / "libwardray_oiio.so";
            void* handle = ::dlopen(module.c_str(), RTLD_NOW | RTLD_LOCAL);
            if (!handle) {
                tried += std::string(tried.empty() ? "" : "; ") + ::dlerror();
                continue;
            }
            reader.read = reinterpret_cast<decltype(reader.read)>(::dlsym(handle, "wardray_oiio_read_bounded"));
            reader.release = reinterpret_cast<decltype(reader.release)>(::dlsym(handle, "wardray_oiio_free"));
            if (reader.read && reader.release) return;
            tried += "; " + module.string() + " lacks the reader entry points";
        }
        load_error = "the image reader module libwardray_oiio.so could not be loaded (" + tried + ")";
    });
    if (!reader.read) {
        error = load_error;
        return nullptr;
    }
    return &reader;
}

// A temporary name beside the target, keeping the folder so the final rename is atomic.
std::filesystem::path temporary_name(const std::filesystem::path& path) {
    std::filesystem::path tmp = path;
    // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) about `"." + std::string`.
    std::string name = ".";
    name += path.filename().string();
    name += ".part";
    name += std::to_string(::getpid());
    tmp.replace_filename(name);
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

Film::Film(int width, int height, std::vector<float> rgb) : m_width(width), m_height(height), m_rgb(std::move(rgb)) {}

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

std::optional<std::string> write_atomically(
    const std::filesystem::path& path,
    const std::function<std::optional<std::string>(const std::filesystem::path& temporary)>& write) {
    const std::filesystem::path tmp = temporary_name(path);
    const PartialFileGuard guard(tmp);
    std::error_code ec;
    if (const auto error = write(tmp)) {
        std::filesystem::remove(tmp, ec);
        return "cannot write '" + path.string() + "': " + *error;
    }
    std::filesystem::rename(tmp, path, ec);
    if (ec) {
        std::filesystem::remove(tmp, ec);
        return "cannot write '" + path.string() + "': " + ec.message();
    }
    return std::nullopt;
}

std::optional<std::string> write_image(const Film& film, const std::filesystem::path& path, ImageFormat format,
                                       const Film* alpha) {
    return write_atomically(path, [&](const std::filesystem::path& tmp) -> std::optional<std::string> {
        switch (format) {
            case ImageFormat::Png:
                return write_png(film, tmp, transcoding(GammaCurve::neutral(), GammaCurve::srgb()), GammaCurve::srgb(),
                                 alpha);
            case ImageFormat::Exr: return write_exr(film, tmp, alpha);
            case ImageFormat::Hdr: return write_hdr(film, tmp);
        }
        return std::string("unknown image format");
    });
}

std::optional<Film> read_image(const std::filesystem::path& path, std::string& error, bool* stored, bool* alpha,
                               bool* grey, bool* bits16, std::vector<float>* alpha_values, std::uint64_t max_pixels) {
    if (const auto oversized = oversized_image(path, max_pixels)) {
        error = *oversized;
        return std::nullopt;
    }
    // PNGs (but grey and RGB ones with a tRNS chunk), JPEGs and GIFs (most image maps and JPEG height fields) through
    // libpng, libjpeg and the GIF decoder; the rest through OpenImageIO, loaded on first use (about 0.5 s and 120 MB of libraries).
    int width = 0, height = 0;
    std::vector<float> pixels, png_alpha;
    bool jpeg_grey = false, gif = false, png_with_alpha = false;
    if (grey || bits16) {
        if (!read_jpeg_rgb(path, width, height, pixels, &jpeg_grey))
            return read_image_with_oiio(path, error, stored, alpha, grey, bits16, alpha_values, max_pixels);
    } else if (!read_png_rgb(path, width, height, pixels) && !read_jpeg_rgb(path, width, height, pixels)) {
        if (read_png_rgba(path, width, height, pixels, png_alpha)) {
            png_with_alpha = true;
        } else {
            if (!read_gif_rgb(path, width, height, pixels))
                return read_image_with_oiio(path, error, stored, alpha, nullptr, nullptr, alpha_values, max_pixels);
            gif = true;
        }
    }
    // The decoded samples become the film's own (a large image map is not held twice while it is read).
    pixels.resize(static_cast<std::size_t>(width) * height * 3);
    if (!stored)
        for (float& v : pixels) v = static_cast<float>(srgb_decode(v));
    Film film(width, height, std::move(pixels));
    if (stored) *stored = true;
    // POV-Ray compat (of OpenImageIO's reading): a GIF reports an alpha channel without values (OpenImageIO
    // names channel 4 of its 4), so an image map warns that its alpha is not rendered and is opaque.
    if (alpha) *alpha = gif || png_with_alpha;
    if (grey) *grey = jpeg_grey;
    if (bits16) *bits16 = false;
    if (alpha_values) *alpha_values = std::move(png_alpha);
    return film;
}

std::optional<Film> read_image_with_oiio(const std::filesystem::path& path, std::string& error, bool* stored,
                                         bool* alpha, bool* grey, bool* bits16, std::vector<float>* alpha_values,
                                         std::uint64_t max_pixels) {
    const OiioReader* reader = oiio_reader(error);
    if (!reader) return std::nullopt;
    int width = 0, height = 0, encoded = 0;
    float* pixels = nullptr;
    float* alpha_channel = nullptr;
    char message[512] = {0};
    if (!reader->read(path.c_str(), max_pixels, &width, &height, &encoded, &pixels, &alpha_channel, message,
                      sizeof(message))) {
        error = "cannot read '" + path.string() + "': " + message;
        return std::nullopt;
    }
    Film film(width, height);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const float* p = &pixels[(static_cast<std::size_t>(y) * width + x) * 3];
            Vec3 rgb{p[0], p[1], p[2]};
            if ((encoded & 1) && !stored) rgb = {srgb_decode(rgb.x), srgb_decode(rgb.y), srgb_decode(rgb.z)};
            film.set_pixel(x, y, rgb);
        }
    }
    reader->release(pixels);
    if (alpha_values) {
        alpha_values->clear();
        if (alpha_channel) alpha_values->assign(alpha_channel, alpha_channel + static_cast<std::size_t>(width) * height);
    }
    if (alpha_channel) reader->release(alpha_channel);
    if (stored) *stored = (encoded & 1) != 0;
    if (alpha) *alpha = (encoded & 2) != 0;
    if (grey) *grey = (encoded & 4) != 0;
    if (bits16) *bits16 = (encoded & 8) != 0;
    return film;
}

}  // namespace wardray::render
