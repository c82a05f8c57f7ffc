// The option table: every switch, INI key and long option, with its help text and how it sets Options.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "app/options.h"

namespace wardray::app {

/// What follows an option's name.
enum class ValueKind {
    None,       ///< nothing: `+RFI`, `--check`; a switch with text after its letters is some other switch
    Flag,       ///< the sign is the value: `+V` / `-V`, or on/off in an INI file
    Value,      ///< one value: `+W640`, `--threads 2`, `Width=640`
    FlagValue,  ///< the sign and, optionally, a value: `+A`, `+A0.3`, `-A`, `+FN`, `-F`
    TwoValues,  ///< two words: `--aov KIND FILE`
};

/// One use of an option, whichever way it was written.
struct OptionUse {
    /// `+` (true) or `-` (false) of a switch, or the on/off of an INI flag key; empty for an INI value key and a
    /// long option.
    std::optional<bool> sign;
    std::string_view value{};   ///< what follows the switch letters, the INI `=` or the long option; may be empty
    std::string_view second{};  ///< the second word of a TwoValues option
};

/// Sets Options from one use; returns why the value is refused ("expected a size in pixels, 1..65536").
using OptionSetter = std::optional<std::string> (*)(const OptionUse& use, Options& options);

/// One option: how the command line and INI files spell it, what it takes, its help, and what it sets.
struct OptionSpec {
    std::string_view letters{};     ///< POV-Ray switch letters after `+`/`-` ("WT"); empty: no switch
    std::string_view ini_key{};     ///< POV-Ray INI key taking the value ("Work_Threads"); empty: none
    std::string_view ini_flag{};    ///< POV-Ray INI key taking on/off in place of the sign ("Antialias"); empty: none
    std::string_view long_name{};   ///< wardray's long option ("--threads"); empty: none
    std::string_view short_name{};  ///< a one-letter alias of the long option ("-o"); empty: none
    ValueKind kind = ValueKind::None;
    std::string_view usage{};       ///< the left column of --help ("+WTn, --threads n")
    std::string_view help{};        ///< the right column; '\n' starts a continuation line
    std::string_view long_error{};  ///< what a wrong long option says after its name ("needs a count 1..1024")
    OptionSetter set = nullptr;
};

/// Every option, in --help order: POV-Ray's switches first, then wardray's long options.
std::span<const OptionSpec> option_table();

/// POV-Ray's animation, partial-render and front-end switches and keys (app/frame_options.cpp), which
/// option_table() lists after the other POV-Ray switches. An entry with no usage is not shown by --help.
std::span<const OptionSpec> frame_option_table();

/// A whole decimal integer / a finite number, the whole text and nothing else.
bool parse_int(std::string_view text, int& out);
bool parse_double(std::string_view text, double& out);

/// POV-Ray's INI booleans: on/off, true/false, yes/no, 1/0, in any case; empty when `text` is none of them.
std::optional<bool> parse_ini_bool(std::string_view text);

/// Whether `s` begins with `prefix`, ignoring ASCII case (POV-Ray's switches and INI keys ignore it).
bool starts_with_ci(std::string_view s, std::string_view prefix);
/// Whether `a` and `b` are equal, ignoring ASCII case.
bool equals_ci(std::string_view a, std::string_view b);

/// The entry whose switch letters begin `body` (the switch without its sign), the longest such; an entry of kind
/// None matches only its letters exactly. Case-insensitive, as in POV-Ray. Null when none does.
const OptionSpec* find_switch(std::string_view body);

/// The entry with this long or short option name (`--threads`, `-o`); null when none has it.
const OptionSpec* find_long_option(std::string_view name);

/// The entry with this INI key (case-insensitive, as in POV-Ray), as its value key or its flag key; null when none.
const OptionSpec* find_ini_key(std::string_view key, bool& is_flag_key);

}  // namespace wardray::app
