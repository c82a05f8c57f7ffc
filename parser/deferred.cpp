// Deferred declarations: a library file's pigments, finishes and textures are read when the scene first uses
// them, so including textures.inc or stones.inc costs little more than lexing it.
//
// A deferred value must read the same when it is evaluated as it would have where it stands. The scan in
// try_defer_declaration accepts only values whose meaning cannot change silently: no directives or macros, no
// random numbers or file and geometry queries, and identifiers that are keywords or declared items. Whatever
// could change what the value reads forces it first: rebinding, undefining or shadowing an identifier it reads
// (before_rebinding), the end of the scope holding one (before_scope_ends), and #default (evaluate_all_deferred).
// The #version it was declared under is restored while it is read.
#include <algorithm>
#include <memory>
#include <string_view>

#include "parser/keywords.h"
#include "parser/parser.h"

namespace wardray::parser {

namespace {

/// Value keywords whose declarations may be deferred.
bool deferrable_item(std::string_view w) {
    return w == "texture" || w == "pigment" || w == "finish" || w == "normal" || w == "color_map" ||
           w == "colour_map";
}

/// Words whose value depends on when they are read (a random stream's state, files, the objects so far).
bool depends_on_time_of_reading(std::string_view w) {
    return w == "rand" || w == "seed" || w == "trace" || w == "inside" || w == "min_extent" || w == "max_extent" ||
           w == "file_exists" || w == "function" || w == "now";
}

/// Kinds of identifier a deferred value may read: values that only change by rebinding.
bool readable_when_deferred(const Value& v) {
    return std::holds_alternative<Numeric>(v) || std::holds_alternative<std::string>(v) ||
           std::holds_alternative<Boxed<Pigment>>(v) || std::holds_alternative<Boxed<Finish>>(v) ||
           std::holds_alternative<Boxed<Texture>>(v) || std::holds_alternative<Boxed<Transform>>(v) ||
           std::holds_alternative<Unsupported>(v) || std::holds_alternative<Boxed<Interior>>(v) ||
           std::holds_alternative<Boxed<Normal>>(v) || std::holds_alternative<Boxed<SkySphere>>(v) ||
           std::holds_alternative<Boxed<Fog>>(v) || std::holds_alternative<Boxed<Rainbow>>(v) ||
           std::holds_alternative<Boxed<Media>>(v) || std::holds_alternative<Boxed<MaterialValue>>(v) ||
           std::holds_alternative<Deferred>(v);
}

}  // namespace

bool Preprocessor::try_defer_declaration(const Token& id, bool local) {
    if (!m_options.defer_library_declarations || m_evaluating_deferred > 0 || !m_declaring.empty()) return false;
    const SourceFile& file = *m_files[m_file];
    if (!file.library || m_frames.empty() || m_frames.back().kind != Frame::Kind::Include) return false;
    // A loop reads its body again, with other values each time.
    for (std::size_t c = m_frames.back().cond_depth; c < m_conds.size(); ++c)
        if (m_conds[c].kind == Cond::Kind::While || m_conds[c].kind == Cond::Kind::For) return false;

    const TokenStore& tokens = file.tokens;
    const std::size_t begin = m_pos;
    if (tokens[begin].kind != TokenKind::Identifier || !deferrable_item(tokens[begin].text)) return false;
    std::vector<std::string_view> reads;
    // Scans `keyword { ... }` from `i`, leaving `i` just past the closing brace; false when the value cannot wait.
    auto scan_block = [&](std::size_t& i) {
        ++i;
        if (!is_punct(tokens[i], "{")) return false;
        int depth = 0;
        for (;; ++i) {
            const Token& t = tokens[i];
            if (t.kind == TokenKind::EndOfFile || t.kind == TokenKind::Directive) return false;
            if (t.kind == TokenKind::Punct) {
                if (t.text == "{") ++depth;
                if (t.text == "}" && --depth == 0) {
                    ++i;
                    return true;
                }
            } else if (t.kind == TokenKind::Identifier) {
                if (t.text == id.text || depends_on_time_of_reading(t.text) || m_macros.count(t.text) > 0)
                    return false;
                if (const Value* v = find_slot(t.text)) {
                    if (!readable_when_deferred(*v)) return false;
                    reads.push_back(t.text);
                } else if (!is_keyword(t.text)) {
                    return false;  // undeclared: reading it now reports the mistake where it stands
                }
            }
        }
    };
    std::size_t end = begin;
    if (!scan_block(end)) return false;
    // Further textures are layers of the same declaration.
    if (tokens[begin].text == "texture")
        while (is_word(tokens[end], "texture"))
            if (!scan_block(end)) return false;
    // An operator after the value is a mistake the declaration reports where it stands.
    const Token& after = tokens[end];
    if (after.kind == TokenKind::Punct &&
        (after.text == "+" || after.text == "-" || after.text == "*" || after.text == "/"))
        return false;

    DeferredDeclaration d;
    d.name = id.text;
    d.where = id;
    d.file = m_file;
    // Both ends are tokens viewing the file's own text: the keyword and the last closing brace.
    d.start = LexStart{static_cast<std::size_t>(tokens[begin].text.data() - file.text.data()), tokens[begin].line,
                       tokens[begin].column};
    d.end = static_cast<std::size_t>(tokens[end - 1].text.end() - file.text.data());
    d.version = m_version;
    const auto index = static_cast<std::uint32_t>(m_deferred.size());
    m_deferred.push_back(std::move(d));
    declare(id.text, Deferred{index}, local);
    m_deferred_warnings.erase(id.text);
    for (const std::string_view name : reads) {
        std::vector<std::uint32_t>& readers = m_deferred_readers[std::string(name)];
        if (readers.empty() || readers.back() != index) readers.push_back(index);
    }
    m_pos = end;
    if (is_punct(peek_expr(), ";")) next();
    return true;
}

void Preprocessor::evaluate_deferred(Value& slot) {
    const std::uint32_t index = std::get<Deferred>(slot).index;
    m_deferred[index].pending = false;
    const DeferredDeclaration d = m_deferred[index];
    const SourceFile& source = *m_files[d.file];

    // The value is read from its own stream, lexed again from the file's text: its tokens keep their file, lines
    // and columns, so diagnostics point into the library file.
    auto stream = std::make_unique<SourceFile>();
    stream->path = source.path;
    stream->library = true;
    // Its lexical errors were reported when the file was first read.
    stream->tokens.reset(source.text, d.start, d.end, d.file, stream->path, stream->decoded, {});
    const auto stream_index = static_cast<std::uint32_t>(m_files.size());
    m_files.push_back(std::move(stream));

    const std::uint32_t saved_file = m_file;
    const std::size_t saved_pos = m_pos;
    const std::size_t saved_brace_depth = m_brace_depth;
    const std::size_t saved_open_braces = m_open_braces.size();
    const double saved_version = m_version;
    auto restore = [&] {
        --m_evaluating_deferred;
        m_file = saved_file;
        m_pos = saved_pos;
        m_brace_depth = saved_brace_depth;
        m_open_braces.resize(saved_open_braces);
        m_version = saved_version;
        if (m_files.size() == stream_index + 1) m_files.pop_back();
    };
    ++m_evaluating_deferred;
    m_file = stream_index;
    m_pos = 0;
    m_version = d.version;
    try {
        Value v = parse_rvalue();
        if (peek().kind != TokenKind::EndOfFile)
            fail(peek(), "unexpected " + describe_token(peek()) + " in a declaration");
        restore();
        slot = std::move(v);
    } catch (...) {
        restore();
        // Its error is reported at the value; name the declaration, which stays undeclared as it would have.
        if (!m_diagnostics.empty() && m_diagnostics.back().severity == Severity::Error)
            m_diagnostics.back().notes.insert(m_diagnostics.back().notes.begin(),
                                              "in the declaration of '" + d.name + "', read at its first use");
        for (auto& scope : m_scopes) {
            const auto found = scope.find(d.name);
            if (found != scope.end() && &found->second == &slot) {
                scope.erase(found);
                break;
            }
        }
        throw;
    }
}

void Preprocessor::evaluate_pending(std::uint32_t index) {
    if (!m_deferred[index].pending) return;
    const std::string name = m_deferred[index].name;
    for (auto it = m_scopes.rbegin(); it != m_scopes.rend(); ++it) {
        const auto found = it->find(name);
        if (found == it->end()) continue;
        if (const auto* d = std::get_if<Deferred>(&found->second); d != nullptr && d->index == index) {
            evaluate_deferred(found->second);
            return;
        }
    }
    m_deferred[index].pending = false;  // rebound or undefined before anything read it
}

void Preprocessor::before_rebinding(const std::string& name) {
    if (m_deferred_readers.empty()) return;
    const auto found = m_deferred_readers.find(name);
    if (found == m_deferred_readers.end()) return;
    const std::vector<std::uint32_t> readers = std::move(found->second);
    m_deferred_readers.erase(found);
    for (const std::uint32_t index : readers) evaluate_pending(index);
}

void Preprocessor::before_scope_ends(const NameMap<Value>& scope) {
    if (m_deferred_readers.empty()) return;
    std::vector<std::string> names;
    for (const auto& [name, value] : scope)
        if (m_deferred_readers.count(name) > 0) names.push_back(name);
    // In name order, not the table's (which follows the hash).
    std::sort(names.begin(), names.end());
    for (const std::string& name : names) before_rebinding(name);
}

void Preprocessor::evaluate_all_deferred() {
    for (std::uint32_t i = 0; i < m_deferred.size(); ++i) evaluate_pending(i);
    m_deferred_readers.clear();
}

}  // namespace wardray::parser
