// POV-Ray INI files: lines, [Section] labels and ; comments, read into what each line asks for.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace wardray::app {

/// One line of an INI file that asks for something.
struct IniLine {
    enum class Kind {
        Setting,   ///< `Key=Value`: key and value trimmed, the value's enclosing double quotes removed
        Switches,  ///< `+W320 +H240 Declare=N=1`: words, each a switch or a KEY=VALUE
        IniFile,   ///< a line that is a file name alone: another INI file, read in its place
    };
    Kind kind = Kind::Setting;
    int line = 0;  ///< 1-based
    std::string key;
    std::string value;  ///< Setting: the value; Switches: the whole line; IniFile: the file name
};

/// An INI file's lines that apply, in order: those before its first [Section] label and, when a section is asked
/// for, those of that section (labels compare without case, as in POV-Ray).
struct IniFile {
    std::filesystem::path path;
    std::vector<IniLine> lines;
};

/// Whether a command-line argument names an INI file: `scene.ini` or `scene.ini[Section]` (any case of .ini).
bool is_ini_argument(std::string_view argument);

/// Reads `scene.ini` or `scene.ini[Section]` (a relative name not found is looked for in POV-Ray's ini folder,
/// /usr/share/povray-3.7/ini, as POV-Ray does with its library path); on failure the message, starting with the file (and line, for a
/// line that cannot be read): "scene.ini:3: error: ...", or "scene.ini: error: no section [Big]".
std::variant<IniFile, std::string> read_ini_file(std::string_view argument);

/// Splits a Switches line into its words (whitespace outside double quotes separates them).
std::vector<std::string> split_ini_words(std::string_view text);

}  // namespace wardray::app
