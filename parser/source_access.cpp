// SourceStream's part of read confinement: every file a scene names is checked against the permitted folders.
#include <system_error>

#include "parser/source_stream.h"

namespace wardray::parser {

void SourceStream::require_readable(const Token& at, const std::filesystem::path& file, std::string_view what) {
    if (m_read_roots.empty()) m_read_roots = readable_roots(m_options, m_files.front()->path.str());
    if (!is_readable(file, m_read_roots)) fail(at, read_refusal(file, what));
}

std::optional<std::filesystem::path> SourceStream::find_readable(const Token& at,
                                                                 const std::filesystem::path& requested,
                                                                 const char* extension, std::string_view what) {
    for (const SearchCandidate& candidate : search_candidates(requested, extension)) {
        std::error_code ec;
        if (!std::filesystem::is_regular_file(candidate.path, ec)) continue;
        require_readable(at, candidate.path, what);
        return candidate.path;
    }
    return std::nullopt;
}

}  // namespace wardray::parser
