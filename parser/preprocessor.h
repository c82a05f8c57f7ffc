// Preprocessor: POV-Ray's directives (#declare ... #fopen) and the declarations of library files read at first use.
#pragma once

#include <map>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "parser/token_stream.h"

namespace wardray::parser {

/// True for the primitive shape keywords the renderer draws (sphere ... superellipsoid).
bool is_shape_keyword(std::string_view word);
/// True when `t` starts an object (a shape, object, union, intersection, difference, merge, ...), which also
/// ends a failed directive's operands.
bool is_object_keyword(const Token& t);

/// Runs the directives the token stream meets (#declare/#local, #if/#while/#for/#switch, #include, #macro,
/// #fopen/#read/#write, #version, messages) and keeps the deferred declarations of library files; the values
/// directives read come from the evaluator above.
class Preprocessor : public TokenStream {
protected:
    using TokenStream::TokenStream;

    /// Runs the directive at the current token; when it fails, skips what is left of it (skip_failed_directive).
    void process_directive() final;
    /// Runs the directive `tok` (its name already consumed).
    void run_directive(const Token& tok);
    /// After a directive `tok` failed: returns to the macro/include depth, #if/#while nesting and brace depth it
    /// started at, and skips the rest of its operands (of an #if/#while/... its whole block), so the error is
    /// reported once and its #else/#end do not fail again.
    void skip_failed_directive(const Token& tok, std::size_t frames, std::size_t conds, std::size_t braces);
    /// #declare or #local (`local`).
    void directive_declare(const Token& tok, bool local);
    /// #if, #ifdef, #ifndef.
    void directive_if(const Token& tok);
    /// #while.
    void directive_while(const Token& tok);
    /// #for.
    void directive_for(const Token& tok);
    /// #end of a conditional, loop or switch.
    void directive_end(const Token& tok);
    /// #else, or #elseif when `elseif`.
    void directive_else(const Token& tok, bool elseif);
    /// #switch.
    void directive_switch(const Token& tok);
    /// #case or #range met while running a case (without #break it falls through).
    void directive_case(const Token& tok);
    /// #break.
    void directive_break(const Token& tok);
    /// #include.
    void directive_include(const Token& tok);
    /// #macro: records the definition and skips its body.
    void directive_macro(const Token& tok);
    /// #fopen, #read, #write, #fclose (file_io.cpp), confined to the folders ParseOptions allows.
    void directive_file_io(const Token& tok);
    /// `requested` as the scene names a file to read or write: a relative name is taken from the scene's folder.
    std::filesystem::path scene_relative(const std::filesystem::path& requested) const;
    /// Fails at `at` when `target` (a file the scene would write) lies outside the scene's folder and the write
    /// paths; the one check #fopen write/append and the save_file names of photons and radiosity go through.
    void require_writable(const Token& at, const std::filesystem::path& target);
    /// Sets an identifier as #read does: an existing one keeps its scope, a new one is global.
    void assign_existing_or_global(const std::string& name, Value v);
    /// Skips raw tokens of the current file until a directive in `stops` at nesting `depth` 0; returns it
    /// (consumed) or an EndOfFile token when the file ended first.
    Token skip_until(int depth, std::initializer_list<const char*> stops, const Token& opener);

    /// A library `#declare` whose value is read at the identifier's first use: where its value lies in its file,
    /// and the #version it was declared under.
    struct DeferredDeclaration {
        std::string name;
        Token where;  ///< the declared identifier
        std::uint32_t file = 0;
        LexStart start;
        std::size_t end = 0;  ///< byte offset just past the value
        double version = 3.7;
        bool pending = true;
    };
    /// At a declaration's value (just after '='): when the value is a pigment, finish, texture or colour map
    /// of a library file that reads only keywords and identifiers whose later rebinding can be detected, binds
    /// `id` to a Deferred, moves past the value and returns true.
    bool try_defer_declaration(const Token& id, bool local);
    void evaluate_deferred(Value& slot) final;
    /// Evaluates deferred declaration `index` if it is still pending and bound.
    void evaluate_pending(std::uint32_t index);
    void before_rebinding(const std::string& name) final;
    void before_scope_ends(const NameMap<Value>& scope) final;
    /// Evaluates every pending deferred declaration (before state they depend on changes, e.g. #default).
    void evaluate_all_deferred();

    /// #default (and the old `default` statement): the texture readers'.
    virtual void directive_default(const Token& tok) = 0;
    /// A float expression (the evaluator's).
    virtual double parse_float() = 0;
    /// A float or vector expression (the evaluator's).
    virtual Numeric parse_numeric() = 0;
    /// A string expression (the evaluator's).
    virtual std::string parse_string() = 0;
    /// Reads `[i][j]...` after an array identifier and returns the flat element index (the evaluator's).
    virtual std::size_t parse_array_index(const ArrayValue& array, const Token& id) = 0;

    std::vector<DeferredDeclaration> m_deferred;
    /// Identifier -> the pending deferred declarations whose value reads it.
    std::unordered_map<std::string, std::vector<std::uint32_t>> m_deferred_readers;
    /// Files written while writing is off (FileWrites::Discard): kept here so the scene can read them back.
    std::map<std::string, std::string> m_memory_files;
};

}  // namespace wardray::parser
