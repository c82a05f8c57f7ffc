// The option table: one entry per option; the command line, INI settings and --help all read it.
#include "app/option_table.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <iterator>
#include <vector>

namespace wardray::app {

namespace {

using Why = std::optional<std::string>;

// Image sizes beyond this are refused before any memory is asked for (64k x 64k is 48 GiB of film).
constexpr int kMaxImageSide = 65536;


std::filesystem::path to_path(std::string_view text) {
    return std::filesystem::path(std::string(text));
}

Why set_count(std::string_view text, int low, int high, const char* why, int& out) {
    int n = 0;
    if (!parse_int(text, n) || n < low || n > high) return why;
    out = n;
    return std::nullopt;
}

Why set_size(std::string_view text, int& out) {
    return set_count(text, 1, kMaxImageSide, "expected a size in pixels, 1..65536", out);
}

Why set_path(std::string_view text, const char* why, std::optional<std::filesystem::path>& out) {
    if (text.empty()) return why;
    out = to_path(text);
    return std::nullopt;
}

Why add_path(std::string_view text, const char* why, std::vector<std::filesystem::path>& out) {
    if (text.empty()) return why;
    out.push_back(to_path(text));
    return std::nullopt;
}

// The parser's guard rails: a positive whole number.
Why set_limit(std::string_view text, std::optional<std::uint64_t>& out) {
    std::uint64_t n = 0;
    const char* end = text.data() + text.size();
    if (text.empty() || std::from_chars(text.data(), end, n).ptr != end || n == 0)
        return "needs a positive whole number";
    out = n;
    return std::nullopt;
}

// --seed: any 64-bit unsigned number (0, the default, is the render without it).
Why set_seed(std::string_view text, std::uint64_t& out) {
    std::uint64_t n = 0;
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, n);
    if (text.empty() || ec != std::errc{} || ptr != end) return "needs a whole number 0..2^64-1";
    out = n;
    return std::nullopt;
}

// POV-Ray's +F: -F writes no file, +F writes one, +F<letter> also names the format (only its first letter counts).
Why set_output_type(const OptionUse& use, Options& o) {
    if (use.value.empty()) {
        o.write_output = use.sign.value_or(true);
        return std::nullopt;
    }
    if (use.sign) o.write_output = true;
    switch (std::toupper(static_cast<unsigned char>(use.value[0]))) {
        case 'N': o.format = render::ImageFormat::Png; break;
        case 'E': o.format = render::ImageFormat::Exr; break;
        case 'H': o.format = render::ImageFormat::Hdr; break;
        default: return "supported formats are +FN (PNG), +FE (OpenEXR) and +FH (Radiance HDR)";
    }
    return std::nullopt;
}

// POV-Ray's +A[threshold] / -A; a threshold after the switch also turns antialiasing on.
Why set_antialias(const OptionUse& use, Options& o) {
    if (use.sign) o.antialias = *use.sign;
    if (use.value.empty()) return std::nullopt;
    double t = 0.0;
    if (!parse_double(use.value, t) || t < 0.0) return "expected a non-negative threshold";
    o.antialias_threshold = t;
    if (use.sign) o.antialias = true;
    return std::nullopt;
}

// POV-Ray's +J[amount] / -J: -J (or Jitter=off) is no jitter whatever follows; +J alone is 1.
Why set_jitter(const OptionUse& use, Options& o) {
    if (use.sign == false) {
        o.jitter = 0.0;
        return std::nullopt;
    }
    double j = 1.0;
    if (!use.value.empty() && (!parse_double(use.value, j) || j < 0.0)) return "expected a jitter amount >= 0";
    o.jitter = j;
    return std::nullopt;
}

// POV-Ray's Declare=NAME=VALUE: a float defined before the scene is read.
Why set_declare(const OptionUse& use, Options& o) {
    const auto eq = use.value.find('=');
    double v = 0.0;
    if (eq == std::string_view::npos || eq == 0 || !parse_double(use.value.substr(eq + 1), v))
        return "expected Declare=NAME=NUMBER";
    o.declares.emplace_back(std::string(use.value.substr(0, eq)), v);
    return std::nullopt;
}

Why set_gi(const OptionUse& use, Options& o) {
    if (use.value == "cache") o.gi = lighting::GiMode::Cache;
    else if (use.value == "reference") o.gi = lighting::GiMode::Reference;
    else if (use.value == "off") o.gi = lighting::GiMode::Off;
    else return "must be cache, reference or off";
    return std::nullopt;
}

Why set_gi_spacing(const OptionUse& use, Options& o) {
    if (use.value == "harmonic") o.gi_hessian_spacing = false;
    else if (use.value == "hessian") o.gi_hessian_spacing = true;
    else return "must be harmonic or hessian";
    return std::nullopt;
}

Why set_gi_pretrace_bound(const OptionUse& use, Options& o) {
    if (use.value == "final") o.gi_pov_pretrace_bound = false;
    else if (use.value == "pov") o.gi_pov_pretrace_bound = true;
    else return "must be final or pov";
    return std::nullopt;
}

Why set_gi_reuse_floor(const OptionUse& use, Options& o) {
    if (use.value == "geometry") o.gi_geometry_floor = true;
    else if (use.value == "screen") o.gi_geometry_floor = false;
    else return "must be geometry or screen";
    return std::nullopt;
}

Why set_gi_area_lights(const OptionUse& use, Options& o) {
    if (use.value == "fine") o.gi_fine_area_lights = true;
    else if (use.value == "grid") o.gi_fine_area_lights = false;
    else return "must be fine or grid";
    return std::nullopt;
}

Why set_aov(const OptionUse& use, Options& o) {
    if ((use.value != "irradiance" && use.value != "records") || use.second.empty())
        return "needs a kind (irradiance or records) and a file name";
    (use.value == "irradiance" ? o.aov_irradiance : o.aov_records) = to_path(use.second);
    return std::nullopt;
}

// An option that sets one flag: from the switch's sign or INI on/off, else on.
template <bool Options::*Field>
Why set_sign(const OptionUse& use, Options& o) {
    o.*Field = use.sign.value_or(true);
    return std::nullopt;
}

Why set_scene(const OptionUse& use, Options& o) {
    if (use.value.empty()) return "expected a scene file name";
    o.scene = to_path(use.value);
    return std::nullopt;
}

Why set_antialias_gamma(const OptionUse& use, Options& o) {
    double g = 0.0;
    if (!parse_double(use.value, g) || g <= 0.0) return "expected a positive antialiasing gamma";
    o.antialias_gamma = g;
    return std::nullopt;
}

// POV-Ray's File_Gamma= and Display_Gamma=: a positive number (1.0 is no gamma) or sRGB.
Why set_gamma(std::string_view text, GammaCurve& out) {
    double g = 0.0;
    if (parse_double(text, g) && g > 0.0) {
        out = GammaCurve::power_law(g);
        return std::nullopt;
    }
    if (equals_ci(text, "srgb")) {
        out = GammaCurve::srgb();
        return std::nullopt;
    }
    return "expected a positive gamma or sRGB";
}

// POV-Ray 3.7's methods: 1 (adaptive, non-recursive) and 2 (adaptive, recursive); POV-Ray compat: 3.7 renders
// +AM3 as method 2.
Why set_sampling_method(const OptionUse& use, Options& o) {
    if (use.value != "1" && use.value != "2" && use.value != "3") return "expected sampling method 1, 2 or 3";
    o.sampling_method = use.value == "1" ? 1 : 2;
    return std::nullopt;
}

// There is no preview window, so +D and -D are accepted and ignored.
Why set_display(const OptionUse& use, Options&) {
    if (!use.value.empty()) return "unknown display option";
    return std::nullopt;
}

Why set_verbose(const OptionUse& use, Options& o) {
    if (!use.value.empty()) return "unknown verbosity option";
    o.verbose = use.sign.value_or(true);
    return std::nullopt;
}

Why set_gi_gradients(const OptionUse& use, Options& o) {
    if (use.value != "on" && use.value != "off") return "must be on or off";
    o.gi_gradients = use.value == "on";
    return std::nullopt;
}

Why set_on_off(const OptionUse& use, bool& value) {
    if (use.value != "on" && use.value != "off") return "must be on or off";
    value = use.value == "on";
    return std::nullopt;
}

Why set_gi_carry(const OptionUse& use, Options& o) {
    if (use.value == "all") o.gi_carry = CarryMode::All;
    else if (use.value == "still") o.gi_carry = CarryMode::Still;
    else if (use.value == "off") o.gi_carry = CarryMode::Off;
    else return "must be all, still or off";
    return std::nullopt;
}

Why set_no_pretrace(const OptionUse&, Options& o) {
    o.pretrace = false;
    return std::nullopt;
}

using K = ValueKind;
using U = const OptionUse&;  // the setters' first parameter, short so that an entry fits its lines

// POV-Ray's switches (with their keys from POV-Ray 3.7's INI table), then wardray's own long options.
constexpr OptionSpec kOptions[] = {
    {.letters = "I", .ini_key = "Input_File_Name", .kind = K::Value, .usage = "+Iscene.pov",
     .help = "the scene (or the first argument that is not an option)", .set = set_scene},
    {.letters = "O", .ini_key = "Output_File_Name", .long_name = "--output", .short_name = "-o", .kind = K::Value,
     .usage = "+Ofile, -o file", .help = "output image (default: the scene's name, .png)",
     .long_error = "needs a file name",
     .set = [](U u, Options& o) { return set_path(u.value, "expected an output file name", o.output); }},
    {.letters = "F", .ini_key = "Output_File_Type", .ini_flag = "Output_To_File", .kind = K::FlagValue,
     .usage = "+FN +FE +FH, -F", .help = "PNG (sRGB), OpenEXR or Radiance HDR (linear); -F writes no file",
     .set = set_output_type},
    {.letters = "W", .ini_key = "Width", .kind = K::Value, .usage = "+Wn", .help = "image width (default 320)",
     .set = [](U u, Options& o) { return set_size(u.value, o.width); }},
    {.letters = "H", .ini_key = "Height", .kind = K::Value, .usage = "+Hn", .help = "image height (default 240)",
     .set = [](U u, Options& o) { return set_size(u.value, o.height); }},
    {.letters = "WT", .ini_key = "Work_Threads", .long_name = "--threads", .kind = K::Value,
     .usage = "+WTn, --threads n", .help = "worker threads (default: all cores)", .long_error = "needs a count 1..1024",
     .set = [](U u, Options& o) { return set_count(u.value, 1, 1024, "expected a thread count 1..1024", o.threads); }},
    {.letters = "A", .ini_key = "Antialias_Threshold", .ini_flag = "Antialias", .kind = K::FlagValue,
     .usage = "+A[t], -A", .help = "antialiasing on with threshold t (0.3), or off", .set = set_antialias},
    {.letters = "R", .ini_key = "Antialias_Depth", .kind = K::Value, .usage = "+Rn",
     .help = "antialiasing depth 1..9 (3)",
     .set = [](U u, Options& o) {
         return set_count(u.value, 1, 9, "expected an antialiasing depth 1..9", o.antialias_depth);
     }},
    {.letters = "J", .ini_key = "Jitter_Amount", .ini_flag = "Jitter", .kind = K::FlagValue, .usage = "+J[n], -J",
     .help = "antialiasing jitter (1), or none", .set = set_jitter},
    {.letters = "AG", .ini_key = "Antialias_Gamma", .kind = K::Value, .usage = "+AGn",
     .help = "antialiasing comparison gamma (2.5)", .set = set_antialias_gamma},
    {.letters = "AM", .ini_key = "Sampling_Method", .kind = K::Value, .usage = "+AMn",
     .help = "antialiasing method: 1 non-recursive (default), 2 recursive (3 is 2)", .set = set_sampling_method},
    {.letters = "L", .ini_key = "Library_Path", .kind = K::Value, .usage = "+Lpath",
     .help = "add an #include search folder",
     .set = [](U u, Options& o) { return add_path(u.value, "expected a library folder", o.library_paths); }},
    {.ini_key = "File_Gamma", .kind = K::Value, .usage = "File_Gamma=G",
     .help = "PNG encoding gamma: sRGB (default) or a number (1.0: linear)",
     .set = [](U u, Options& o) { return set_gamma(u.value, o.file_gamma); }},
    {.ini_key = "Display_Gamma", .kind = K::Value, .usage = "Display_Gamma=G",
     .help = "display gamma (sRGB); scenes without gamma handling write HDR with it",
     .set = [](U u, Options& o) { return set_gamma(u.value, o.display_gamma); }},
    {.ini_key = "Declare", .kind = K::Value, .usage = "Declare=N=V", .help = "define the float N before parsing",
     .set = set_declare},
    {.letters = "D", .ini_flag = "Display", .kind = K::Flag, .usage = "+D, -D", .help = "accepted as in POV-Ray",
     .set = set_display},
    {.letters = "V", .ini_flag = "Verbose", .kind = K::Flag, .usage = "+V, -V",
     .help = "a summary line when done, or none", .set = set_verbose},
    {.letters = "RFI", .ini_flag = "Radiosity_From_File", .kind = K::None, .usage = "+RFI",
     .help = "start the irradiance cache from the radiosity file", .set = set_sign<&Options::radiosity_load>},
    {.letters = "RFO", .ini_flag = "Radiosity_To_File", .kind = K::None, .usage = "+RFO",
     .help = "save the irradiance cache to the radiosity file", .set = set_sign<&Options::radiosity_save>},
    {.letters = "RF", .ini_key = "Radiosity_File_Name", .kind = K::Value, .usage = "+RF<file>",
     .help = "the radiosity file (default: the scene's name, .rca)",
     .set = [](U u, Options& o) { return set_path(u.value, "expected a radiosity file name", o.radiosity_file); }},
    {.long_name = "--check", .kind = K::None, .usage = "--check",
     .help = "parse and describe the scene, render nothing", .set = set_sign<&Options::check_only>},
    {.long_name = "--gi", .kind = K::Value, .usage = "--gi=cache|reference|off",
     .help = "how indirect light is computed (default: cache with a radiosity block)", .set = set_gi},
    {.long_name = "--gi-rays", .kind = K::Value, .usage = "--gi-rays N",
     .help = "reference mode: paths per pixel (default 256)",
     .set = [](U u, Options& o) { return set_count(u.value, 1, 1000000, "needs a count 1..1000000", o.gi_rays); }},
    {.long_name = "--gi-light-picks", .kind = K::Value, .usage = "--gi-light-picks N",
     .help = "lights tested with a shadow ray at each hit of a gather ray's path, picked\n"
             "by their unshadowed light (default 1; 0 tests every light)",
     .set = [](U u, Options& o) { return set_count(u.value, 0, 64, "needs a count 0..64", o.gi_light_picks); }},
    {.long_name = "--gi-guide", .kind = K::Value, .usage = "--gi-guide=on|off",
     .help = "reference mode: guide every bounce towards where a pilot pass found the\n"
             "light coming from (default on; off samples the cosine alone)",
     .set = [](U u, Options& o) { return set_on_off(u, o.gi_guide); }},
    {.long_name = "--gi-area-lights", .kind = K::Value, .usage = "--gi-area-lights=fine|grid",
     .help = "reference mode: the camera hits' jittered area lights sampled on a fine grid\n"
             "that converges with the paths (default), or on POV-Ray's grid with the cache\n"
             "mode's jitter, so that the reference converges the cache mode's own image",
     .set = set_gi_area_lights},
    {.long_name = "--gi-path-seed", .kind = K::Value, .usage = "--gi-path-seed N",
     .help = "reference mode: another sample pattern for the paths alone, the rest drawn\n"
             "as --seed draws it (default: --seed's)",
     .set = [](U u, Options& o) {
         std::uint64_t seed = 0;
         if (auto why = set_seed(u.value, seed)) return why;
         o.gi_path_seed = seed;
         return Why{};
     }},
    {.long_name = "--seed", .kind = K::Value, .usage = "--seed N",
     .help = "another sample pattern for every stochastic part (reference paths, cache\n"
             "gathers, jitter, photons); the same N, the same image (default 0)",
     .set = [](U u, Options& o) { return set_seed(u.value, o.seed); }},
    {.long_name = "--gi-gradients", .kind = K::Value, .usage = "--gi-gradients=on|off",
     .help = "cache mode: irradiance gradients (default on; off is POV-Ray 3.7's cache)", .set = set_gi_gradients},
    {.long_name = "--gi-gradient-cap", .kind = K::Value, .usage = "--gi-gradient-cap=on|off",
     .help = "cache mode, with gradients: a record's radius at most E/|grad E|\n"
             "(Krivanek et al. 2006; default on; POV-Ray 3.7 has no such cap)",
     .set = [](U u, Options& o) { return set_on_off(u, o.gi_gradient_cap); }},
    {.long_name = "--gi-neighbour-clamp", .kind = K::Value, .usage = "--gi-neighbour-clamp=on|off",
     .help = "cache mode: radii clamped by neighbours' R_j + |p - p_j| (Krivanek et al.\n"
             "2006; default on; POV-Ray 3.7 has no such clamp)",
     .set = [](U u, Options& o) { return set_on_off(u, o.gi_neighbour_clamp); }},
    {.long_name = "--gi-spacing", .kind = K::Value, .usage = "--gi-spacing=harmonic|hessian",
     .help = "cache mode: a record's radius from the harmonic mean distance of its hits\n"
             "(as POV-Ray 3.7) or, with gradients, from the irradiance Hessian (Schwarzhaupt,\n"
             "Jensen and Jarosz 2012; the default)",
     .set = set_gi_spacing},
    {.long_name = "--gi-adaptive", .kind = K::Value, .usage = "--gi-adaptive=on|off",
     .help = "cache mode: adaptive hemisphere sampling, a tenth of each gather's rays\n"
             "sent into the cells whose neighbours differ most (Ward's ambient\n"
             "super-sampling, as Radiance's -as); off by default since the\n"
             "grid became multi-jittered: it then has as little error or less",
     .set = [](U u, Options& o) { return set_on_off(u, o.gi_adaptive); }},
    {.long_name = "--gi-lookup-sampling", .kind = K::Value, .usage = "--gi-lookup-sampling K",
     .help = "cache mode: at gather rays' hits, one lookup in K (every K-th ray of a\n"
             "gather); the others take a coarse estimate from a grid of the cache's\n"
             "records, which the looked-up hits correct K-fold (a control variate, so\n"
             "unbiased over a gather's rays). Default 4; 1: every hit looks up, as POV-Ray",
     .set = [](U u, Options& o) {
         return set_count(u.value, 1, 64, "needs a count 1..64", o.gi_lookup_sampling);
     }},
    {.long_name = "--gi-reuse-floor", .kind = K::Value, .usage = "--gi-reuse-floor=geometry|screen",
     .help = "cache mode, with gradients: near geometry closer than minimum_reuse, a\n"
             "record's radius down to half its harmonic mean distance, not below a pixel\n"
             "(geometry, the default), or POV-Ray 3.7's minimum_reuse everywhere (screen)",
     .set = set_gi_reuse_floor},
    {.long_name = "--gi-carry", .kind = K::Value, .usage = "--gi-carry=all|still|off",
     .help = "animation: carry the irradiance cache from frame to frame, every record\n"
             "(all) or those no changed object covers 1 % of the hemisphere of (still)",
     .set = set_gi_carry},
    {.long_name = "--no-pretrace", .kind = K::None, .usage = "--no-pretrace",
     .help = "cache mode: skip the pretrace passes", .set = set_no_pretrace},
    {.long_name = "--gi-record-pass", .kind = K::Value, .usage = "--gi-record-pass=on|off",
     .help = "cache mode: after the pretrace, the final pass's first rays make its records\n"
             "first, so every pixel sees them (default on; POV-Ray 3.7 makes them as it goes)",
     .set = [](U u, Options& o) { return set_on_off(u, o.gi_record_pass); }},
    {.long_name = "--gi-pretrace-bound", .kind = K::Value, .usage = "--gi-pretrace-bound=final|pov",
     .help = "cache mode, with the record passes and gradients: the pretrace's error\n"
             "bound, error_bound x min(1, low_error_factor / 0.5), the final pass's at\n"
             "POV-Ray's default factor (final, the default: the record passes fill what a\n"
             "sparser pretrace leaves, for less error in the same time), or POV-Ray 3.7's\n"
             "error_bound x low_error_factor (pov)",
     .set = set_gi_pretrace_bound},
    {.long_name = "--aov", .kind = K::TwoValues, .usage = "--aov irradiance|records FILE",
     .help = "also write the indirect irradiance alone (irradiance), or the image\n"
             "with each cache record (first bounce) as a red dot (records)",
     .set = set_aov},
    {.long_name = "--stats", .kind = K::Value, .usage = "--stats file.json", .help = "write timings and ray counts",
     .set = [](U u, Options& o) { return set_path(u.value, "needs a file name", o.stats); }},
    {.long_name = "--read-path", .kind = K::Value, .usage = "--read-path DIR", .help = "a folder the scene may read files from (#include, #fopen, fonts,\nimages, +RFI)",
     .set = [](U u, Options& o) { return add_path(u.value, "needs a folder", o.read_paths); }},
    {.long_name = "--strict-reads", .kind = K::None, .usage = "--strict-reads",
     .help = "read only from the scene's folder, the include path and --read-path,\nnot from what Debian's povray.conf permits ($HOME, /tmp, ...)",
     .set = set_sign<&Options::strict_reads>},
    {.long_name = "--write-path", .kind = K::Value, .usage = "--write-path DIR",
     .help = "a folder #fopen may write into",
     .set = [](U u, Options& o) { return add_path(u.value, "needs a folder", o.write_paths); }},
    {.long_name = "--allow-file-writes", .kind = K::None, .usage = "--allow-file-writes",
     .help = "#write really writes (inside the --write-path folders)", .set = set_sign<&Options::allow_file_writes>},
    {.long_name = "--max-loop-iterations", .kind = K::Value, .usage = "--max-loop-iterations N",
     .help = "raise the parser's guard rails: loop iterations,",
     .set = [](U u, Options& o) { return set_limit(u.value, o.max_loop_iterations); }},
    {.long_name = "--max-macro-depth", .kind = K::Value, .usage = "--max-macro-depth N", .help = "  macro nesting,",
     .set = [](U u, Options& o) { return set_limit(u.value, o.max_macro_depth); }},
    {.long_name = "--max-include-depth", .kind = K::Value, .usage = "--max-include-depth N",
     .help = "  #include nesting,", .set = [](U u, Options& o) { return set_limit(u.value, o.max_include_depth); }},
    {.long_name = "--max-array-size", .kind = K::Value, .usage = "--max-array-size N", .help = "  array elements,",
     .set = [](U u, Options& o) { return set_limit(u.value, o.max_array_size); }},
    {.long_name = "--max-string-length", .kind = K::Value, .usage = "--max-string-length N", .help = "  string length,",
     .set = [](U u, Options& o) { return set_limit(u.value, o.max_string_length); }},
    {.long_name = "--max-memory-file", .kind = K::Value, .usage = "--max-memory-file BYTES",
     .help = "  a memory file's bytes", .set = [](U u, Options& o) { return set_limit(u.value, o.max_memory_file); }},
    {.long_name = "--max-objects", .kind = K::Value, .usage = "--max-objects N",
     .help = "  objects created,", .set = [](U u, Options& o) { return set_limit(u.value, o.max_objects); }},
    {.long_name = "--max-memory", .kind = K::Value, .usage = "--max-memory MB",
     .help = "  memory the parse may take (MB)",
     .set = [](U u, Options& o) { return set_limit(u.value, o.max_memory); }},
    {.long_name = "--help", .short_name = "-h", .kind = K::None, .usage = "--help, -h", .help = "this text",
     .set = set_sign<&Options::show_help>},
    {.long_name = "--version", .kind = K::None, .usage = "--version", .help = "the version",
     .set = set_sign<&Options::show_version>},
};

}  // namespace

bool parse_int(std::string_view text, int& out) {
    if (text.empty()) return false;
    const char* end = text.data() + text.size();
    auto [ptr, ec] = std::from_chars(text.data(), end, out);
    return ec == std::errc() && ptr == end;
}

bool parse_double(std::string_view text, double& out) {
    if (text.empty()) return false;
    const std::string s(text);
    char* end = nullptr;
    out = std::strtod(s.c_str(), &end);
    return end == s.c_str() + s.size() && std::isfinite(out);
}

std::optional<bool> parse_ini_bool(std::string_view text) {
    for (const char* yes : {"on", "true", "yes", "1"})
        if (equals_ci(text, yes)) return true;
    for (const char* no : {"off", "false", "no", "0"})
        if (equals_ci(text, no)) return false;
    return std::nullopt;
}

bool starts_with_ci(std::string_view s, std::string_view prefix) {
    if (s.size() < prefix.size()) return false;
    for (std::size_t i = 0; i < prefix.size(); ++i)
        if (std::toupper(static_cast<unsigned char>(s[i])) != std::toupper(static_cast<unsigned char>(prefix[i])))
            return false;
    return true;
}

bool equals_ci(std::string_view a, std::string_view b) {
    return a.size() == b.size() && starts_with_ci(a, b);
}

std::span<const OptionSpec> option_table() {
    // POV-Ray's switches and keys (kOptions up to its first long-only entry), the frame table's, then the long
    // options; built once.
    static const std::vector<OptionSpec> all = [] {
        const auto is_long_only = [](const OptionSpec& spec) {
            return spec.letters.empty() && spec.ini_key.empty() && spec.ini_flag.empty();
        };
        const auto first_long = std::find_if(std::begin(kOptions), std::end(kOptions), is_long_only);
        std::vector<OptionSpec> v(std::begin(kOptions), first_long);
        const std::span<const OptionSpec> frames = frame_option_table();
        v.insert(v.end(), frames.begin(), frames.end());
        v.insert(v.end(), first_long, std::end(kOptions));
        return v;
    }();
    return all;
}

const OptionSpec* find_switch(std::string_view body) {
    const OptionSpec* best = nullptr;
    for (const OptionSpec& spec : option_table()) {
        if (spec.letters.empty() || !starts_with_ci(body, spec.letters)) continue;
        if (spec.kind == ValueKind::None && body.size() != spec.letters.size()) continue;
        if (!best || spec.letters.size() > best->letters.size()) best = &spec;
    }
    return best;
}

const OptionSpec* find_long_option(std::string_view name) {
    for (const OptionSpec& spec : option_table())
        if (!name.empty() && (spec.long_name == name || spec.short_name == name)) return &spec;
    return nullptr;
}

const OptionSpec* find_ini_key(std::string_view key, bool& is_flag_key) {
    for (const OptionSpec& spec : option_table()) {
        if (!spec.ini_key.empty() && equals_ci(key, spec.ini_key)) {
            is_flag_key = false;
            return &spec;
        }
        if (!spec.ini_flag.empty() && equals_ci(key, spec.ini_flag)) {
            is_flag_key = true;
            return &spec;
        }
    }
    return nullptr;
}

}  // namespace wardray::app
