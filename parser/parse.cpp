// Parse entry points, the statement loop with error recovery, and the undeclared-identifier diagnostic.
#include "parser/parse.h"

#include <cerrno>
#include <cstring>
#include <new>

#include "core/large_stack.h"
#include "parser/keywords.h"
#include "parser/parser.h"

namespace wardray::parser {

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
    // Deeply nested objects (POV-Ray reads 20,000 nested unions) need more stack than a thread's default: the
    // descent runs on a thread with room for them, reserved but committed only as far as it is used.
    constexpr std::size_t k_parse_stack_bytes = std::size_t{1} << 30;
    ParseResult result;
    run_with_stack(k_parse_stack_bytes, [&](std::size_t stack_bytes) {
        m_stack_base = static_cast<const char*>(__builtin_frame_address(0));
        // A margin below the reserved size for the frames under the guard's last check.
        if (stack_bytes != 0) m_max_stack_bytes = static_cast<std::ptrdiff_t>(stack_bytes / 8 * 7);
        result = run_here(std::move(text), path);
    });
    return result;
}

ParseResult Parser::run_here(std::string text, const std::string& path) {
    ParseResult result;
    try {
        m_scopes.emplace_back();
        if (m_options.set_number_of_waves) m_options.set_number_of_waves(10);
        for (const auto& [name, value] : m_options.declares) m_scopes.front()[name] = Numeric::scalar(value);
        auto file = std::make_unique<SourceFile>();
        file->path = path;
        file->text = std::move(text);
        if (const auto excerpt = binary_excerpt(file->text)) {
            // Not text: one error at its start, quoting only a short escaped excerpt.
            Diagnostic d;
            d.severity = Severity::Error;
            d.loc = SourceLoc{path, 1, 1};
            d.message = "this is not a scene file: it is not text (it starts with \"" + *excerpt + "\")";
            m_diagnostics.push_back(std::move(d));
            ++m_errors;
            file->text.clear();
        }
        normalize_source_text(file->text);
        m_files.push_back(std::move(file));
        lex_file(0);
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
            if (!m_builder.global().assumed_gamma_given) {
                // POV-Ray compat: without assumed_gamma, a scene whose final #version is below 3.7, or that has
                // no #version anywhere (POV-Ray then assumes 3.62), gets POV-Ray 3.6's "no gamma handling".
                m_builder.global().gamma_handling = m_version_given && m_version >= 3.7;
                Diagnostic d;
                d.severity = Severity::Warning;
                d.loc.path = path;
                d.message = m_builder.global().gamma_handling
                                ? "assumed_gamma not given in global_settings; using 1.0"
                                : "assumed_gamma not given in a scene for POV-Ray before 3.7 (by its #version, or "
                                  "having none): gamma handling is off, as in POV-Ray 3.6";
                report(std::move(d));
            }
        } catch (const FatalError&) {
        } catch (const std::bad_alloc&) {
            // A scene that builds more than memory holds (an endless loop of objects): blame where it stopped.
            // The token is taken only if it is in memory: lexing now would allocate.
            const Token* at = m_file < m_files.size() ? m_files[m_file]->tokens.if_present(m_pos) : nullptr;
            m_diagnostics.push_back(make_diagnostic(
                Severity::Error, at != nullptr ? *at : Token{},
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
    m_builder.set_legacy_sky(!(m_version_given && m_version >= 3.7));
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
