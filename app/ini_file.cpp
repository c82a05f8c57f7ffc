// POV-Ray INI files: each line classified, comments removed, the asked-for section selected.
#include "app/ini_file.h"

#include <fstream>
#include <optional>

#include "app/option_table.h"

namespace wardray::app {

namespace {

const std::filesystem::path kPovrayIniDir = "/usr/share/povray-3.7/ini";

std::string_view trim(std::string_view s) {
    const auto first = s.find_first_not_of(" \t\r\n");
    if (first == std::string_view::npos) return {};
    const auto last = s.find_last_not_of(" \t\r\n");
    return s.substr(first, last - first + 1);
}

// A line without its `;` comment (a `;` inside double quotes is text).
std::string_view strip_comment(std::string_view line) {
    bool quoted = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
        if (line[i] == '"') quoted = !quoted;
        if (line[i] == ';' && !quoted) return line.substr(0, i);
    }
    return line;
}

std::string unquote(std::string_view s) {
    if (s.size() >= 2 && s.front() == '"' && s.back() == '"') s = s.substr(1, s.size() - 2);
    return std::string(s);
}

// A `[Label]` line's label, trimmed; empty when the line is not one.
std::optional<std::string_view> section_label(std::string_view line) {
    if (line.empty() || line.front() != '[') return std::nullopt;
    const auto close = line.find(']');
    if (close == std::string_view::npos) return std::nullopt;
    return trim(line.substr(1, close - 1));
}

}  // namespace

bool is_ini_argument(std::string_view argument) {
    if (const auto open = argument.find('['); open != std::string_view::npos && argument.back() == ']')
        argument = argument.substr(0, open);
    return argument.size() > 4 && equals_ci(argument.substr(argument.size() - 4), ".ini");
}

std::vector<std::string> split_ini_words(std::string_view text) {
    std::vector<std::string> words;
    std::string word;
    bool quoted = false;
    for (const char c : text) {
        if (c == '"') quoted = !quoted;
        if (!quoted && (c == ' ' || c == '\t')) {
            if (!word.empty()) words.push_back(std::move(word));
            word.clear();
            continue;
        }
        if (c != '"') word += c;
    }
    if (!word.empty()) words.push_back(std::move(word));
    return words;
}

std::variant<IniFile, std::string> read_ini_file(std::string_view argument) {
    std::string_view name = argument;
    std::optional<std::string_view> wanted;
    if (const auto open = argument.find('['); open != std::string_view::npos && argument.back() == ']') {
        name = argument.substr(0, open);
        wanted = trim(argument.substr(open + 1, argument.size() - open - 2));
    }
    IniFile ini;
    ini.path = std::filesystem::path(std::string(name));
    // POV-Ray compat: an INI file not found as named is looked for in POV-Ray's ini folder (quickres.ini, ...).
    std::error_code ec;
    if (ini.path.is_relative() && !std::filesystem::exists(ini.path, ec) &&
        std::filesystem::is_regular_file(kPovrayIniDir / ini.path, ec))
        ini.path = kPovrayIniDir / ini.path;
    std::ifstream in(ini.path);
    if (!in) return ini.path.string() + ": error: cannot read the INI file";
    const auto error_at = [&](int number, const char* message) {
        return ini.path.string() + ":" + std::to_string(number) + ": error: " + message;
    };
    std::string text;
    // POV-Ray compat: lines before the first label always apply; a label's lines only when it is asked for.
    bool in_wanted = true, found = !wanted;
    for (int number = 1; std::getline(in, text); ++number) {
        const std::string_view line = trim(strip_comment(text));
        if (line.empty()) continue;
        if (const auto label = section_label(line)) {
            in_wanted = wanted && equals_ci(*label, *wanted);
            found = found || in_wanted;
            continue;
        }
        if (line.front() == '[')
            return error_at(number, "a section label needs its ']'");
        if (!in_wanted) continue;
        IniLine l;
        l.line = number;
        if (line.front() == '+' || line.front() == '-') {
            l.kind = IniLine::Kind::Switches;
            l.value = std::string(line);
        } else if (const auto eq = line.find('='); eq != std::string_view::npos) {
            l.kind = IniLine::Kind::Setting;
            l.key = std::string(trim(line.substr(0, eq)));
            l.value = unquote(trim(line.substr(eq + 1)));
            if (l.key.empty()) return error_at(number, "a setting needs its key before '='");
        } else {
            l.kind = IniLine::Kind::IniFile;
            l.value = unquote(line);
        }
        ini.lines.push_back(std::move(l));
    }
    if (!found) return ini.path.string() + ": error: no section [" + std::string(*wanted) + "] in the INI file";
    return ini;
}

}  // namespace wardray::app
