// Output gamma: how POV-Ray 3.7 turns a render's working-gamma values into the values an image file holds.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "core/gamma.h"
#include "render/film.h"
#include "scene/settings.h"

namespace wardray::render {

/// The two curves an image is written with: the film holds values encoded with `working`; PNG re-encodes them
/// with `file`, HDR and EXR decode them to linear light.
struct OutputGamma {
    GammaCurve working;                    ///< the scene's assumed_gamma (neutral: the film is linear)
    GammaCurve file = GammaCurve::srgb();  ///< File_Gamma: PNG's encoding
};

/// POV-Ray 3.7's output gamma for a scene, given File_Gamma and Display_Gamma (default sRGB each). With gamma
/// handling off (a 3.6 scene without assumed_gamma) both curves are the display gamma, so a PNG holds the colour
/// values as they are and an HDR file those values decoded with the display gamma.
OutputGamma output_gamma(const scene::GlobalSettings& global, const GammaCurve& file_gamma,
                         const GammaCurve& display_gamma);

/// The antialiasing comparison gamma (+AG) to use on working-gamma values: POV-Ray decodes the working gamma
/// first, so a power law `g` turns +AG `a` into a / g (sRGB working gamma is taken as 2.2).
double antialias_gamma_on_working_values(double antialias_gamma, const GammaCurve& working);

/// Writes `film` (working-gamma values) to `path` as `format` with `gamma`, atomically as write_image does; with
/// `alpha`, PNG and EXR get an alpha channel (see write_image).
std::optional<std::string> write_image(const Film& film, const std::filesystem::path& path, ImageFormat format,
                                       const OutputGamma& gamma, const Film* alpha = nullptr);

}  // namespace wardray::render
