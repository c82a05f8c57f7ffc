// SourceStream: reading and lexing source files, the include search order, and diagnostics with their notes.
#include "parser/source_stream.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>
#include <system_error>

namespace wardray::parser {

SourceStream::SourceStream(const ParseOptions& options)
    : m_stack_base(static_cast<const char*>(__builtin_frame_address(0))),
      m_options(options),
      m_resident_at_start(resident_bytes()) {}

std::string SourceFile::line_text(std::uint32_t line) const {
    // Diagnostics and entity locations ask for lines often: index the line starts once per file.
    if (line_starts.empty()) {
        line_starts.push_back(0);
        for (std::size_t i = 0; i < text.size(); ++i)
            if (text[i] == '\n') line_starts.push_back(i + 1);
    }
    if (line == 0 || line > line_starts.size()) return {};
    const std::size_t start = line_starts[line - 1];
    std::size_t end = line < line_starts.size() ? line_starts[line] - 1 : text.size();
    if (end > start && text[end - 1] == '\r') --end;
    return text.substr(start, end - start);
}

void SourceStream::NestingGuard::fail(const Token& at, std::size_t limit, bool stack_full) {
    m_stream.report(m_stream.make_diagnostic(
        Severity::Error, at,
        stack_full ? "nesting too deep for the stack (" + std::to_string(m_depth) + " levels); stopping"
                   : "nesting deeper than " + std::to_string(limit) + " levels; stopping"));
    throw FatalError{};
}

Diagnostic SourceStream::make_diagnostic(Severity s, const Token& at, std::string message) const {
    Diagnostic d;
    d.severity = s;
    d.message = std::move(message);
    if (at.file < m_files.size()) {
        const SourceFile& f = *m_files[at.file];
        d.loc = SourceLoc{f.path, at.line, at.column};
    }
    d.span = at.kind == TokenKind::EndOfFile ? 1 : at.length;
    // A note without a message only carries a location (for scene entities): skip the costly parts.
    if (s == Severity::Note && d.message.empty()) return d;
    // Escaped and cut short: a line of a file that is not really text never reaches the terminal as it is.
    if (at.file < m_files.size()) d.source_line = printable_source_line(m_files[at.file]->line_text(at.line));
    // Notes, innermost first: the macro being expanded and the include chain; deep recursion is shortened to
    // the innermost and outermost few frames.
    constexpr std::size_t k_shown_each_side = 3;
    const std::size_t n_frames = m_frames.size();
    for (auto it = m_frames.rbegin(); it != m_frames.rend(); ++it) {
        const auto from_inside = static_cast<std::size_t>(it - m_frames.rbegin());
        if (n_frames > 2 * k_shown_each_side + 1 && from_inside >= k_shown_each_side &&
            from_inside < n_frames - k_shown_each_side) {
            if (from_inside == k_shown_each_side)
                d.notes.push_back("... " + std::to_string(n_frames - 2 * k_shown_each_side) +
                                  " more macro calls and includes ...");
            continue;
        }
        const Token& site = it->call_site;
        const std::string where =
            (site.file < m_files.size() ? m_files[site.file]->path.str() : std::string("?")) + ":" + std::to_string(site.line);
        if (it->kind == Frame::Kind::Include)
            d.notes.push_back("included from " + where);
        else
            d.notes.push_back("in macro '" + it->name + "' invoked from " + where);
    }
    return d;
}

void SourceStream::report(Diagnostic d) {
    const bool error = d.severity == Severity::Error;
    if (d.severity == Severity::Warning) m_warnings.push_back(d);
    m_diagnostics.push_back(std::move(d));
    if (error && ++m_errors >= m_options.max_errors) throw FatalError{};
}

void SourceStream::fail(const Token& at, std::string message) {
    if (at.kind == TokenKind::EndOfFile && at.file < m_files.size()) {
        // After an unterminated string the rest of the file is gone: what fails at its end is a consequence.
        if (m_files[at.file]->truncated) throw FatalError{};
        // The file ended inside a block: point at the brace that was never closed.
        if (!m_open_braces.empty() && m_open_braces.back().file == at.file) {
            Diagnostic d = make_diagnostic(Severity::Error, m_open_braces.back(),
                                           "this '{' is never closed: the file ends before its '}'");
            d.notes.insert(d.notes.begin(), "the file ends at line " + std::to_string(at.line) + " inside this block");
            report(std::move(d));
            throw FatalError{};
        }
    }
    report(make_diagnostic(Severity::Error, at, std::move(message)));
    throw StatementError{};
}

void SourceStream::warn(const Token& at, std::string message) {
    report(make_diagnostic(Severity::Warning, at, std::move(message)));
}

void SourceStream::warn_unsupported(const Token& at, const std::string& feature) {
    Diagnostic d = make_diagnostic(Severity::Warning, at, feature + " is not rendered yet");
    if (m_declaring.empty()) {
        emit_feature_warning(std::move(d));
        return;
    }
    for (const Diagnostic& pending : m_declaring.back())
        if (pending.message == d.message) return;
    m_declaring.back().push_back(std::move(d));
}

void SourceStream::emit_feature_warning(Diagnostic d) {
    if (!m_warned_features.insert(d.message).second) return;
    report(std::move(d));
}

void SourceStream::warn_once(const Token& at, const std::string& message) {
    // Checked before the diagnostic is built: loops may call the same function millions of times.
    if (m_warned_features.count(message) > 0) return;
    emit_feature_warning(make_diagnostic(Severity::Warning, at, message));
}

bool read_text_file(const std::filesystem::path& path, std::string& text, std::string& error) {
    std::FILE* f = std::fopen(path.c_str(), "rb");
    if (f == nullptr) {
        error = std::strerror(errno);
        return false;
    }
    std::error_code ec;
    const auto size = std::filesystem::file_size(path, ec);
    text.clear();
    if (!ec) text.reserve(static_cast<std::size_t>(size));
    char buffer[1 << 16];
    while (const std::size_t n = std::fread(buffer, 1, sizeof buffer, f)) text.append(buffer, n);
    const bool failed = std::ferror(f) != 0;
    std::fclose(f);
    if (failed) error = std::strerror(EIO);
    return !failed;
}

std::optional<std::uint32_t> SourceStream::load_file(const std::filesystem::path& path, bool library,
                                                     std::string& error) {
    const std::string key = path.lexically_normal().string();
    if (const auto it = m_file_index.find(key); it != m_file_index.end()) {
        if (m_files[it->second]->tokens.cleared()) lex_file(it->second);  // released after its first reading
        return it->second;
    }
    auto file = std::make_unique<SourceFile>();
    if (!read_text_file(path, file->text, error)) return std::nullopt;
    if (const auto excerpt = binary_excerpt(file->text)) {
        error = "it is not a text file (it starts with \"" + *excerpt + "\")";
        return std::nullopt;
    }
    normalize_source_text(file->text);
    file->path = key;
    file->library = library;
    const auto index = static_cast<std::uint32_t>(m_files.size());
    m_files.push_back(std::move(file));
    m_file_index[key] = index;
    lex_file(index);
    return index;
}

void SourceStream::lex_file(std::uint32_t index) {
    SourceFile& file = *m_files[index];
    file.tokens.reset(file.text, LexStart{}, file.text.size(), index, file.path, file.decoded,
                      [this, index](std::vector<Diagnostic>& lex_errors) {
                          SourceFile& f = *m_files[index];
                          for (auto& d : lex_errors) {
                              f.truncated = f.truncated || d.message == "unterminated string";
                              report(std::move(d));
                          }
                      });
    // The first chunk now: a file of a few thousand tokens reports its lexical errors before it is read.
    (void)file.tokens[0];
}

std::vector<SourceStream::SearchCandidate> SourceStream::search_candidates(const std::filesystem::path& requested,
                                                                        const char* extension) const {
    namespace fs = std::filesystem;
    std::vector<SearchCandidate> candidates;
    if (requested.is_absolute()) {
        candidates.push_back({requested, false, false});
    } else {
        // POV-Ray compat: POV-Ray looks in the current folder, then in its library paths in order (its front end's
        // FindFilePath), for the scene and for every file it includes, however deep. The scene's folder comes next
        // (POV-Ray is run from there); the reading file's own folder, which POV-Ray never searches, comes last.
        std::vector<fs::path> seen;
        auto add = [&](const fs::path& folder, bool library, bool beyond) {
            std::error_code ec;
            const fs::path key = fs::weakly_canonical(folder.empty() ? fs::path(".") : folder, ec);
            if (std::find(seen.begin(), seen.end(), key) != seen.end()) return;
            seen.push_back(key);
            candidates.push_back({folder.empty() ? requested : folder / requested, library, beyond});
        };
        add(fs::path(), false, false);
        add(fs::path(m_files.front()->path.str()).parent_path(), false, false);
        for (const auto& dir : m_options.library_paths) add(dir, true, false);
        const SourceFile& reading = *m_files[m_file];
        add(fs::path(reading.path.str()).parent_path(), reading.library, !reading.library);
    }
    if (!requested.has_extension()) {
        // POV-Ray compat: a name without extension is also tried with the usual one.
        const std::size_t n = candidates.size();
        for (std::size_t i = 0; i < n; ++i) {
            SearchCandidate c = candidates[i];
            c.path += extension;
            candidates.push_back(std::move(c));
        }
    }
    return candidates;
}

}  // namespace wardray::parser
