// The option table: one entry per option; the command line, INI settings and --help all read it.
#include "app/option_table.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>

namespace wardray::app {

namespace {

using Why = std::optional<std::string>;

// Image sizes beyond this are refused before any memory is asked for (64k x 64k is 48 GiB of film).
constexpr int kMaxImageSide = 65536;

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

using K = ValueKind;

// POV-Ray's switches (with their INI keys from POV-Ray 3.7's INI table), then wardray's own long options.
constexpr OptionSpec kOptions[] = {
    {"I", "Input_File_Name", "", "", "", K::Value, "+Iscene.pov",
     "the scene (or the first argument that is not an option)", "", [](const OptionUse& u, Options& o) -> Why {
         if (u.value.empty()) return "expected a scene file name";
         o.scene = to_path(u.value);
         return std::nullopt;
     }},
    {"O", "Output_File_Name", "", "--output", "-o", K::Value, "+Ofile, -o file",
     "output image (default: the scene's name, .png)", "needs a file name",
     [](const OptionUse& u, Options& o) { return set_path(u.value, "expected an output file name", o.output); }},
    {"F", "Output_File_Type", "Output_To_File", "", "", K::FlagValue, "+FN +FE +FH, -F",
     "PNG (sRGB), OpenEXR or Radiance HDR (linear); -F writes no file", "", set_output_type},
    {"W", "Width", "", "", "", K::Value, "+Wn", "image width (default 320)", "",
     [](const OptionUse& u, Options& o) { return set_size(u.value, o.width); }},
    {"H", "Height", "", "", "", K::Value, "+Hn", "image height (default 240)", "",
     [](const OptionUse& u, Options& o) { return set_size(u.value, o.height); }},
    {"WT", "Work_Threads", "", "--threads", "", K::Value, "+WTn, --threads n", "worker threads (default: all cores)",
     "needs a count 1..1024",
     [](const OptionUse& u, Options& o) {
         return set_count(u.value, 1, 1024, "expected a thread count 1..1024", o.threads);
     }},
    {"A", "Antialias_Threshold", "Antialias", "", "", K::FlagValue, "+A[t], -A",
     "antialiasing on with threshold t (0.3), or off", "", set_antialias},
    {"R", "Antialias_Depth", "", "", "", K::Value, "+Rn", "antialiasing depth 1..9 (3)", "",
     [](const OptionUse& u, Options& o) {
         return set_count(u.value, 1, 9, "expected an antialiasing depth 1..9", o.antialias_depth);
     }},
    {"J", "Jitter_Amount", "Jitter", "", "", K::FlagValue, "+J[n], -J", "antialiasing jitter (1), or none", "",
     set_jitter},
    {"AG", "Antialias_Gamma", "", "", "", K::Value, "+AGn", "antialiasing comparison gamma (2.5)", "",
     [](const OptionUse& u, Options& o) -> Why {
         double g = 0.0;
         if (!parse_double(u.value, g) || g <= 0.0) return "expected a positive antialiasing gamma";
         o.antialias_gamma = g;
         return std::nullopt;
     }},
    // Only method 1 (adaptive, non-recursive) is implemented; method 2 is refused rather than faked.
    {"AM", "Sampling_Method", "", "", "", K::Value, "+AM1", "antialiasing sampling method (1, the only one)", "",
     [](const OptionUse& u, Options& o) -> Why {
         if (u.value != "1") return "only sampling method 1 (+AM1) is supported so far";
         return std::nullopt;
     }},
    {"L", "Library_Path", "", "", "", K::Value, "+Lpath", "add an #include search folder", "",
     [](const OptionUse& u, Options& o) { return add_path(u.value, "expected a library folder", o.library_paths); }},
    {"", "Declare", "", "", "", K::Value, "Declare=N=V", "define the float N before parsing", "", set_declare},
    // There is no preview window, so +D and -D are accepted and ignored.
    {"D", "", "Display", "", "", K::Flag, "+D, -D", "accepted as in POV-Ray", "",
     [](const OptionUse& u, Options& o) -> Why {
         if (!u.value.empty()) return "unknown display option";
         return std::nullopt;
     }},
    {"V", "", "Verbose", "", "", K::Flag, "+V, -V", "a summary line when done, or none", "",
     [](const OptionUse& u, Options& o) -> Why {
         if (!u.value.empty()) return "unknown verbosity option";
         o.verbose = u.sign.value_or(true);
         return std::nullopt;
     }},
    {"RFI", "", "Radiosity_From_File", "", "", K::None, "+RFI",
     "start the irradiance cache from the radiosity file", "", set_sign<&Options::radiosity_load>},
    {"RFO", "", "Radiosity_To_File", "", "", K::None, "+RFO", "save the irradiance cache to the radiosity file", "",
     set_sign<&Options::radiosity_save>},
    {"RF", "Radiosity_File_Name", "", "", "", K::Value, "+RF<file>",
     "the radiosity file (default: the scene's name, .rca)", "",
     [](const OptionUse& u, Options& o) {
         return set_path(u.value, "expected a radiosity file name", o.radiosity_file);
     }},
    {"", "", "", "--check", "", K::None, "--check", "parse and describe the scene, render nothing", "",
     set_sign<&Options::check_only>},
    {"", "", "", "--gi", "", K::Value, "--gi=cache|reference|off",
     "how indirect light is computed (default: cache with a radiosity block)", "", set_gi},
    {"", "", "", "--gi-rays", "", K::Value, "--gi-rays N", "reference mode: paths per pixel (default 256)", "",
     [](const OptionUse& u, Options& o) {
         return set_count(u.value, 1, 1000000, "needs a count 1..1000000", o.gi_rays);
     }},
    {"", "", "", "--gi-gradients", "", K::Value, "--gi-gradients=on|off",
     "cache mode: irradiance gradients (default on; off is POV-Ray 3.7's cache)", "",
     [](const OptionUse& u, Options& o) -> Why {
         if (u.value != "on" && u.value != "off") return "must be on or off";
         o.gi_gradients = u.value == "on";
         return std::nullopt;
     }},
    {"", "", "", "--no-pretrace", "", K::None, "--no-pretrace", "cache mode: skip the pretrace passes", "",
     [](const OptionUse&, Options& o) -> Why {
         o.pretrace = false;
         return std::nullopt;
     }},
    {"", "", "", "--aov", "", K::TwoValues, "--aov irradiance|records FILE",
     "also write the indirect irradiance alone (irradiance), or the image\n"
     "with each cache record (first bounce) as a red dot (records)", "", set_aov},
    {"", "", "", "--stats", "", K::Value, "--stats file.json", "write timings and ray counts", "",
     [](const OptionUse& u, Options& o) { return set_path(u.value, "needs a file name", o.stats); }},
    {"", "", "", "--read-path", "", K::Value, "--read-path DIR", "a folder #fopen may read from", "",
     [](const OptionUse& u, Options& o) { return add_path(u.value, "needs a folder", o.read_paths); }},
    {"", "", "", "--write-path", "", K::Value, "--write-path DIR", "a folder #fopen may write into", "",
     [](const OptionUse& u, Options& o) { return add_path(u.value, "needs a folder", o.write_paths); }},
    {"", "", "", "--allow-file-writes", "", K::None, "--allow-file-writes",
     "#write really writes (inside the --write-path folders)", "", set_sign<&Options::allow_file_writes>},
    {"", "", "", "--max-loop-iterations", "", K::Value, "--max-loop-iterations N",
     "raise the parser's guard rails: loop iterations,", "", [](const OptionUse& u, Options& o) { return set_limit(u.value, o.max_loop_iterations); }},
    {"", "", "", "--max-macro-depth", "", K::Value, "--max-macro-depth N", "  macro nesting,", "",
     [](const OptionUse& u, Options& o) { return set_limit(u.value, o.max_macro_depth); }},
    {"", "", "", "--max-include-depth", "", K::Value, "--max-include-depth N", "  #include nesting,", "",
     [](const OptionUse& u, Options& o) { return set_limit(u.value, o.max_include_depth); }},
    {"", "", "", "--max-array-size", "", K::Value, "--max-array-size N", "  array elements,", "",
     [](const OptionUse& u, Options& o) { return set_limit(u.value, o.max_array_size); }},
    {"", "", "", "--max-string-length", "", K::Value, "--max-string-length N", "  string length,", "",
     [](const OptionUse& u, Options& o) { return set_limit(u.value, o.max_string_length); }},
    {"", "", "", "--max-memory-file", "", K::Value, "--max-memory-file BYTES", "  a memory file's bytes", "",
     [](const OptionUse& u, Options& o) { return set_limit(u.value, o.max_memory_file); }},
    {"", "", "", "--help", "-h", K::None, "--help, -h", "this text", "", set_sign<&Options::show_help>},
    {"", "", "", "--version", "", K::None, "--version", "the version", "", set_sign<&Options::show_version>},
};

}  // namespace

std::span<const OptionSpec> option_table() {
    return kOptions;
}

const OptionSpec* find_switch(std::string_view body) {
    const OptionSpec* best = nullptr;
    for (const OptionSpec& spec : kOptions) {
        if (spec.letters.empty() || !starts_with_ci(body, spec.letters)) continue;
        if (spec.kind == ValueKind::None && body.size() != spec.letters.size()) continue;
        if (!best || spec.letters.size() > best->letters.size()) best = &spec;
    }
    return best;
}

const OptionSpec* find_long_option(std::string_view name) {
    for (const OptionSpec& spec : kOptions)
        if (!name.empty() && (spec.long_name == name || spec.short_name == name)) return &spec;
    return nullptr;
}

const OptionSpec* find_ini_key(std::string_view key, bool& is_flag_key) {
    for (const OptionSpec& spec : kOptions) {
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
