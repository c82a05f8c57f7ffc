// Options: what a run is asked to do, from POV-Ray's switches, its INI keys and wardray's long options.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "core/gamma.h"
#include "lighting/integrator.h"
#include "render/film.h"

namespace wardray::app {

/// POV-Ray's animation settings as given (+KFI, +KFF, +KI, +KF, +KC, +SF, +EF, +K); app/animation.h makes frames.
struct AnimationOptions {
    std::optional<int> initial_frame{};  ///< +KFI; with +KFF unset, no animation unless one of them is given
    std::optional<int> final_frame{};    ///< +KFF
    double initial_clock = 0.0;          ///< +KI
    double final_clock = 1.0;            ///< +KF
    bool cyclic = false;                 ///< +KC: the last frame is one step short of final_clock
    std::optional<int> subset_start{};   ///< +SF: the first frame rendered
    std::optional<int> subset_end{};     ///< +EF: the last frame rendered
    std::optional<double> clock{};       ///< +K / Clock=: a still image's clock

    friend bool operator==(const AnimationOptions&, const AnimationOptions&) = default;
};

/// +SR/+ER/+SC/+EC as written: a fraction of the image or a 1-based pixel number (app/partial_render.h).
struct RegionOptions {
    std::optional<double> start_row{}, end_row{}, start_column{}, end_column{};

    friend bool operator==(const RegionOptions&, const RegionOptions&) = default;
};

/// --gi-carry: how irradiance records cross from frame to frame of an animation: not at all (each frame afresh,
/// POV-Ray's default), all of them (as +RFI +RFO do through the file), or only those whose surroundings did not
/// change (app/cache_carry.h).
enum class CarryMode { Off, All, Still };

/// Everything the command line (or an INI setting) can set. Defaults are POV-Ray's.
struct Options {
    std::filesystem::path scene;                    ///< empty: the bundled default scene
    std::optional<std::filesystem::path> output;    ///< empty: the scene's name with the format's extension
    std::optional<render::ImageFormat> format;              ///< from +F; otherwise from the output's extension
    bool write_output = true;                       ///< -F turns file output off, as in POV-Ray
    int width = 320;
    int height = 240;
    int threads = 0;                                ///< 0: all cores
    bool antialias = false;
    double antialias_threshold = 0.3;  ///< +A0.3
    int antialias_depth = 3;           ///< +R3
    int sampling_method = 1;           ///< +AM1 or +AM2
    double jitter = 1.0;               ///< +J1.0, -J: 0
    double antialias_gamma = 2.5;      ///< +AG2.5
    GammaCurve file_gamma = GammaCurve::srgb();     ///< File_Gamma=: the PNG encoding (HDR and EXR stay linear)
    GammaCurve display_gamma = GammaCurve::srgb();  ///< Display_Gamma=: used for files only by 3.6 scenes
    std::optional<lighting::GiMode> gi;             ///< empty: cache when the scene has radiosity, else off
    int gi_rays = 256;                              ///< --gi-rays: paths per pixel in reference mode
    int gi_light_picks = 1;                         ///< --gi-light-picks: shadow-tested lights per gather hit
    bool gi_guide = true;                           ///< --gi-guide=off: reference paths sample the cosine alone
    std::uint64_t seed = 0;                         ///< --seed: 0 draws the samples the renders without it draw
    std::optional<std::uint64_t> gi_path_seed;      ///< --gi-path-seed: the reference paths' own seed
    bool gi_fine_area_lights = true;                ///< --gi-area-lights=grid: the reference keeps POV-Ray's grid
    bool gi_gradients = true;                       ///< --gi-gradients=off: records without gradients
    bool gi_gradient_cap = true;                    ///< --gi-gradient-cap=off: no radius cap E/|∇t E|
    bool gi_neighbour_clamp = true;                 ///< --gi-neighbour-clamp=off: no neighbour clamping
    bool gi_hessian_spacing = true;                 ///< --gi-spacing=harmonic: record radii from hit distances
    bool gi_adaptive = false;                       ///< --gi-adaptive: extra gather rays where strata differ
    int gi_lookup_sampling = 4;                     ///< --gi-lookup-sampling: 1 lookup in K at gather hits
    bool gi_geometry_floor = true;                  ///< --gi-reuse-floor=screen: POV-Ray's minimum_reuse everywhere
    bool pretrace = true;                           ///< --no-pretrace: skip POV-Ray's pretrace passes
    bool gi_record_pass = true;                     ///< --gi-record-pass=off: the final pass makes its records
    /// --gi-pretrace-bound=pov: the pretrace's error bound is POV-Ray's error_bound × low_error_factor; by default
    /// (with the record passes and the gradients) error_bound × cache::pretrace_low_error_factor(low_error_factor).
    bool gi_pov_pretrace_bound = false;
    bool radiosity_load = false;                    ///< +RFI: start from the records of the radiosity file
    bool radiosity_save = false;                    ///< +RFO: write every record to the radiosity file
    std::optional<std::filesystem::path> radiosity_file;  ///< +RF<name>; empty: the scene's name with .rca
    CarryMode gi_carry = CarryMode::Off;                  ///< --gi-carry=all|still|off
    std::optional<std::filesystem::path> aov_irradiance;  ///< --aov irradiance FILE: indirect irradiance alone
    std::optional<std::filesystem::path> aov_records;     ///< --aov records FILE: the image with the records as dots
    std::vector<std::pair<std::string, double>> declares;
    std::vector<std::filesystem::path> library_paths;
    std::optional<std::filesystem::path> stats;
    /// #fopen may also read from these folders (--read-path) and write into these (--write-path).
    std::vector<std::filesystem::path> read_paths;
    /// --strict-reads: none of the folders Debian's povray.conf permits ($HOME, /tmp, ...), only the scene's folder,
    /// the include path and the --read-path folders.
    bool strict_reads = false;
    std::vector<std::filesystem::path> write_paths;
    bool allow_file_writes = false;  ///< --allow-file-writes: #write really writes (inside the permitted folders)
    // Parser guard rails; empty keeps the parser's defaults.
    std::optional<std::uint64_t> max_loop_iterations;
    std::optional<std::uint64_t> max_macro_depth;
    std::optional<std::uint64_t> max_include_depth;
    std::optional<std::uint64_t> max_array_size;
    std::optional<std::uint64_t> max_string_length;
    std::optional<std::uint64_t> max_memory_file;
    std::optional<std::uint64_t> max_objects;  ///< --max-objects
    std::optional<std::uint64_t> max_memory;   ///< --max-memory, in MB
    AnimationOptions animation;
    RegionOptions region;
    bool continue_trace = false;  ///< +C: frames whose image already exists are not rendered again
    bool output_alpha = false;    ///< +UA: the image gets an alpha channel (background transparent)
    int quality = 9;              ///< +Q
    int render_block_size = 32;   ///< +BS: POV-Ray's render block, the unit of antialiasing decisions
    /// Settings read and not used ("Create_Ini is not supported; ignored"), each with its file:line, printed when
    /// the run starts.
    std::vector<std::string> warnings;
    bool check_only = false;
    bool verbose = false;
    bool show_help = false;
    bool show_version = false;

    /// Equal when every field is (so tests can say two spellings set the same thing).
    friend bool operator==(const Options&, const Options&) = default;
};

/// What went wrong with the command line: a message for stderr; the caller exits with status 2.
struct UsageError {
    std::string message;
    /// The mistake is in an INI file (the message starts with its file:line): exit status 1, no usage text.
    bool in_file = false;
};

/// Parses argv[1..]; the result is either options or a usage error.
std::variant<Options, UsageError> parse_command_line(const std::vector<std::string>& args);

/// Applies one INI setting (`Width=640` is key "Width", value "640"; key and value trimmed, keys compared without
/// case) through the same table as the switches, so it sets `options` as `+W640` does; an unknown key or a wrong
/// value is an error.
std::optional<UsageError> apply_ini_setting(std::string_view key, std::string_view value, Options& options);

/// The usage text printed with a usage error and by --help, generated from the option table.
std::string usage_text();

}  // namespace wardray::app
