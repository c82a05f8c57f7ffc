// Read confinement: the folders a scene may read files from, and the check every way of reading goes through.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "parser/parse.h"

namespace wardray::parser {

/// The folders a scene may read from, as given: its own folder, the include path (`library_paths`: the system
/// include folder, `+L`, `Library_Path`), the `--read-path` folders and the configuration's permitted folders
/// (`permitted_reads`, untrusted). `trusted` is true for the folders the
/// user or the system named (their symbolic links are followed wherever they point).
struct ReadRoot {
    std::filesystem::path folder;
    bool trusted = false;
    bool subfolders = true;  ///< false: only the files directly in `folder` (a povray.conf `read = DIR` entry)
};
std::vector<ReadRoot> readable_roots(const ParseOptions& options, const std::filesystem::path& scene_file);

/// True when `file` lies inside one of `roots`: its real location (links and '..' resolved) inside a root's real
/// location, or, for a trusted root, its written location inside the root (the system include folder links its
/// fonts to /usr/share/fonts).
bool is_readable(const std::filesystem::path& file, const std::vector<ReadRoot>& roots);

/// The error for a file outside the permitted folders, naming the switch that allows it: "reading '<real path>'
/// (<what>) is not allowed: ...".
std::string read_refusal(const std::filesystem::path& file, std::string_view what);

/// When `text` is not text (NUL bytes, a UTF-16 or UTF-32 byte-order mark, or mostly control bytes and invalid
/// UTF-8 in its first kilobytes): a short excerpt of its start with every byte that is not printable ASCII
/// escaped (\xNN), at most about 40 characters. Nothing for a text file.
std::optional<std::string> binary_excerpt(std::string_view text);

/// Makes a source file's text uniform for the lexer: drops a UTF-8 byte-order mark, and turns CRLF and lone CR
/// line ends into LF (POV-Ray accepts all three).
void normalize_source_text(std::string& text);

/// A source line fit to be shown in a diagnostic: bytes that are not printable (control bytes, invalid UTF-8)
/// escaped as \xNN and the line cut at `max_chars` with "...". Lines of plain text come back unchanged.
std::string printable_source_line(std::string_view line, std::size_t max_chars = 240);

}  // namespace wardray::parser

namespace wardray::parser {

/// The process's resident memory in bytes (0 when the system does not say).
std::size_t resident_bytes();

}  // namespace wardray::parser
