// Scene description, global settings: global_settings and its radiosity block.
#pragma once

#include <optional>
#include <string>

#include "core/color.h"
#include "core/diagnostics.h"
#include "core/gamma.h"

namespace wardray::scene {

/// The `radiosity { ... }` block of global_settings with POV-Ray 3.7's defaults.
struct RadiositySettings {
    int count = 35;
    int count_directions = 1600;
    double error_bound = 1.8;
    double low_error_factor = 0.5;
    double minimum_reuse = 0.015;
    double maximum_reuse = 0.2;
    int nearest_count = 5;
    int nearest_count_pretrace = 0;  ///< 0: not given
    int recursion_limit = 2;
    double pretrace_start = 0.08;
    double pretrace_end = 0.04;
    double brightness = 1.0;
    double gray_threshold = 0.0;
    double adc_bailout = 0.01;
    bool always_sample = false;
    double max_sample = -1.0;  ///< brightest a gather sample may be (its largest channel); ≤ 0: no limit
    bool normal = false;
    bool media = false;
    SourceLoc loc;
    bool operator==(const RadiositySettings&) const = default;
};

/// The `photons { ... }` block of global_settings with POV-Ray 3.7's defaults (its ScenePhotonSettings).
struct PhotonSettings {
    double spacing = 1.0;  ///< surface separation (POV-Ray's surfaceSeparation)
    int count = 0;         ///< `count`: a target photon count instead of spacing (0: not given)
    int gather_min = 20;
    int gather_max = 100;
    int media_steps = 0;  ///< `media max_steps [, factor]`: photons in media (0: none)
    double media_factor = 1.0;
    double jitter = 0.4;
    int max_trace_level = -1;  ///< −1: the scene's max_trace_level
    double adc_bailout = -1.0;  ///< −1: the scene's adc_bailout
    double expand_tolerance = 0.2;
    int expand_min = 35;
    double radius = -1.0;  ///< `radius gather, multiplier, media gather, media multiplier`; −1: estimated
    double radius_multiplier = 1.0;
    double media_radius = -1.0;
    double media_radius_multiplier = 1.0;
    double autostop = 0.5;
    std::string file;  ///< save_file or load_file name (empty: neither)
    bool load = false;  ///< `load_file` (else `save_file` when `file` is given)
    SourceLoc loc;
    bool operator==(const PhotonSettings&) const = default;
};

/// The scene-wide settings of global_settings, with POV-Ray 3.7's defaults.
struct GlobalSettings {
    GammaCurve assumed_gamma;  ///< the working gamma: how the scene's colour values are encoded
    bool assumed_gamma_given = false;
    /// POV-Ray 3.7's gamma model; false when the scene gives no assumed_gamma and its #version is below 3.7 or
    /// missing: POV-Ray 3.6's "no gamma handling", colour values written to files as they are.
    bool gamma_handling = true;
    Color ambient_light{1.0, 1.0, 1.0};
    int max_trace_level = 5;
    double adc_bailout = 1.0 / 255.0;
    int number_of_waves = 10;  ///< the wave sources of `waves` and `ripples` (POV-Ray's default 10)
    int noise_generator = 2;  ///< POV-Ray 3.7's default: range-corrected noise
    std::optional<RadiositySettings> radiosity;
    std::optional<PhotonSettings> photons;  ///< POV-Ray's photonsEnabled: a block with gather_max > 0
    bool operator==(const GlobalSettings&) const = default;
};

}  // namespace wardray::scene
