// Token stream: reading tokens through the directive layer, symbol scopes, and include/macro frames.
#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string_view>

#include "parser/parser.h"

namespace wardray::parser {

// ---------------------------------------------------------------------------------------------------------------
// Token access

Token TokenStream::peek_directives() {
    while (true) {
        const Token& t = raw();
        if (t.kind == TokenKind::Directive) {
            process_directive();
            continue;
        }
        if (t.kind == TokenKind::EndOfFile && !m_frames.empty() && m_evaluating_deferred == 0) {
            handle_end_of_file();
            continue;
        }
        return t;
    }
}

Token TokenStream::peek_expr_directives() {
    // A macro's closing #end is always read through (so `M(1) * 2` works). Other directives run too, except
    // between the operands of a declared value, which they end, so `#declare A = 1 #if (A)` sees A declared.
    while (true) {
        const Token& t = raw();
        if (t.kind != TokenKind::Directive) return t;
        if (t.text == "end" && !m_frames.empty() && m_frames.back().kind == Frame::Kind::Macro &&
            m_conds.size() == m_frames.back().cond_depth) {
            ++m_pos;
            return_from_macro();
            continue;
        }
        if (m_directive_ends_value_at == m_brace_depth) return t;
        process_directive();
    }
}

Token TokenStream::next() {
    Token t = peek();
    if (t.kind != TokenKind::EndOfFile) ++m_pos;
    // The memory budget, every 16384 tokens (about 10 us each time, a few per millisecond of parsing).
    if ((++m_tokens_taken & 0x3FFF) == 0) check_memory(t);
    if (t.kind == TokenKind::Punct) {
        if (t.text == "{") {
            ++m_brace_depth;
            m_open_braces.push_back(t);
        }
        if (t.text == "}" && m_brace_depth > 0) {
            --m_brace_depth;
            m_open_braces.pop_back();
        }
    }
    return t;
}

bool TokenStream::accept(std::string_view punct) {
    if (!is_punct(peek(), punct)) return false;
    next();
    return true;
}

bool TokenStream::accept_keyword(std::string_view word) {
    if (!is_word(peek(), word)) return false;
    next();
    return true;
}

Token TokenStream::expect(std::string_view punct) {
    const Token& t = peek();
    if (!is_punct(t, punct)) {
        const std::string found = t.kind == TokenKind::EndOfFile ? "end of file" : "'" + t.text + "'";
        std::string message = "expected '";
        message += punct;
        fail(t, message + "' but found " + found);
    }
    return next();
}

Token TokenStream::expect_identifier() {
    const Token& t = peek();
    if (t.kind != TokenKind::Identifier) {
        const std::string found = t.kind == TokenKind::EndOfFile ? "end of file" : "'" + t.text + "'";
        fail(t, "expected an identifier but found " + found);
    }
    return next();
}

void TokenStream::accept_semicolon_after_declare(const Value& v, const Token& where) {
    if (is_punct(peek_expr(), ";")) {
        next();
        if (std::holds_alternative<Numeric>(v)) m_numeric_declare_semicolon = m_tokens_taken;
        return;
    }
    // POV-Ray compat: 3.5+ wants ';' after float, vector and colour declarations.
    if (std::holds_alternative<Numeric>(v) && m_version >= 3.5)
        warn(where, "missing ';' after the declaration of '" + where.text + "'");
}

void TokenStream::skip_block(const Token& kw) {
    // Skips a balanced `{ ... }` (directives inside are still processed, as POV-Ray would).
    expect("{");
    const std::size_t depth = m_brace_depth;
    while (m_brace_depth >= depth) {
        const Token t = next();
        if (t.kind == TokenKind::EndOfFile) fail(kw, "'" + kw.text + "' block has no closing '}'");
    }
}

void TokenStream::skip_optional_block(const Token& kw) {
    if (is_punct(peek(), "{")) skip_block(kw);
}

bool TokenStream::starts_string(const Token& t) {
    if (t.kind == TokenKind::String) return true;
    if (t.kind != TokenKind::Identifier) return false;
    // The string functions all begin with c, s or v (most identifiers are rejected by that alone).
    const char c0 = t.text.empty() ? '\0' : t.text[0];
    if (c0 == 'c' || c0 == 's' || c0 == 'v') {
        for (const std::string_view f : {"concat", "str", "chr", "substr", "strupr", "strlwr", "vstr"})
            if (t.text == f) return true;
    }
    const Value* v = lookup(t.text);
    return v != nullptr && std::holds_alternative<std::string>(*v);
}

// ---------------------------------------------------------------------------------------------------------------
// Symbols

const Value* TokenStream::lookup(std::string_view name) {
    const HashedName key = hashed(name);
    if (const auto deferred = m_deferred_warnings.empty() ? m_deferred_warnings.end() : m_deferred_warnings.find(key);
        deferred != m_deferred_warnings.end()) {
        const std::vector<Diagnostic> warnings = deferred->second;
        for (const Diagnostic& d : warnings) {
            if (m_declaring.empty()) {
                emit_feature_warning(d);
                continue;
            }
            // Each feature once: an identifier looked up several times, or redeclared from its own value,
            // would otherwise multiply its warnings with every declaration (exponentially in a fractal).
            std::vector<Diagnostic>& pending = m_declaring.back();
            const auto same = [&](const Diagnostic& p) { return p.message == d.message; };
            if (std::none_of(pending.begin(), pending.end(), same)) pending.push_back(d);
        }
    }
    Value* slot = find_slot(key);
    if (slot != nullptr && std::holds_alternative<Deferred>(*slot)) evaluate_deferred(*slot);
    return slot;
}

Value* TokenStream::lookup_mutable(const std::string& name) {
    before_rebinding(name);
    Value* slot = find_slot(name);
    if (slot != nullptr && std::holds_alternative<Deferred>(*slot)) evaluate_deferred(*slot);
    return slot;
}

Value* TokenStream::find_slot(std::string_view name) { return find_slot(hashed(name)); }

Value* TokenStream::find_slot(const HashedName& key) {
    for (auto it = m_scopes.rbegin(); it != m_scopes.rend(); ++it) {
        const auto found = it->find(key);
        if (found != it->end()) return &found->second;
    }
    return nullptr;
}

void TokenStream::declare(const std::string& name, Value v, bool local) {
    before_rebinding(name);
    // The copies a declared object held are freed when it is rebound (`#declare U = union { object { U } ... }`):
    // the object budget counts them no longer.
    auto rebind = [this](Value& slot, Value&& with) {
        if (const auto* o = std::get_if<Boxed<ObjectValue>>(&slot); o && o->sole()) uncount_objects((*o)->copied);
        slot = std::move(with);
    };
    // POV-Ray compat: #local binds in the innermost scope (include file or macro); #declare rebinds the innermost
    // existing name, a macro's local included, and creates a global only when the name is new.
    if (!local) {
        for (auto it = m_scopes.rbegin(); it != m_scopes.rend(); ++it) {
            const auto found = it->find(name);
            if (found == it->end()) continue;
            rebind(found->second, std::move(v));
            return;
        }
    }
    auto& scope = local ? m_scopes.back() : m_scopes.front();
    rebind(scope[name], std::move(v));
}

std::vector<std::string> TokenStream::known_names() const {
    std::vector<std::string> names;
    for (const auto& scope : m_scopes)
        for (const auto& [name, value] : scope) names.push_back(name);
    for (const auto& [name, macro] : m_macros) names.push_back(name);
    return names;
}

// ---------------------------------------------------------------------------------------------------------------
// Frames

void TokenStream::handle_end_of_file() {
    const Frame frame = m_frames.back();
    const Token& eof = raw();
    while (m_conds.size() > frame.cond_depth) {
        report(make_diagnostic(Severity::Error, m_conds.back().where,
                               "'#" + m_conds.back().where.text + "' has no matching #end in this file"));
        m_conds.pop_back();
    }
    if (frame.kind == Frame::Kind::Macro) {
        report(make_diagnostic(Severity::Error, eof, "end of file inside macro '" + frame.name + "'"));
    }
    before_scope_ends(m_scopes.back());
    m_scopes.pop_back();
    m_frames.pop_back();
    // Pay for what is used: once a library file has been read, only its macros' bodies are read again (deferred
    // declarations lex their stretch anew), so the rest of its tokens' memory goes to the files read next.
    SourceFile& finished = *m_files[m_file];
    bool still_open = frame.return_file == m_file;
    for (const Frame& f : m_frames) still_open = still_open || f.return_file == m_file;
    if (frame.kind == Frame::Kind::Include && finished.library && !still_open) {
        if (finished.has_macros) keep_macro_bodies(m_file);
        finished.tokens.clear();
    }
    m_file = frame.return_file;
    m_pos = frame.return_pos;
}

void TokenStream::return_from_macro() {
    const Frame frame = m_frames.back();
    before_scope_ends(m_scopes.back());
    m_frames.pop_back();
    m_scopes.pop_back();
    m_file = frame.return_file;
    m_pos = frame.return_pos;
}

void TokenStream::invoke_macro(const Token& name_tok, const Macro& macro) {
    expect("(");
    std::vector<std::optional<Value>> args;
    std::unordered_map<std::string, std::pair<std::size_t, std::string>> references;
    if (!accept(")")) {
        while (true) {
            const Token& t = peek();
            // POV-Ray compat: a parameter given a bare declared identifier is passed by reference.
            const auto& tokens = m_files[m_file]->tokens;
            // POV-Ray compat (its look-ahead): a float, vector or colour identifier given with no comma before
            // another declared identifier (`M(A, B C D, E)`) is passed as a reference to that next identifier, so
            // B, C and D above become C, D and D. POV-Ray decides what the lone identifier refers to after it has
            // read the next token, and an identifier there replaces it; a comma or parenthesis does not.
            bool shifted = false;
            if (t.kind == TokenKind::Identifier && args.size() < macro.params.size() &&
                tokens[m_pos + 1].kind == TokenKind::Identifier && !m_macros.count(tokens[m_pos + 1].text)) {
                const Value* first = lookup(t.text);
                const Value* next_value = lookup(tokens[m_pos + 1].text);
                shifted = first && std::holds_alternative<Numeric>(*first) && next_value;
            }
            const Token& named = shifted ? tokens[m_pos + 1] : t;
            if (named.kind == TokenKind::Identifier && args.size() < macro.params.size() &&
                (shifted || is_punct(tokens[m_pos + 1], ",") || is_punct(tokens[m_pos + 1], ")"))) {
                for (std::size_t s = m_scopes.size(); s > 0; --s) {
                    if (m_scopes[s - 1].count(named.text)) {
                        // A parameter that is itself a reference passes on what it refers to.
                        std::pair<std::size_t, std::string> target{s - 1, named.text};
                        for (const Frame& f : m_frames)
                            if (const auto r = f.references.find(named.text);
                                f.kind == Frame::Kind::Macro && f.scope_index == s - 1 && r != f.references.end())
                                target = r->second;
                        references[macro.params[args.size()]] = std::move(target);
                        break;
                    }
                }
            }
            if (shifted) {
                next();
                args.emplace_back(*lookup(named.text));
            } else if (is_punct(t, ",") || is_punct(t, ")")) {
                args.emplace_back();
            } else {
                args.emplace_back(parse_rvalue());
            }
            if (accept(",")) {
                // POV-Ray compat: a comma may follow the last argument (`M(A, B, )`), as every comma is optional.
                if (args.size() == macro.params.size() && accept(")")) break;
                continue;
            }
            // POV-Ray compat: the comma between arguments may be left out (shapes.pov: `Center_Object(...) -y`).
            if (args.size() < macro.params.size() && !is_punct(peek(), ")")) continue;
            expect(")");
            break;
        }
    }
    if (args.size() > macro.params.size())
        fail(name_tok, "macro '" + name_tok.text + "' takes " + std::to_string(macro.params.size()) +
                           " parameter(s) but " + std::to_string(args.size()) + " were given");
    NameMap<Value> scope;
    // The parameters shadow outer names from here on.
    for (const std::string& param : macro.params) before_rebinding(param);
    for (std::size_t i = 0; i < macro.params.size(); ++i) {
        if (i < args.size() && args[i]) {
            scope[macro.params[i]] = std::move(*args[i]);
        } else if (!macro.optional[i]) {
            fail(name_tok, "macro '" + name_tok.text + "' is missing parameter '" + macro.params[i] + "'");
        }
    }
    std::size_t macro_depth = 0;
    for (const Frame& f : m_frames) macro_depth += f.kind == Frame::Kind::Macro ? 1 : 0;
    if (macro_depth >= m_options.max_macro_depth) {
        report(make_diagnostic(Severity::Error, name_tok,
                               "macro calls nest deeper than the limit of " +
                                   std::to_string(m_options.max_macro_depth) +
                                   " (runaway recursion?); raise it with --max-macro-depth"));
        throw FatalError{};
    }
    Frame frame;
    frame.kind = Frame::Kind::Macro;
    frame.name = name_tok.text;
    frame.return_file = m_file;
    frame.return_pos = m_pos;
    frame.call_site = name_tok;
    frame.cond_depth = m_conds.size();
    frame.scope_index = m_scopes.size();
    frame.references = std::move(references);
    m_frames.push_back(std::move(frame));
    m_scopes.push_back(std::move(scope));
    m_file = macro.file;
    m_pos = macro.body;
}

void TokenStream::expand_macros() {
    while (true) {
        const Token& t = peek();
        if (t.kind != TokenKind::Identifier) return;
        const auto m = m_macros.find(t.text);
        if (m == m_macros.end()) return;
        const Token name = next();
        invoke_macro(name, m->second);
    }
}

bool TokenStream::count_loop_iteration(const Token& where) {
    if (++m_loop_iterations <= m_options.max_loop_iterations) return true;
    report(make_diagnostic(Severity::Error, where,
                           "loops ran more than the limit of " + std::to_string(m_options.max_loop_iterations) +
                               " iterations in total (endless #while?); raise it with --max-loop-iterations"));
    throw FatalError{};
}

void TokenStream::keep_macro_bodies(std::uint32_t index) {
    const SourceFile& file = *m_files[index];
    auto bodies = std::make_unique<SourceFile>();
    bodies->path = file.path;
    bodies->library = file.library;
    bodies->has_macros = true;
    const auto bodies_index = static_cast<std::uint32_t>(m_files.size());
    std::vector<Token> tokens;
    for (auto& [name, macro] : m_macros) {
        if (macro.file != index) continue;
        // The body and its closing #end; the tokens keep their file, lines and columns for diagnostics.
        const std::size_t start = tokens.size();
        for (std::size_t pos = macro.body; pos <= macro.end; ++pos) tokens.push_back(file.tokens[pos]);
        macro.file = bodies_index;
        macro.end = start + (macro.end - macro.body);
        macro.body = start;
    }
    tokens.push_back(file.tokens.last());  // the file's EndOfFile
    bodies->tokens.assign(std::move(tokens));
    m_files.push_back(std::move(bodies));
}

}  // namespace wardray::parser
