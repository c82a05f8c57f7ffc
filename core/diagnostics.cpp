// Diagnostics: formatting in the compiler style users know, and collection.
#include "core/diagnostics.h"

#include <algorithm>
#include <string>

namespace wardray {

namespace {

const char* severity_name(Severity s) {
    switch (s) {
        case Severity::Note: return "note";
        case Severity::Warning: return "warning";
        case Severity::Error: return "error";
    }
    return "error";
}

}  // namespace

std::string format_diagnostic(const Diagnostic& d) {
    std::string out;
    if (!d.loc.path.empty()) {
        out += d.loc.path;
        if (d.loc.line > 0) {
            // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) about `":" + std::string`.
            out += ':';
            out += std::to_string(d.loc.line);
            out += ':';
            out += std::to_string(d.loc.column);
        }
        out += ": ";
    }
    out += severity_name(d.severity);
    out += ": ";
    out += d.message;
    out += '\n';
    if (!d.source_line.empty() && d.loc.line > 0) {
        const std::string number = std::to_string(d.loc.line);
        const std::string gutter(std::max<std::size_t>(number.size(), 4) - number.size() + 1, ' ');
        out += gutter + number + " | ";
        // Tabs become single spaces so the caret lines up with the text above it.
        std::string line = d.source_line;
        std::replace(line.begin(), line.end(), '\t', ' ');
        out += line + '\n';
        out += std::string(gutter.size() + number.size(), ' ') + " | ";
        const std::size_t col = d.loc.column > 0 ? d.loc.column - 1 : 0;
        out += std::string(std::min(col, line.size()), ' ');
        out += '^';
        if (d.span > 1) out += std::string(d.span - 1, '~');
        out += '\n';
    }
    for (const std::string& note : d.notes) out += "note: " + note + '\n';
    return out;
}

void DiagnosticSink::add(Diagnostic d) {
    if (d.severity == Severity::Error) ++m_errors;
    if (d.severity == Severity::Warning) ++m_warnings;
    m_all.push_back(std::move(d));
}

}  // namespace wardray
