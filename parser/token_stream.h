// TokenStream: tokens as the readers see them (directives run, macros expanded), and the symbol scopes.
#pragma once

#include <initializer_list>
#include <set>
#include <string>
#include <unordered_map>
#include <vector>

#include "parser/source_stream.h"

namespace wardray::parser {

/// Reads tokens through the directive layer: a directive met is handed to process_directive, the end of an
/// include or macro returns to its caller. Holds the macros, the open #if/#while/... and the symbol scopes.
class TokenStream : public SourceStream {
protected:
    using SourceStream::SourceStream;

    /// An open #if / #while / #for / #switch.
    struct Cond {
        enum class Kind { If, While, For, Switch };
        Kind kind = Kind::If;
        Token where;
        std::size_t restart_pos = 0;  ///< #while: the directive token; #for: the first body token
        std::string ident;            ///< #for counter
        double end = 0.0;
        double step = 1.0;
        double switch_value = 0.0;
    };
    /// A #macro definition: its parameters and where its body lies.
    struct Macro {
        std::vector<std::string> params;
        std::vector<bool> optional;
        std::uint32_t file = 0;
        std::size_t body = 0;
        std::size_t end = 0;
        Token where;
    };

    /// The next token after running the directives before it. A copy: the chunk of the file it came from may be
    /// released while the caller still holds it (TokenStore). Inline for the common token that is neither a
    /// directive nor an end of file, so callers reading only its kind and text copy nothing.
    Token peek() {
        const Token& t = raw();
        if (t.kind != TokenKind::Directive && t.kind != TokenKind::EndOfFile) return t;
        return peek_directives();
    }
    /// As peek, inside a value: a directive at the value's own brace depth ends it instead of running.
    Token peek_expr() {
        const Token& t = raw();
        if (t.kind != TokenKind::Directive) return t;
        return peek_expr_directives();
    }
    /// peek() at a directive or an end of file.
    Token peek_directives();
    /// peek_expr() at a directive.
    Token peek_expr_directives();
    /// Consumes the next token, counting braces.
    Token next();
    /// Consumes the punctuation `punct` when it comes next.
    bool accept(std::string_view punct);
    /// Consumes the keyword `word` when it comes next.
    bool accept_keyword(std::string_view word);
    /// Consumes the punctuation `punct` or fails.
    Token expect(std::string_view punct);
    /// Consumes an identifier or fails.
    Token expect_identifier();
    /// Takes the ';' after a declaration; warns when a numeric declaration lacks it (3.5+). A second ';' may follow
    /// a numeric one (see m_numeric_declare_semicolon).
    void accept_semicolon_after_declare(const Value& v, const Token& where);
    /// True when `t` starts a string expression (a string, a string function or a string identifier).
    bool starts_string(const Token& t);
    /// Skips a balanced `{ ... }` after `kw` (directives inside still run).
    void skip_block(const Token& kw);
    /// Skips a `{ ... }` after `kw` when one comes next.
    void skip_optional_block(const Token& kw);

    /// Returns from the include or macro whose tokens ended.
    void handle_end_of_file();
    /// Copies the bodies of the macros file `index` defines into a stream of their own, so the file's tokens can
    /// be released.
    void keep_macro_bodies(std::uint32_t index);
    /// Reads the arguments of a call of `macro` at `name_tok` and starts reading its body.
    void invoke_macro(const Token& name_tok, const Macro& macro);
    /// Ends the macro being read: drops its scope and returns to the call site.
    void return_from_macro();
    /// Invokes macros standing where an item is expected, so their bodies are read in place.
    void expand_macros();
    /// Skips what is left of a failed statement down to brace depth `depth`.
    void recover_after_error(std::size_t depth);
    /// Counts one pass of a loop at `where`; false past the loop limit.
    bool count_loop_iteration(const Token& where);

    /// Finds an identifier, innermost scope first; using it releases the warnings deferred at its declaration and
    /// evaluates a deferred declaration.
    const Value* lookup(std::string_view name);
    /// As lookup, for a caller about to change the value in place.
    Value* lookup_mutable(const std::string& name);
    /// The binding of an identifier as stored (a Deferred stays deferred), innermost scope first; no side effects.
    Value* find_slot(std::string_view name);
    Value* find_slot(const HashedName& key);
    /// Binds `name` to `v` in the innermost (local) or the global scope.
    void declare(const std::string& name, Value v, bool local);
    /// Every declared identifier and macro name, for suggestions.
    std::vector<std::string> known_names() const;
    /// Reports `at` as undeclared, with the closest known name as a suggestion.
    [[noreturn]] void fail_undeclared(const Token& at);

    /// Runs the directive at the current token (the preprocessor's).
    virtual void process_directive() = 0;
    /// Reads any value: a float, vector, colour, string or declared item (the evaluator's).
    virtual Value parse_rvalue() = 0;
    /// Evaluates the deferred declaration held in `slot` and stores its value there.
    virtual void evaluate_deferred(Value& slot) = 0;
    /// Called before `name` is rebound, undefined or shadowed (deferred declarations reading it are evaluated).
    virtual void before_rebinding(const std::string& name) = 0;
    /// Called before a scope is dropped: the deferred declarations reading its names are evaluated first.
    virtual void before_scope_ends(const NameMap<Value>& scope) = 0;

    std::vector<Cond> m_conds;
    NameMap<Macro> m_macros;
    std::vector<NameMap<Value>> m_scopes;
    std::uint64_t m_loop_iterations = 0;
    /// Tokens consumed so far by next().
    std::uint64_t m_tokens_taken = 0;
    /// m_tokens_taken when the ';' ending a float, vector or colour declaration was consumed.
    std::uint64_t m_numeric_declare_semicolon = 0;
    /// Identifiers whose #declare failed: their uses are not errors again.
    std::set<std::string> m_failed_declarations;
    /// Deferred declarations being evaluated (nested when one reads another): their stream ends at its own end.
    std::size_t m_evaluating_deferred = 0;
};

}  // namespace wardray::parser
