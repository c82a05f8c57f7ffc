// Parse entry points, the statement loop with error recovery, and diagnostics with include/macro notes.
#include "parser/parse.h"

#include <cerrno>
#include <cstring>
#include <new>

#include "parser/keywords.h"
#include "parser/parser.h"

namespace wardray::parser {

SourceStream::SourceStream(const ParseOptions& options)
    : m_stack_base(static_cast<const char*>(__builtin_frame_address(0))), m_options(options) {}

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

SourceStream::NestingGuard::NestingGuard(SourceStream& stream, const Token& at, std::size_t& depth)
    : m_stream(stream), m_depth(depth) {
    // The stack grows down on every platform we build for: the distance from where the parser began is its use.
    const char* here = static_cast<const char*>(__builtin_frame_address(0));
    const bool stack_full = m_stream.m_stack_base - here > k_max_stack_bytes;
    if (++m_depth <= k_max_nesting && !stack_full) return;
    --m_depth;
    m_stream.report(m_stream.make_diagnostic(
        Severity::Error, at,
        stack_full ? "nesting too deep for the stack (" + std::to_string(m_depth) + " levels); stopping"
                   : "nesting deeper than " + std::to_string(k_max_nesting) + " levels; stopping"));
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
    if (at.file < m_files.size()) d.source_line = m_files[at.file]->line_text(at.line);
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
            (site.file < m_files.size() ? m_files[site.file]->path : std::string("?")) + ":" + std::to_string(site.line);
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

void TokenStream::fail_undeclared(const Token& at) {
    if (m_failed_declarations.count(at.text) > 0) throw StatementError{};  // its #declare was reported
    Diagnostic d = make_diagnostic(Severity::Error, at, "undeclared identifier '" + at.text + "'");
    // Suggest the closest declared name (preferred) or keyword within edit distance 2.
    std::string best;
    std::size_t best_distance = 3;
    auto consider = [&](std::string_view name) {
        if (name == at.text) return;
        const std::size_t dist = edit_distance(at.text, name, 2);
        if (dist < best_distance || (dist == best_distance && !best.empty() && name < best)) {
            best_distance = dist;
            best = std::string(name);
        }
    };
    for (const std::string& name : known_names()) consider(name);
    const std::string declared_best = best;
    const std::size_t declared_distance = best_distance;
    for (std::string_view kw : all_keywords()) consider(kw);
    if (!declared_best.empty() && declared_distance <= best_distance) best = declared_best;
    if (!best.empty() && at.text.size() > 2) d.notes.insert(d.notes.begin(), "did you mean '" + best + "'?");
    report(std::move(d));
    throw StatementError{};
}

void TokenStream::recover_after_error(std::size_t depth) {
    // A failed statement keyword followed by a block (`spher { ... }`): skip that block too.
    if (m_brace_depth == depth && is_punct(raw(), "{")) {
        ++m_pos;
        ++m_brace_depth;
        m_open_braces.push_back(m_files[m_file]->tokens[m_pos - 1]);
    }
    // Skip the rest of the statement that failed: everything up to its closing brace.
    for (int guard = 0; m_brace_depth > depth && guard < 10'000'000; ++guard) {
        try {
            if (next().kind == TokenKind::EndOfFile) break;
        } catch (const StatementError&) {
        }
        // A loop around unclosed blocks opens more on every pass: stop as the descent's own nesting limit does,
        // before the open braces fill memory.
        if (m_brace_depth > depth + k_max_nesting) {
            report(make_diagnostic(Severity::Error, m_open_braces.back(),
                                   "nesting deeper than " + std::to_string(k_max_nesting) +
                                       " levels while skipping a failed statement; stopping"));
            throw FatalError{};
        }
    }
    m_brace_depth = depth;
    if (m_open_braces.size() > depth) m_open_braces.resize(depth);
    if (raw().kind == TokenKind::Punct && raw().text == ";") ++m_pos;
}

ParseResult Parser::run(std::string text, const std::string& path) {
    ParseResult result;
    try {
        m_scopes.emplace_back();
        for (const auto& [name, value] : m_options.declares) m_scopes.front()[name] = Numeric::scalar(value);
        auto file = std::make_unique<SourceFile>();
        file->path = path;
        file->text = std::move(text);
        std::vector<Diagnostic> lex_errors;
        file->tokens = lex(file->text, 0, path, lex_errors, file->decoded);
        m_files.push_back(std::move(file));
        for (auto& d : lex_errors) {
            m_files.back()->truncated = m_files.back()->truncated || d.message == "unterminated string";
            report(std::move(d));
        }
        try {
            while (true) {
                try {
                    if (peek().kind == TokenKind::EndOfFile) break;
                    parse_statement();
                } catch (const StatementError&) {
                    recover_after_error(0);
                }
            }
            for (const Cond& c : m_conds)
                report(make_diagnostic(Severity::Error, c.where, "'#" + c.where.text + "' has no matching #end"));
            if (!m_builder.global().assumed_gamma_given && m_version >= 3.7) {
                Diagnostic d;
                d.severity = Severity::Warning;
                d.loc.path = path;
                d.message = "assumed_gamma not given in global_settings; using 1.0";
                report(std::move(d));
            }
        } catch (const FatalError&) {
        } catch (const std::bad_alloc&) {
            // A scene that builds more than memory holds (an endless loop of objects): blame where it stopped.
            m_diagnostics.push_back(make_diagnostic(
                Severity::Error, m_file < m_files.size() && m_pos < m_files[m_file]->tokens.size() ? raw() : Token{},
                "out of memory: the scene holds more than this machine can (an endless loop?)"));
            ++m_errors;
        }
    } catch (const std::exception& e) {
        Diagnostic d;
        d.loc.path = path;
        d.message = std::string("internal parser error: ") + e.what();
        m_diagnostics.push_back(std::move(d));
        ++m_errors;
    } catch (...) {
        Diagnostic d;
        d.loc.path = path;
        d.message = "internal parser error";
        m_diagnostics.push_back(std::move(d));
        ++m_errors;
    }
    result.diagnostics = std::move(m_diagnostics);
    if (m_errors == 0) result.scene = m_builder.finish(path, m_version, std::move(m_warnings));
    return result;
}

ParseResult parse_string(std::string_view text, const std::string& path, const ParseOptions& options) {
    try {
        Parser parser(options);
        return parser.run(std::string(text), path);
    } catch (...) {
        ParseResult r;
        Diagnostic d;
        d.loc.path = path;
        d.message = "internal parser error";
        r.diagnostics.push_back(std::move(d));
        return r;
    }
}

ParseResult parse_file(const std::filesystem::path& path, const ParseOptions& options) {
    const std::string name = path.string();
    std::string reason;
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) {
        reason = std::strerror(EISDIR);
    } else {
        std::string text;
        if (read_text_file(path, text, reason)) return parse_string(text, name, options);
    }
    ParseResult r;
    Diagnostic d;
    d.severity = Severity::Error;
    d.message = "cannot open scene file '" + name + "': " + reason;
    r.diagnostics.push_back(std::move(d));
    return r;
}

}  // namespace wardray::parser
