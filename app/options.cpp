// Options: the command line, INI settings and --help, all three read from the option table.
#include "app/options.h"

#include <algorithm>
#include <cctype>

#include "app/ini_file.h"
#include "app/option_table.h"

namespace wardray::app {

namespace {

// One POV-Ray switch: `plus` is its sign, `body` what follows the sign ("W320", "WT2", "A0.3", "FN").
std::optional<UsageError> apply_switch(bool plus, std::string_view body, Options& o) {
    std::string shown(1, plus ? '+' : '-');
    shown += body;
    const OptionSpec* spec = find_switch(body);
    if (!spec) return UsageError{"invalid switch '" + shown + "': unknown switch (see --help)"};
    if (auto why = spec->set(OptionUse{plus, body.substr(spec->letters.size()), {}}, o))
        return UsageError{"invalid switch '" + shown + "': " + *why};
    return std::nullopt;
}

// One long option (`--threads 2`, `--gi=off`, `-o file`); `next` yields the following argument when it needs one.
template <typename Next>
std::optional<UsageError> apply_long_option(const std::string& arg, Options& o, Next&& next) {
    std::string name = arg;
    std::optional<std::string> inline_value;
    if (const auto eq = arg.find('='); eq != std::string::npos) {
        name = arg.substr(0, eq);
        inline_value = arg.substr(eq + 1);
    }
    const OptionSpec* spec = find_long_option(name);
    if (!spec) return UsageError{"unknown option '" + name + "' (see --help)"};
    // A missing value is an empty one, which every option that takes a value refuses.
    std::string value, second;
    if (spec->kind != ValueKind::None) value = inline_value ? *inline_value : next().value_or("");
    if (spec->kind == ValueKind::TwoValues) second = next().value_or("");
    if (auto why = spec->set(OptionUse{std::nullopt, value, second}, o))
        return UsageError{name + " " + (spec->long_error.empty() ? *why : std::string(spec->long_error))};
    return std::nullopt;
}

// One INI key's value through its table entry: on/off for a flag key, anything else for a value key.
std::optional<std::string> apply_ini_value(const OptionSpec& spec, bool is_flag_key, std::string_view value,
                                           Options& o) {
    if (is_flag_key) {
        const std::optional<bool> on = parse_ini_bool(value);
        if (!on) return "expected on or off";
        return spec.set(OptionUse{*on, {}, {}}, o);
    }
    if (value.empty()) return "expected a value";
    return spec.set(OptionUse{std::nullopt, value, {}}, o);
}

// The table entry of a command-line argument written as an INI setting (`Declare=N=V`, `File_Gamma=2.2`), or null.
const OptionSpec* ini_argument_spec(const std::string& arg, bool& is_flag_key) {
    const auto eq = arg.find('=');
    if (eq == std::string::npos || eq == 0 || arg[0] == '+' || arg[0] == '-') return nullptr;
    return find_ini_key(std::string_view(arg).substr(0, eq), is_flag_key);
}

// POV-Ray compat: an INI setting may also be written on the command line, as KEY=VALUE.
std::optional<UsageError> apply_ini_argument(const std::string& arg, const OptionSpec& spec, bool is_flag_key,
                                             Options& o) {
    const std::string_view value = std::string_view(arg).substr(arg.find('=') + 1);
    const std::optional<std::string> why =
        is_flag_key ? apply_ini_value(spec, true, value, o) : spec.set(OptionUse{std::nullopt, value, {}}, o);
    if (why) return UsageError{"invalid '" + arg + "': " + *why};
    return std::nullopt;
}

// INI files that name INI files: this deep at most.
constexpr int kMaxIniDepth = 10;

std::optional<UsageError> apply_ini_file(std::string_view argument, Options& o, int depth);

// An INI file's `Key=Value` (empty values change nothing, as in POV-Ray); the reason when it is refused.
std::optional<std::string> apply_ini_key(std::string_view key, std::string_view value, Options& o) {
    bool is_flag_key = false;
    const OptionSpec* spec = find_ini_key(key, is_flag_key);
    if (!spec) return "unknown INI key '" + std::string(key) + "'";
    if (value.empty()) return std::nullopt;
    if (auto why = apply_ini_value(*spec, is_flag_key, value, o))
        return "invalid '" + std::string(key) + "=" + std::string(value) + "': " + *why;
    return std::nullopt;
}

// One line of an INI file; errors and the warnings it adds carry `where` ("scene.ini:3: ").
std::optional<UsageError> apply_ini_line(const IniLine& line, const std::string& where, Options& o, int depth) {
    auto error = [&](const std::string& message) { return UsageError{where + "error: " + message, true}; };
    switch (line.kind) {
        case IniLine::Kind::IniFile:
            return apply_ini_file(line.value, o, depth + 1);
        case IniLine::Kind::Setting:
            if (auto why = apply_ini_key(line.key, line.value, o)) return error(*why);
            return std::nullopt;
        case IniLine::Kind::Switches:
            for (const std::string& word : split_ini_words(line.value)) {
                if (word.size() >= 2 && (word[0] == '+' || word[0] == '-')) {
                    if (auto e = apply_switch(word[0] == '+', std::string_view(word).substr(1), o))
                        return error(e->message);
                } else if (const auto eq = word.find('='); eq != std::string::npos && eq > 0) {
                    if (auto why = apply_ini_key(word.substr(0, eq), word.substr(eq + 1), o)) return error(*why);
                } else {
                    return error("expected a switch (+X or -X) or KEY=VALUE, not '" + word + "'");
                }
            }
            return std::nullopt;
    }
    return std::nullopt;
}

// `scene.ini` or `scene.ini[Section]`: every line that applies, in order, so later settings win.
std::optional<UsageError> apply_ini_file(std::string_view argument, Options& o, int depth) {
    if (depth > kMaxIniDepth)
        return UsageError{std::string(argument) + ": error: INI files name each other more than 10 deep", true};
    auto read = read_ini_file(argument);
    if (const std::string* message = std::get_if<std::string>(&read)) return UsageError{*message, true};
    const IniFile& ini = std::get<IniFile>(read);
    for (const IniLine& line : ini.lines) {
        const std::string where = ini.path.string() + ":" + std::to_string(line.line) + ": ";
        const std::size_t warnings_before = o.warnings.size();
        if (auto error = apply_ini_line(line, where, o, depth)) return error;
        for (std::size_t i = warnings_before; i < o.warnings.size(); ++i)
            if (o.warnings[i].find(": warning: ") == std::string::npos)
                o.warnings[i] = where + "warning: " + o.warnings[i];
    }
    return std::nullopt;
}

}  // namespace

std::variant<Options, UsageError> parse_command_line(const std::vector<std::string>& args) {
    Options o;
    bool scene_argument = false;  // the scene named by a plain argument (once only; +I may replace it)
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& arg = args[i];
        auto next = [&]() -> std::optional<std::string> {
            if (i + 1 < args.size()) return args[++i];
            return std::nullopt;
        };
        std::optional<UsageError> error;
        bool is_flag_key = false;
        const std::size_t warnings_before = o.warnings.size();
        if (arg.rfind("--", 0) == 0 || find_long_option(arg)) {
            error = apply_long_option(arg, o, next);
        } else if (const OptionSpec* spec = ini_argument_spec(arg, is_flag_key)) {
            error = apply_ini_argument(arg, *spec, is_flag_key, o);
        } else if (arg.size() >= 2 && (arg[0] == '+' || arg[0] == '-')) {
            error = apply_switch(arg[0] == '+', std::string_view(arg).substr(1), o);
        } else if (is_ini_argument(arg)) {
            error = apply_ini_file(arg, o, 0);
        } else if (!arg.empty()) {
            // The scene, given once: as the first plain argument or with +I.
            if (scene_argument) return UsageError{"more than one scene given ('" + arg + "')"};
            scene_argument = true;
            o.scene = arg;
        } else {
            error = UsageError{"empty argument"};
        }
        if (error) return *error;
        for (std::size_t w = warnings_before; w < o.warnings.size(); ++w)
            if (o.warnings[w].find(": warning: ") == std::string::npos)
                o.warnings[w] = "wardray: warning: " + o.warnings[w];
    }
    return o;
}

std::optional<UsageError> apply_ini_setting(std::string_view key, std::string_view value, Options& options) {
    bool is_flag_key = false;
    const OptionSpec* spec = find_ini_key(key, is_flag_key);
    if (!spec) return UsageError{"unknown INI key '" + std::string(key) + "'"};
    if (auto why = apply_ini_value(*spec, is_flag_key, value, options))
        return UsageError{"invalid INI setting '" + std::string(key) + "=" + std::string(value) + "': " + *why};
    return std::nullopt;
}

namespace {

// The entries --help has no line for (second spellings, POV-Ray's front-end settings), each named once.
std::string also_accepted(const std::string& help) {
    std::string text = "Also read (POV-Ray's display, console and bounding settings, ignored; the others warn unless "
                       "at their\nneutral value):";
    std::size_t column = text.size() - text.rfind('\n') - 1;
    for (const OptionSpec& spec : option_table()) {
        if (!spec.usage.empty()) continue;
        std::string name;
        if (!spec.letters.empty()) {
            std::string shown = std::string(spec.letters);
            if (help.find(shown.append("n")) != std::string::npos) continue;  // on a neighbour's line ("+KFFn")
            name.append("+").append(spec.letters);
        }
        for (const std::string_view key : {spec.ini_flag, spec.ini_key})
            if (!key.empty()) name.append(name.empty() ? "" : " ").append(key);
        if (column + name.size() + 1 > 118) {
            text.append("\n ");
            column = 1;
        }
        text.append(" ").append(name);
        column += name.size() + 1;
    }
    return text.append("\n");
}

}  // namespace

std::string usage_text() {
    // Each entry's usage, then its help from this column on; continuation lines start at the same column.
    constexpr std::size_t kHelpColumn = 34;
    std::string text = "usage: wardray [scene.pov | +Iscene.pov] [settings.ini[Section] ...] [options]\n"
                       "       wardray diff IMAGE REFERENCE [--json] [-o DIFFERENCE.png]\n";
    for (const OptionSpec& spec : option_table()) {
        if (spec.usage.empty()) continue;  // a second spelling listed with the first, or accepted silently
        std::string line = "  " + std::string(spec.usage);
        line.resize(std::max(line.size() + 2, kHelpColumn), ' ');
        for (const char c : spec.help) line += c == '\n' ? "\n" + std::string(kHelpColumn, ' ') : std::string(1, c);
        text += line + "\n";
    }
    text += also_accepted(text);
    text += "With no scene, renders the bundled default scene.\n";
    return text;
}

}  // namespace wardray::app
