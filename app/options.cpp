// Options: POV-Ray's `+X`/`-X` switches, `Key=Value` pairs and wardray's `--long` options.
#include "app/options.h"

#include <cctype>
#include <charconv>
#include <cstdlib>

namespace wardray::app {

namespace {

bool parse_int(const std::string& text, int& out) {
    if (text.empty()) return false;
    const char* end = text.data() + text.size();
    auto [ptr, ec] = std::from_chars(text.data(), end, out);
    return ec == std::errc() && ptr == end;
}

bool parse_double(const std::string& text, double& out) {
    if (text.empty()) return false;
    char* end = nullptr;
    out = std::strtod(text.c_str(), &end);
    return end == text.c_str() + text.size() && std::isfinite(out);
}

bool starts_with_ci(const std::string& s, const std::string& prefix) {
    if (s.size() < prefix.size()) return false;
    for (std::size_t i = 0; i < prefix.size(); ++i)
        if (std::toupper(static_cast<unsigned char>(s[i])) != std::toupper(static_cast<unsigned char>(prefix[i])))
            return false;
    return true;
}

// POV-Ray's gamma INI values: a positive number (1.0 is no gamma) or sRGB.
bool parse_gamma(const std::string& text, GammaCurve& out) {
    double g = 0.0;
    if (parse_double(text, g) && g > 0.0) {
        out = GammaCurve::power_law(g);
        return true;
    }
    if (text.size() == 4 && starts_with_ci(text, "srgb")) {
        out = GammaCurve::srgb();
        return true;
    }
    return false;
}

// Image sizes beyond this are refused before any memory is asked for (64k x 64k is 48 GiB of film).
constexpr int kMaxImageSide = 65536;

// Parses one POV-Ray switch body (after the + or -), e.g. "W320", "WT2", "A0.3", "FN", "Iscene.pov".
std::optional<UsageError> apply_pov_switch(bool plus, const std::string& body, Options& o) {
    auto bad = [&](const std::string& why) {
        return UsageError{"invalid switch '" + std::string(plus ? "+" : "-") + body + "': " + why};
    };
    if (body.empty()) return bad("empty switch");
    if (starts_with_ci(body, "AG")) {
        double g = 0.0;
        if (!parse_double(body.substr(2), g) || g <= 0.0) return bad("expected a positive antialiasing gamma");
        o.antialias_gamma = g;
        return std::nullopt;
    }
    if (starts_with_ci(body, "AM")) {
        // Only method 1 (adaptive, non-recursive) is implemented; method 2 is refused rather than faked.
        if (body.substr(2) != "1") return bad("only sampling method 1 (+AM1) is supported so far");
        return std::nullopt;
    }
    // POV-Ray's radiosity file switches: +RFI loads, +RFO saves, +RF<name> names the file.
    if (starts_with_ci(body, "RFI") && body.size() == 3) {
        o.radiosity_load = plus;
        return std::nullopt;
    }
    if (starts_with_ci(body, "RFO") && body.size() == 3) {
        o.radiosity_save = plus;
        return std::nullopt;
    }
    if (starts_with_ci(body, "RF")) {
        if (body.size() == 2) return bad("expected a radiosity file name");
        o.radiosity_file = body.substr(2);
        return std::nullopt;
    }
    if (starts_with_ci(body, "WT")) {
        int n = 0;
        if (!parse_int(body.substr(2), n) || n < 1 || n > 1024) return bad("expected a thread count 1..1024");
        o.threads = n;
        return std::nullopt;
    }
    const char key = static_cast<char>(std::toupper(static_cast<unsigned char>(body[0])));
    const std::string value = body.substr(1);
    switch (key) {
        case 'W':
        case 'H': {
            int n = 0;
            if (!parse_int(value, n) || n < 1 || n > kMaxImageSide)
                return bad("expected a size in pixels, 1.." + std::to_string(kMaxImageSide));
            (key == 'W' ? o.width : o.height) = n;
            return std::nullopt;
        }
        case 'I':
            if (value.empty()) return bad("expected a scene file name");
            o.scene = value;
            return std::nullopt;
        case 'O':
            if (value.empty()) return bad("expected an output file name");
            o.output = value;
            return std::nullopt;
        case 'L':
            if (value.empty()) return bad("expected a library folder");
            o.library_paths.emplace_back(value);
            return std::nullopt;
        case 'F':
            if (!plus && value.empty()) {
                o.write_output = false;
                return std::nullopt;
            }
            o.write_output = true;
            if (value.empty()) return std::nullopt;
            switch (std::toupper(static_cast<unsigned char>(value[0]))) {
                case 'N': o.format = render::ImageFormat::Png; break;
                case 'E': o.format = render::ImageFormat::Exr; break;
                case 'H': o.format = render::ImageFormat::Hdr; break;
                default: return bad("supported formats are +FN (PNG), +FE (OpenEXR) and +FH (Radiance HDR)");
            }
            return std::nullopt;
        case 'A':
            o.antialias = plus;
            if (!value.empty()) {
                double t = 0.0;
                if (!parse_double(value, t) || t < 0.0) return bad("expected a non-negative threshold");
                o.antialias_threshold = t;
                o.antialias = true;
            }
            return std::nullopt;
        case 'R': {
            int n = 0;
            if (!parse_int(value, n) || n < 1 || n > 9) return bad("expected an antialiasing depth 1..9");
            o.antialias_depth = n;
            return std::nullopt;
        }
        case 'J': {
            double j = 1.0;
            if (!plus) j = 0.0;
            else if (!value.empty() && (!parse_double(value, j) || j < 0.0)) return bad("expected a jitter amount >= 0");
            o.jitter = j;
            return std::nullopt;
        }
        case 'D':  // display: there is no preview window, so both are accepted and ignored
            if (!value.empty()) return bad("unknown display option");
            return std::nullopt;
        case 'V':
            if (!value.empty()) return bad("unknown verbosity option");
            o.verbose = plus;
            return std::nullopt;
        default:
            return bad("unknown switch (see --help)");
    }
}

// Applies a long option; `next` yields the following argument for options that take one.
template <typename Next>
std::optional<UsageError> apply_long_option(const std::string& arg, Options& o, Next&& next) {
    std::string name = arg;
    std::optional<std::string> inline_value;
    if (const auto eq = arg.find('='); eq != std::string::npos) {
        name = arg.substr(0, eq);
        inline_value = arg.substr(eq + 1);
    }
    auto value = [&]() -> std::optional<std::string> { return inline_value ? inline_value : next(); };
    if (name == "--help" || name == "-h") {
        o.show_help = true;
    } else if (name == "--version") {
        o.show_version = true;
    } else if (name == "--check") {
        o.check_only = true;
    } else if (name == "--output" || name == "-o") {
        const auto v = value();
        if (!v || v->empty()) return UsageError{name + " needs a file name"};
        o.output = *v;
    } else if (name == "--threads") {
        const auto v = value();
        int n = 0;
        if (!v || !parse_int(*v, n) || n < 1 || n > 1024) return UsageError{"--threads needs a count 1..1024"};
        o.threads = n;
    } else if (name == "--gi") {
        const auto v = value();
        if (v == "cache") o.gi = lighting::GiMode::Cache;
        else if (v == "reference") o.gi = lighting::GiMode::Reference;
        else if (v == "off") o.gi = lighting::GiMode::Off;
        else return UsageError{"--gi must be cache, reference or off"};
    } else if (name == "--gi-rays") {
        const auto v = value();
        int n = 0;
        if (!v || !parse_int(*v, n) || n < 1 || n > 1000000) return UsageError{"--gi-rays needs a count 1..1000000"};
        o.gi_rays = n;
    } else if (name == "--gi-gradients") {
        const auto v = value();
        if (v == "on") o.gi_gradients = true;
        else if (v == "off") o.gi_gradients = false;
        else return UsageError{"--gi-gradients must be on or off"};
    } else if (name == "--aov") {
        const auto kind = value();
        const auto file = next();
        if (!kind || (*kind != "irradiance" && *kind != "records") || !file || file->empty())
            return UsageError{"--aov needs a kind (irradiance or records) and a file name"};
        (*kind == "irradiance" ? o.aov_irradiance : o.aov_records) = *file;
    } else if (name == "--no-pretrace") {
        o.pretrace = false;
    } else if (name == "--read-path" || name == "--write-path") {
        const auto v = value();
        if (!v || v->empty()) return UsageError{name + " needs a folder"};
        (name == "--read-path" ? o.read_paths : o.write_paths).emplace_back(*v);
    } else if (name == "--allow-file-writes") {
        o.allow_file_writes = true;
    } else if (auto* limit = name == "--max-loop-iterations" ? &o.max_loop_iterations
                             : name == "--max-macro-depth"   ? &o.max_macro_depth
                             : name == "--max-include-depth" ? &o.max_include_depth
                             : name == "--max-array-size"    ? &o.max_array_size
                             : name == "--max-string-length" ? &o.max_string_length
                             : name == "--max-memory-file"   ? &o.max_memory_file
                                                             : nullptr) {
        const auto v = value();
        std::uint64_t n = 0;
        const char* end = v ? v->data() + v->size() : nullptr;
        if (!v || v->empty() || std::from_chars(v->data(), end, n).ptr != end || n == 0)
            return UsageError{name + " needs a positive whole number"};
        *limit = n;
    } else if (name == "--stats") {
        const auto v = value();
        if (!v || v->empty()) return UsageError{"--stats needs a file name"};
        o.stats = *v;
    } else {
        return UsageError{"unknown option '" + name + "' (see --help)"};
    }
    return std::nullopt;
}

}  // namespace

std::variant<Options, UsageError> parse_command_line(const std::vector<std::string>& args) {
    Options o;
    bool have_scene = false;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& arg = args[i];
        auto next = [&]() -> std::optional<std::string> {
            if (i + 1 < args.size()) return args[++i];
            return std::nullopt;
        };
        std::optional<UsageError> error;
        if (arg.rfind("--", 0) == 0 || arg == "-o" || arg == "-h") {
            error = apply_long_option(arg, o, next);
        } else if (starts_with_ci(arg, "Declare=")) {
            // POV-Ray's Declare=NAME=VALUE defines a float before the scene is read.
            const std::string rest = arg.substr(8);
            const auto eq = rest.find('=');
            double v = 0.0;
            if (eq == std::string::npos || eq == 0 || !parse_double(rest.substr(eq + 1), v))
                error = UsageError{"invalid '" + arg + "': expected Declare=NAME=NUMBER"};
            else
                o.declares.emplace_back(rest.substr(0, eq), v);
        } else if (starts_with_ci(arg, "File_Gamma=") || starts_with_ci(arg, "Display_Gamma=")) {
            // POV-Ray's File_Gamma=G and Display_Gamma=G INI settings, given on the command line.
            const auto eq = arg.find('=');
            GammaCurve& target = arg[0] == 'F' || arg[0] == 'f' ? o.file_gamma : o.display_gamma;
            if (!parse_gamma(arg.substr(eq + 1), target))
                error = UsageError{"invalid '" + arg + "': expected a positive gamma or sRGB"};
        } else if (arg.size() >= 2 && (arg[0] == '+' || arg[0] == '-')) {
            error = apply_pov_switch(arg[0] == '+', arg.substr(1), o);
            if (!error && (arg[1] == 'I' || arg[1] == 'i')) have_scene = true;
        } else if (!arg.empty()) {
            if (have_scene) return UsageError{"more than one scene given ('" + arg + "')"};
            o.scene = arg;
            have_scene = true;
        } else {
            error = UsageError{"empty argument"};
        }
        if (error) return *error;
    }
    return o;
}

std::string usage_text() {
    return "usage: wardray [scene.pov | +Iscene.pov] [options]\n"
           "       wardray diff IMAGE REFERENCE [--json] [-o DIFFERENCE.png]\n"
           "  +Ofile, -o file   output image (default: the scene's name, .png)\n"
           "  +FN +FE +FH       PNG (sRGB), OpenEXR or Radiance HDR (linear); -F writes no file\n"
           "  +Wn +Hn           image size (default 320x240)\n"
           "  +WTn, --threads n worker threads (default: all cores)\n"
           "  +A[t] -A          antialiasing on with threshold t (0.3), or off; +Rn depth, +J[n] -J jitter,\n"
           "                    +AGn comparison gamma (2.5), +AM1 sampling method\n"
           "  +Lpath            add an #include search folder\n"
           "  Declare=N=V       define the float N before parsing\n"
           "  File_Gamma=G      PNG encoding gamma: sRGB (default) or a number (1.0: linear)\n"
           "  Display_Gamma=G   display gamma (sRGB); 3.6 scenes without assumed_gamma write HDR with it\n"
           "  +D -D +V -V       accepted as in POV-Ray\n"
           "  --check           parse and describe the scene, render nothing\n"
           "  --gi=cache|reference|off  how indirect light is computed (default: cache with a radiosity block)\n"
           "  --gi-rays N               reference mode: paths per pixel (default 256)\n"
           "  --gi-gradients=on|off     cache mode: irradiance gradients (default on; off is POV-Ray 3.7's cache)\n"
           "  --no-pretrace             cache mode: skip the pretrace passes\n"
           "  --aov irradiance FILE     also write the indirect irradiance alone\n"
           "  --aov records FILE        also write the image with each cache record (first bounce) as a red dot\n"
           "  +RFI +RFO +RF<file>       load / save the irradiance cache (default file: the scene's name, .rca)\n"
           "  --stats file.json write timings and ray counts\n"
           "  --read-path DIR, --write-path DIR, --allow-file-writes   where #fopen may read and write\n"
           "  --max-loop-iterations N, --max-macro-depth N, --max-include-depth N,\n"
           "  --max-array-size N, --max-string-length N, --max-memory-file BYTES\n"
           "                    raise the parser's guard rails\n"
           "  --help, --version\n"
           "With no scene, renders the bundled default scene.\n";
}

}  // namespace wardray::app
