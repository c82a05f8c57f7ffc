// Lists of warnings about the scene that show a few of many places (coincident surfaces, pattern wraps).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "core/diagnostics.h"

namespace wardray {

/// `path:line:column`, as a message names another place than its own.
inline std::string place(const SourceLoc& loc) {
    return loc.path + ':' + std::to_string(loc.line) + ':' + std::to_string(loc.column);
}

/// After the places `shown` of `total` found: one warning at the last of them, `<topic>: N more <what>`.
inline void add_count_of_the_rest(std::vector<Diagnostic>& shown, std::size_t total, const std::string& topic,
                                  const std::string& what) {
    if (total <= shown.size() || shown.empty()) return;
    Diagnostic d;
    d.severity = Severity::Warning;
    d.loc = shown.back().loc;
    d.message = topic + ": " + std::to_string(total - shown.size()) + " more " + what;
    shown.push_back(std::move(d));
}

}  // namespace wardray
