// Source locations and diagnostics: every error and warning names its file, line and column.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/shared_string.h"

namespace wardray {

/// A place in a source file; line and column count from 1 (0 means "no location").
struct SourceLoc {
    SharedString path;  ///< the file as the user or the #include named it (shared by copies)
    std::uint32_t line = 0;
    std::uint32_t column = 0;

    bool operator==(const SourceLoc&) const = default;
};

enum class Severity { Note, Warning, Error };

/// One message about the scene, with the source line it refers to so it can be printed with a caret.
struct Diagnostic {
    Severity severity = Severity::Error;
    SourceLoc loc;
    std::string message;
    std::string source_line;     ///< the text of loc.line, without its newline; empty when unknown
    std::uint32_t span = 1;      ///< how many characters the caret underlines
    std::vector<std::string> notes;  ///< include chain and macro expansion, outermost last
};

/// Formats a diagnostic as `path:line:col: error: message`, the source line, a caret line and `note:` lines.
std::string format_diagnostic(const Diagnostic& d);

/// Collects diagnostics and counts errors, so a parse can stop after a limit.
class DiagnosticSink {
public:
    void add(Diagnostic d);
    const std::vector<Diagnostic>& all() const { return m_all; }
    std::size_t error_count() const { return m_errors; }
    std::size_t warning_count() const { return m_warnings; }

private:
    std::vector<Diagnostic> m_all;
    std::size_t m_errors = 0;
    std::size_t m_warnings = 0;
};

}  // namespace wardray
