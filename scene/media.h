// Scene description, participating media: POV-Ray's `media { }` in an interior or in the scene (atmosphere).
#pragma once

#include <vector>

#include "core/color.h"
#include "core/diagnostics.h"
#include "core/transform.h"
#include "scene/texture.h"

namespace wardray::scene {

/// `media { ... }` with POV-Ray 3.7's defaults for a 3.5+ scene (method 3, intervals 1, samples 10).
struct Media {
    /// POV-Ray's scattering types: 1 isotropic, 2 Mie hazy, 3 Mie murky, 4 Rayleigh, 5 Henyey-Greenstein.
    int scattering_type = 1;
    Color absorption;
    Color emission;
    Color scattering;
    double eccentricity = 0.0;  ///< Henyey-Greenstein g
    double extinction = 1.0;    ///< `extinction`: how much of the scattering also dims light (sc_ext)
    int method = 3;
    int intervals = 1;
    int min_samples = 10;
    int max_samples = 10;
    double jitter = 0.0;
    double aa_threshold = 0.1;
    int aa_level = 3;
    double confidence = 0.9;
    double variance = 1.0 / 128.0;
    double ratio = 0.9;
    /// `density { }` blocks, each a pigment whose rgb scales the coefficients; several multiply. Empty: constant.
    std::vector<Pigment> densities;
    SourceLoc loc;
    bool operator==(const Media&) const = default;
};

/// Moves a media's densities with the object (or the transform written in the media block) that follows them.
inline void transform_media(Media& m, const Transform& tr) {
    for (Pigment& d : m.densities) d.pattern.transform = d.pattern.transform.then(tr);
}

}  // namespace wardray::scene
