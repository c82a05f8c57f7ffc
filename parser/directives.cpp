// The directive layer: #declare/#local, #if/#while/#for/#switch, #include, #macro, #version, #default.
#include <algorithm>
#include <cmath>

#include "core/constants.h"
#include "parser/keyword_table.h"
#include "parser/keywords.h"
#include "parser/parser.h"

namespace wardray::parser {

namespace {

bool is_opening_directive(const std::string& name) {
    return name == "if" || name == "ifdef" || name == "ifndef" || name == "while" || name == "for" ||
           name == "switch" || name == "macro";
}

}  // namespace

// ---------------------------------------------------------------------------------------------------------------
// Directives

Token Preprocessor::skip_until(int depth, std::initializer_list<const char*> stops, const Token& opener) {
    while (true) {
        const Token& t = raw();
        if (t.kind == TokenKind::EndOfFile) {
            report(make_diagnostic(Severity::Error, opener, "'#" + opener.text + "' has no matching #end"));
            return t;
        }
        ++m_pos;
        if (t.kind != TokenKind::Directive) continue;
        if (is_opening_directive(t.text)) {
            ++depth;
            continue;
        }
        if (depth > 0) {
            if (t.text == "end") --depth;
            continue;
        }
        for (const char* s : stops)
            if (t.text == s) return t;
    }
}

void Preprocessor::process_directive() {
    const Token tok = raw();
    // Directives read their operands through peek(), which runs the directives it meets: a loop that jumps
    // back while a directive waits for its operand (`#while (1) #declare S #end`) nests one call deeper on
    // every pass, so bound it like the descent (with its own count: recursive macros nest both).
    const NestingGuard guard(*this, tok, m_directive_nesting);
    ++m_pos;
    // POV-Ray compat: a directive's operands end at the next directive (`#switch (A) #case (0)`, the layers of a
    // declared texture); #default holds only blocks.
    const ScopedSetting operands(m_directive_ends_value_at, tok.text != "default" ? m_brace_depth : k_directives_run);
    const std::size_t frames = m_frames.size();
    const std::size_t conds = m_conds.size();
    const std::size_t braces = m_brace_depth;
    // A declaration's identifier, kept now: by the time its value fails, its tokens may be gone.
    const bool declaration = tok.text == "declare" || tok.text == "local";
    const Token declared = declaration ? raw() : Token{};
    try {
        run_directive(tok);
    } catch (const StatementError&) {
        // Its identifier stays undeclared: later uses of it are consequences, not new errors.
        if (declaration && declared.kind == TokenKind::Identifier) m_failed_declarations.insert(declared.text);
        skip_failed_directive(tok, frames, conds, braces);
        throw;
    }
}

void Preprocessor::skip_failed_directive(const Token& tok, std::size_t frames, std::size_t conds, std::size_t braces) {
    // Leave the macros and includes its operands entered, and the #if/#while/... they opened.
    while (m_frames.size() > frames) return_from_macro();
    if (m_conds.size() > conds) m_conds.resize(conds);
    const TokenText& name = tok.text;
    if (is_opening_directive(name) || name == "else" || name == "elseif") {
        // A block whose header failed is skipped whole, so its #else and #end do not fail again.
        skip_until(0, {"end"}, tok);
        m_brace_depth = braces;
        if (m_open_braces.size() > braces) m_open_braces.resize(braces);
        return;
    }
    if (m_brace_depth > braces) {
        // It failed inside a block of its value (`#declare O = sphere { 0, Undeclared }`): skip to its end.
        recover_after_error(braces);
        return;
    }
    // Skip the rest of its operands: through a ';', or up to the next directive, the enclosing '}' or the
    // next statement; the token it failed at is skipped in any case unless it ends the enclosing block.
    int depth = 0;
    for (bool first = true;; first = false) {
        const Token& t = raw();
        if (t.kind == TokenKind::EndOfFile || t.kind == TokenKind::Directive) return;
        if (depth == 0 && is_punct(t, "}")) return;
        if (!first && depth == 0 && t.kind == TokenKind::Identifier &&
            (is_object_keyword(t) || t.text == "camera" || t.text == "light_source" || t.text == "global_settings" ||
             t.text == "background" || t.text == "sky_sphere" || t.text == "fog"))
            return;
        ++m_pos;
        if (is_punct(t, "{")) ++depth;
        if (is_punct(t, "}")) --depth;
        if (depth == 0 && is_punct(t, ";")) return;
    }
}

void Preprocessor::run_directive(const Token& tok) {
    using Directive = void (*)(Preprocessor&, const Token&);
    auto file_io = [](Preprocessor& p, const Token& t) { p.directive_file_io(t); };
    auto message = [](Preprocessor& p, const Token&) {
        const std::string text = p.parse_string();
        if (p.m_options.debug_output) p.m_options.debug_output(text);
    };
    static const KeywordTable<Directive> directives = {
        {"declare", [](Preprocessor& p, const Token& t) { p.directive_declare(t, false); }},
        {"local", [](Preprocessor& p, const Token& t) { p.directive_declare(t, true); }},
        {"undef",
         [](Preprocessor& p, const Token&) {
             const Token id = p.expect_identifier();
             if (p.is_punct(p.peek_expr(), "[")) {
                 // `#undef A[i]`: the element becomes uninitialised again (POV-Ray's Remove_Symbol).
                 Value* target = p.lookup_mutable(id.text);
                 auto* array = target ? std::get_if<std::shared_ptr<ArrayValue>>(target) : nullptr;
                 if (array == nullptr) p.fail(id, "'" + id.text + "' is not an array");
                 const std::shared_ptr<ArrayValue> keep = *array;
                 keep->elements[p.parse_array_index(*keep, id)].reset();
                 return;
             }
             p.before_rebinding(id.text);
             bool erased = false;
             for (auto it = p.m_scopes.rbegin(); it != p.m_scopes.rend() && !erased; ++it)
                 erased = it->erase(id.text) > 0;
             if (!erased && p.m_macros.erase(id.text) == 0) p.warn(id, "Attempt to undef unknown identifier");
         }},
        {"if", [](Preprocessor& p, const Token& t) { p.directive_if(t); }},
        {"ifdef", [](Preprocessor& p, const Token& t) { p.directive_if(t); }},
        {"ifndef", [](Preprocessor& p, const Token& t) { p.directive_if(t); }},
        {"elseif", [](Preprocessor& p, const Token& t) { p.directive_else(t, true); }},
        {"else", [](Preprocessor& p, const Token& t) { p.directive_else(t, false); }},
        {"end", [](Preprocessor& p, const Token& t) { p.directive_end(t); }},
        {"while", [](Preprocessor& p, const Token& t) { p.directive_while(t); }},
        {"for", [](Preprocessor& p, const Token& t) { p.directive_for(t); }},
        {"switch", [](Preprocessor& p, const Token& t) { p.directive_switch(t); }},
        {"case", [](Preprocessor& p, const Token& t) { p.directive_case(t); }},
        {"range", [](Preprocessor& p, const Token& t) { p.directive_case(t); }},
        {"break", [](Preprocessor& p, const Token& t) { p.directive_break(t); }},
        {"include", [](Preprocessor& p, const Token& t) { p.directive_include(t); }},
        {"macro", [](Preprocessor& p, const Token& t) { p.directive_macro(t); }},
        {"version",
         [](Preprocessor& p, const Token&) {
             p.m_version = p.parse_float();
             p.m_version_given = true;
             if (p.is_punct(p.peek_expr(), ";")) p.next();
         }},
        {"debug", message},
        {"render", message},
        {"statistics", message},
        {"warning", [](Preprocessor& p, const Token& t) { p.warn(t, p.parse_string()); }},
        {"error",
         [](Preprocessor& p, const Token& t) {
             const std::string text = p.parse_string();
             p.report(p.make_diagnostic(Severity::Error, t, text));
             throw FatalError{};
         }},
        {"default", [](Preprocessor& p, const Token& t) { p.directive_default(t); }},
        {"fopen", file_io},
        {"fclose", file_io},
        {"read", file_io},
        {"write", file_io},
    };
    if (const Directive* directive = directives.find(tok.text)) {
        (*directive)(*this, tok);
        return;
    }
    fail(tok, "unknown directive '#" + tok.text + "'");
}

void Preprocessor::directive_case(const Token& tok) {
    // Reached while running a case: POV-Ray compat, a case without #break falls through.
    if (m_conds.empty() || m_conds.back().kind != Cond::Kind::Switch) fail(tok, "'#" + tok.text + "' outside #switch");
    expect("(");
    parse_float();
    if (tok.text == "range") {
        expect(",");
        parse_float();
    }
    expect(")");
}

void Preprocessor::directive_declare(const Token& tok, bool local) {
    if (is_word(peek(), "deprecated")) {
        // `#declare deprecated [once] "message" Name = ...`: the message is for users of Name; not shown here.
        next();
        accept_keyword("once");
        parse_string();
    }
    const Token id = expect_identifier();
    if (is_keyword(id.text) && !is_predeclared_identifier(id.text)) {
        // Reported, then the declaration is read and dropped so the error does not cascade.
        report(make_diagnostic(Severity::Error, id, "'" + id.text + "' is a reserved word and cannot be declared"));
        expect("=");
        const Value dropped = parse_rvalue();
        if (is_punct(peek_expr(), ";")) next();
        return;
    }
    if (is_punct(peek_expr(), "[")) {
        // Assignment to an element of an existing array.
        Value* target = lookup_mutable(id.text);
        auto* array = target ? std::get_if<std::shared_ptr<ArrayValue>>(target) : nullptr;
        if (target == nullptr) fail_undeclared(id);
        if (array == nullptr) fail(id, "'" + id.text + "' is not an array");
        const std::shared_ptr<ArrayValue> keep = *array;
        const std::size_t index = parse_array_index(*keep, id);
        expect("=");
        Value v = parse_rvalue();
        const bool numeric = std::holds_alternative<Numeric>(v);
        keep->elements[index] = std::move(v);
        if (numeric) accept_semicolon_after_declare(Numeric{}, id);
        else if (is_punct(peek_expr(), ";")) next();
        return;
    }
    expect("=");
    if (try_defer_declaration(id, local)) return;
    m_declaring.emplace_back();
    const std::size_t frames = m_frames.size();
    const std::size_t local_scope = m_scopes.size() - 1;
    Value v;
    try {
        v = parse_rvalue();
    } catch (...) {
        m_declaring.pop_back();
        throw;
    }
    std::vector<Diagnostic> deferred = std::move(m_declaring.back());
    m_declaring.pop_back();
    // POV-Ray compat: such a value ended at a directive inside a macro it called, and cannot go on from there.
    if (const Token& d = raw(); std::holds_alternative<Numeric>(v) && d.kind == TokenKind::Directive &&
                                m_frames.size() > frames)
        fail(d, "the value of '" + id.text + "' ends at '#" + d.text +
                    "' inside the macro it called (POV-Ray reads no directive between the operands of a declared "
                    "value); put the macro call in parentheses");
    // raw(), not peek_expr(): a macro's #end right here must not be read before the by-reference check below.
    if (const Token& op = raw(); !std::holds_alternative<Numeric>(v) && op.kind == TokenKind::Punct &&
                                       (op.text == "+" || op.text == "-" || op.text == "*" || op.text == "/"))
        fail(op, "'" + op.text + "' cannot be applied to " + value_kind_name(v));
    if (deferred.empty())
        m_deferred_warnings.erase(id.text);
    else
        m_deferred_warnings[id.text] = std::move(deferred);
    if (auto* array = std::get_if<std::shared_ptr<ArrayValue>>(&v)) {
        // POV-Ray compat: declaring from another array copies it.
        *array = std::make_shared<ArrayValue>(**array);
    }
    const bool numeric = std::holds_alternative<Numeric>(v);
    // POV-Ray compat: #local on a by-reference parameter also writes through, since the parameter lives in the
    // macro's own table (macro4.pov: `#local V = V + 1;`). The frame is the one the #declare stands in: a value
    // from a macro can end inside that macro's body (tracevines.pov: `Q;` in `#if ... Q; #else ... #end`).
    if (frames > 0 && m_frames[frames - 1].kind == Frame::Kind::Macro) {
        const Frame& frame = m_frames[frames - 1];
        if (const auto ref = frame.references.find(id.text); ref != frame.references.end()) {
            // A by-reference parameter: update the caller's identifier and the parameter itself.
            const auto& [scope, name] = ref->second;
            before_rebinding(name);
            before_rebinding(id.text);
            if (scope < m_scopes.size()) m_scopes[scope][name] = v;
            m_scopes[frame.scope_index][id.text] = std::move(v);
            if (numeric) accept_semicolon_after_declare(Numeric{}, id);
            else if (is_punct(peek_expr(), ";")) next();
            return;
        }
    }
    if (local && m_frames.size() > frames) {
        before_rebinding(id.text);
        m_scopes[local_scope][id.text] = std::move(v);
    } else
        declare(id.text, std::move(v), local);
    if (numeric) {
        accept_semicolon_after_declare(Numeric{}, id);
    } else if (is_punct(peek_expr(), ";")) {
        next();
    }
}

void Preprocessor::directive_if(const Token& tok) {
    bool cond = false;
    if (tok.text == "if") {
        cond = parse_float() != 0.0;
    } else {
        expect("(");
        const Token id = expect_identifier();
        const Value* v = lookup(id.text);
        cond = v != nullptr || m_macros.count(id.text) > 0;
        if (const auto* array = v ? std::get_if<std::shared_ptr<ArrayValue>>(v) : nullptr) {
            if (is_punct(peek_expr(), "[")) cond = (*array)->elements[parse_array_index(**array, id)].has_value();
        }
        expect(")");
        if (tok.text == "ifndef") cond = !cond;
    }
    while (true) {
        if (cond) {
            Cond c;
            c.kind = Cond::Kind::If;
            c.where = tok;
            m_conds.push_back(std::move(c));
            return;
        }
        const Token stop = skip_until(0, {"else", "elseif", "end"}, tok);
        if (stop.kind == TokenKind::EndOfFile || stop.text == "end") return;
        cond = stop.text == "else" ? true : parse_float() != 0.0;
    }
}

void Preprocessor::directive_else(const Token& tok, bool elseif) {
    const std::size_t floor = m_frames.empty() ? 0 : m_frames.back().cond_depth;
    if (m_conds.size() > floor && m_conds.back().kind == Cond::Kind::Switch && !elseif) return;  // falls through
    if (m_conds.size() <= floor || m_conds.back().kind != Cond::Kind::If)
        fail(tok, "'#" + tok.text + "' without matching #if");
    // The taken branch ended: skip the remaining branches.
    const Token opener = m_conds.back().where;
    m_conds.pop_back();
    skip_until(0, {"end"}, opener);
}

void Preprocessor::directive_end(const Token& tok) {
    const std::size_t floor = m_frames.empty() ? 0 : m_frames.back().cond_depth;
    if (m_conds.size() <= floor) {
        if (!m_frames.empty() && m_frames.back().kind == Frame::Kind::Macro) {
            return_from_macro();
            return;
        }
        fail(tok, "#end without matching #if, #while, #for, #switch or #macro");
    }
    Cond& c = m_conds.back();
    switch (c.kind) {
        case Cond::Kind::If:
        case Cond::Kind::Switch:
            m_conds.pop_back();
            return;
        case Cond::Kind::While: {
            // Re-read the #while directive, which evaluates its condition again.
            const std::size_t restart = c.restart_pos;
            m_conds.pop_back();
            m_pos = restart;
            return;
        }
        case Cond::Kind::For: {
            const Value* counter = lookup(c.ident);
            const Numeric* n = counter ? std::get_if<Numeric>(counter) : nullptr;
            if (n == nullptr || n->n != 1) {
                const Token where = c.where;
                m_conds.pop_back();
                fail(where, "#for counter '" + where.text + "' must stay a float");
            }
            const double value = n->v[0] + c.step;
            declare(c.ident, Numeric::scalar(value), true);
            // POV-Ray compat: the end is widened by 1e-10, so a sum of fractional steps that rounds just past it
            // (2.6 + 5 * 0.4 = 4.6000000000000005) still runs the last pass.
            if (c.step > 0 ? !(value > c.end + kPovEpsilon) : !(value < c.end - kPovEpsilon)) {
                count_loop_iteration(c.where);
                m_pos = c.restart_pos;
            } else {
                m_conds.pop_back();
            }
            return;
        }
    }
}

void Preprocessor::directive_while(const Token& tok) {
    const std::size_t directive_pos = m_pos - 1;
    const double cond = parse_float();
    if (cond == 0.0) {
        skip_until(0, {"end"}, tok);
        return;
    }
    count_loop_iteration(tok);
    Cond c;
    c.kind = Cond::Kind::While;
    c.where = tok;
    c.restart_pos = directive_pos;
    m_conds.push_back(std::move(c));
}

void Preprocessor::directive_for(const Token& tok) {
    expect("(");
    const Token id = expect_identifier();
    expect(",");
    const double start = parse_float();
    expect(",");
    const double end = parse_float();
    double step = 1.0;
    if (accept(",")) step = parse_float();
    expect(")");
    if (!(std::fabs(step) >= kPovEpsilon)) fail(tok, "#for step must not be zero");
    declare(id.text, Numeric::scalar(start), true);
    if (!(step > 0 ? start < end + kPovEpsilon : start > end - kPovEpsilon)) {
        skip_until(0, {"end"}, tok);
        return;
    }
    Cond c;
    c.kind = Cond::Kind::For;
    c.where = tok;
    c.ident = id.text;
    c.end = end;
    c.step = step;
    c.restart_pos = m_pos;
    m_conds.push_back(std::move(c));
}

void Preprocessor::directive_switch(const Token& tok) {
    const double value = parse_float();
    Cond c;
    c.kind = Cond::Kind::Switch;
    c.where = tok;
    c.switch_value = value;
    m_conds.push_back(std::move(c));
    // Find the first clause that matches; the body then runs until #break or the switch's #end.
    while (true) {
        const Token stop = skip_until(0, {"case", "range", "else", "end"}, tok);
        if (stop.kind == TokenKind::EndOfFile || stop.text == "end") {
            m_conds.pop_back();
            return;
        }
        if (stop.text == "else") return;
        expect("(");
        const double a = parse_float();
        bool match = false;
        if (stop.text == "case") {
            // POV-Ray compat: #case compares with the same tolerance as '='.
            match = std::fabs(a - value) < kPovEpsilon;
        } else {
            expect(",");
            const double b = parse_float();
            match = a <= value && value <= b;
        }
        expect(")");
        if (match) return;
    }
}

void Preprocessor::directive_break(const Token& tok) {
    const std::size_t floor = m_frames.empty() ? 0 : m_frames.back().cond_depth;
    std::size_t target = m_conds.size();
    for (std::size_t i = m_conds.size(); i > floor; --i) {
        if (m_conds[i - 1].kind != Cond::Kind::If) {
            target = i - 1;
            break;
        }
    }
    if (target == m_conds.size()) fail(tok, "#break outside #switch, #while or #for");
    const int open_ifs = static_cast<int>(m_conds.size() - target - 1);
    const Token opener = m_conds[target].where;
    m_conds.resize(target);
    skip_until(open_ifs, {"end"}, opener);
}

void Preprocessor::directive_include(const Token& tok) {
    const Token name_tok = peek();
    const std::string name = parse_string();
    std::size_t include_depth = 0;
    for (const Frame& f : m_frames) include_depth += f.kind == Frame::Kind::Include ? 1 : 0;
    if (include_depth >= m_options.max_include_depth) {
        report(make_diagnostic(Severity::Error, tok,
                               "#include files nest deeper than the limit of " +
                                   std::to_string(m_options.max_include_depth) +
                                   " (recursive #include?); raise it with --max-include-depth"));
        throw FatalError{};
    }
    const std::filesystem::path requested(name);
    const std::vector<SearchCandidate> candidates = search_candidates(requested, ".inc");
    std::optional<std::uint32_t> index;
    std::string error = "No such file or directory";
    for (const SearchCandidate& c : candidates) {
        std::error_code ec;
        if (!std::filesystem::is_regular_file(c.path, ec)) continue;
        require_readable(name_tok, c.path, "include file");
        // A library file is one found through the library paths, or beside the library file including it.
        index = load_file(c.path, c.library, error);
        if (!index) continue;
        if (c.beyond_povray)
            warn(name_tok, "'" + name + "' is found only beside the file including it, where POV-Ray does not look "
                           "(it looks in the current folder and the library paths)");
        break;
    }
    if (!index) {
        Diagnostic d = make_diagnostic(Severity::Error, name_tok, "cannot open include file '" + name + "': " + error);
        std::string searched;
        std::vector<std::string> folders;
        for (const auto& c : candidates) {
            const std::string folder = c.path.parent_path().empty() ? "." : c.path.parent_path().string();
            if (std::find(folders.begin(), folders.end(), folder) == folders.end()) folders.push_back(folder);
        }
        for (const auto& f : folders) searched += (searched.empty() ? "" : ", ") + f;
        d.notes.insert(d.notes.begin(), "searched " + searched);
        report(std::move(d));
        throw StatementError{};
    }
    Frame frame;
    frame.kind = Frame::Kind::Include;
    frame.name = name;
    frame.return_file = m_file;
    frame.return_pos = m_pos;
    frame.call_site = tok;
    frame.cond_depth = m_conds.size();
    m_frames.push_back(std::move(frame));
    m_scopes.emplace_back();
    m_file = *index;
    m_pos = 0;
}

void Preprocessor::directive_macro(const Token& tok) {
    const Token id = expect_identifier();
    Macro macro;
    macro.where = id;
    expect("(");
    if (!accept(")")) {
        while (true) {
            bool optional = false;
            if (is_word(peek(), "optional")) {
                next();
                optional = true;
            }
            macro.params.push_back(expect_identifier().text);
            macro.optional.push_back(optional);
            // POV-Ray compat: the commas between parameters are optional and a trailing one is accepted
            // (shapes3.inc has both).
            accept(",");
            if (accept(")")) break;
        }
    }
    macro.file = m_file;
    macro.body = m_pos;
    m_files[m_file]->has_macros = true;
    // Every call reads the body again: its tokens stay in memory (from here to its #end, once that is found).
    TokenStore& tokens = m_files[m_file]->tokens;
    const std::size_t pin = tokens.pin(macro.body);
    const Token stop = skip_until(0, {"end"}, tok);
    if (stop.kind == TokenKind::EndOfFile) return;
    macro.end = m_pos - 1;
    tokens.pin_end(pin, macro.end);
    m_macros[id.text] = std::move(macro);
}

}  // namespace wardray::parser
