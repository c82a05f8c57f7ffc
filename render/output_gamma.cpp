// Output gamma: PNG re-encoded from the working gamma to File_Gamma; HDR and EXR decoded to linear light.
#include "render/output_gamma.h"

#include "render/image_writers.h"

namespace wardray::render {

OutputGamma output_gamma(const scene::GlobalSettings& global, const GammaCurve& file_gamma,
                         const GammaCurve& display_gamma) {
    // POV-Ray compat: without gamma handling the display gamma stands in for both the working and the file gamma.
    if (!global.gamma_handling) return {display_gamma, display_gamma};
    return {global.assumed_gamma, file_gamma};
}

double antialias_gamma_on_working_values(double antialias_gamma, const GammaCurve& working) {
    return antialias_gamma / working.approximate_gamma();
}

std::optional<std::string> write_image(const Film& film, const std::filesystem::path& path, ImageFormat format,
                                       const OutputGamma& gamma, const Film* alpha) {
    if (format == ImageFormat::Png) {
        const GammaTranscoding encoding = transcoding(gamma.working, gamma.file);
        return write_atomically(path, [&](const std::filesystem::path& tmp) {
            return write_png(film, tmp, encoding, gamma.file, alpha);
        });
    }
    // HDR and EXR hold linear light whatever File_Gamma says.
    const GammaTranscoding to_linear = transcoding(gamma.working, GammaCurve::neutral());
    if (to_linear.is_neutral()) return write_image(film, path, format, alpha);
    Film linear(film.width(), film.height());
    for (int y = 0; y < film.height(); ++y) {
        for (int x = 0; x < film.width(); ++x) {
            const Vec3 c = film.pixel(x, y);
            linear.set_pixel(x, y, {to_linear.encode(c.x), to_linear.encode(c.y), to_linear.encode(c.z)});
        }
    }
    return write_image(linear, path, format, alpha);
}

}  // namespace wardray::render
