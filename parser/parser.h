// Parser: the recursive-descent reader of POV-Ray SDL over a re-readable token stream with a directive layer.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <unordered_map>
#include <vector>

#include "parser/lexer.h"
#include "parser/parse.h"
#include "parser/value.h"

namespace wardray::parser {

class TrueTypeFont;

/// One source file read by the parse, with its tokens (kept alive so macros and loops can re-read them).
struct SourceFile {
    std::string path;  ///< as shown in diagnostics
    std::string text;
    std::vector<Token> tokens;
    DecodedStrings decoded;  ///< string literals with escapes, which tokens view
    bool truncated = false;  ///< the lexer gave up early (unterminated string): errors at its end are noise
    bool library = false;    ///< found through the library paths: its declarations may be deferred
    bool has_macros = false; ///< defines a macro, whose body is read from `tokens` at every call
    mutable std::vector<std::size_t> line_starts;  ///< offset of each line, built on the first diagnostic

    /// The text of line `line` (from 1) without its line ending, found through the line index.
    std::string line_text(std::uint32_t line) const;
};

/// Reads a whole file into `text` with one copy; false with the reason in `error` when it cannot be read.
bool read_text_file(const std::filesystem::path& path, std::string& text, std::string& error);

/// Thrown inside the parser to abandon the current statement after an error was reported.
struct StatementError {};
/// Thrown inside the parser to end the whole parse (error limit, #error, runaway recursion).
struct FatalError {};

/// How a token reads in a message: 'word', string "text", '#directive' or end of file.
std::string describe_token(const Token& t);
/// True for the primitive shape keywords the renderer draws (sphere ... superellipsoid).
bool is_shape_keyword(std::string_view word);
/// A spline's value at `t` interpolated with `type`, with as many components as the spline's values have (at
/// least two), as a call `S(t)` returns it.
Numeric spline_value(const Spline& spline, Spline::Type type, double t);
/// "a pigment", "an object", ... for messages about identifiers of the wrong kind.
const char* value_kind_name(const Value& v);

/// Parses one scene; use once. Internal to parser/: other layers call parse_file / parse_string.
class Parser {
public:
    /// A parser reading with `options` (library paths, declares, image size, error limit).
    explicit Parser(const ParseOptions& options);

    /// Parses `text` as the main scene file named `path`; never throws.
    ParseResult run(std::string text, const std::string& path);

private:
    // --- token stream and directive layer (directives.cpp) ---
    /// A file or macro being read, with where to return when it ends.
    struct Frame {
        enum class Kind { Include, Macro };
        Kind kind = Kind::Include;
        std::string name;
        std::uint32_t return_file = 0;
        std::size_t return_pos = 0;
        Token call_site;
        std::size_t cond_depth = 0;
        std::size_t scope_index = 0;  ///< the macro's own symbol table
        /// Macro parameters given a bare identifier: #declare on them writes that identifier (by reference).
        std::unordered_map<std::string, std::pair<std::size_t, std::string>> references;
    };
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

    const Token& raw() const { return m_files[m_file]->tokens[m_pos]; }
    const Token& peek();
    const Token& peek_expr();
    Token next();
    bool accept(std::string_view punct);
    bool accept_keyword(std::string_view word);
    Token expect(std::string_view punct);
    Token expect_identifier();
    // Inline, taking views: most callers pass literals, whose length is then known where they are compared.
    bool is_punct(const Token& t, std::string_view p) const { return t.kind == TokenKind::Punct && t.text == p; }
    bool is_word(const Token& t, std::string_view w) const { return t.kind == TokenKind::Identifier && t.text == w; }
    void accept_semicolon_after_declare(const Value& v, const Token& where);

    /// Runs the directive at the current token; when it fails, skips what is left of it (skip_failed_directive).
    void process_directive();
    void run_directive(const Token& tok);
    /// After a directive `tok` failed: returns to the macro/include depth, #if/#while nesting and brace depth it
    /// started at, and skips the rest of its operands (of an #if/#while/... its whole block), so the error is
    /// reported once and its #else/#end do not fail again.
    void skip_failed_directive(const Token& tok, std::size_t frames, std::size_t conds, std::size_t braces);
    void directive_declare(const Token& tok, bool local);
    void directive_if(const Token& tok);
    void directive_while(const Token& tok);
    void directive_for(const Token& tok);
    void directive_end(const Token& tok);
    void directive_else(const Token& tok, bool elseif);
    void directive_switch(const Token& tok);
    void directive_break(const Token& tok);
    void directive_include(const Token& tok);
    /// Where a file named in the scene is looked for, in order: the reading file's folder, then the library paths;
    /// a name without extension is then tried with `extension` in the same places.
    std::vector<std::filesystem::path> search_candidates(const std::filesystem::path& requested,
                                                         const char* extension) const;
    void directive_macro(const Token& tok);
    void directive_default(const Token& tok);
    /// #fopen, #read, #write, #fclose (file_io.cpp), confined to the folders ParseOptions allows.
    void directive_file_io(const Token& tok);
    /// Sets an identifier as #read does: an existing one keeps its scope, a new one is global.
    void assign_existing_or_global(const std::string& name, Value v);
    /// Skips raw tokens of the current file until a directive in `stops` at nesting `depth` 0; returns it
    /// (consumed) or an EndOfFile token when the file ended first.
    Token skip_until(int depth, std::initializer_list<const char*> stops, const Token& opener);
    void handle_end_of_file();
    /// Copies the bodies of the macros file `index` defines into a stream of their own, so the file's tokens can
    /// be released.
    void keep_macro_bodies(std::uint32_t index);
    /// Lexes a file's text into its tokens; the first time, its lexical errors are reported.
    void lex_file(std::uint32_t index, bool first);
    /// Reads and lexes a file once (a second #include of it reuses the tokens); `library` marks a file found
    /// through the library paths.
    std::optional<std::uint32_t> load_file(const std::filesystem::path& path, bool library, std::string& error);
    void invoke_macro(const Token& name_tok, const Macro& macro);
    void return_from_macro();
    /// Invokes macros standing where an item is expected, so their bodies are read in place.
    void expand_macros();
    void recover_after_error(std::size_t depth);
    bool count_loop_iteration(const Token& where);

    // --- symbols ---
    /// Finds an identifier, innermost scope first; using it releases the warnings deferred at its declaration and
    /// evaluates a deferred declaration.
    const Value* lookup(const std::string& name);
    /// As lookup, for a caller about to change the value in place.
    Value* lookup_mutable(const std::string& name);
    /// The binding of an identifier as stored (a Deferred stays deferred), innermost scope first; no side effects.
    Value* find_slot(const std::string& name);

    // --- deferred declarations (deferred.cpp) ---
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
    /// Evaluates the deferred declaration held in `slot` and stores its value there.
    void evaluate_deferred(Value& slot);
    /// Evaluates deferred declaration `index` if it is still pending and bound.
    void evaluate_pending(std::uint32_t index);
    /// Called before `name` is rebound, undefined or shadowed: evaluates the deferred declarations that read it,
    /// so they see the binding they were written against.
    void before_rebinding(const std::string& name);
    /// Called before a scope is dropped: the deferred declarations reading its names are evaluated first.
    void before_scope_ends(const std::unordered_map<std::string, Value>& scope);
    /// Evaluates every pending deferred declaration (before state they depend on changes, e.g. #default).
    void evaluate_all_deferred();
    std::vector<DeferredDeclaration> m_deferred;
    /// Identifier -> the pending deferred declarations whose value reads it.
    std::unordered_map<std::string, std::vector<std::uint32_t>> m_deferred_readers;
    /// Deferred declarations being evaluated (nested when one reads another): their stream ends at its own end.
    std::size_t m_evaluating_deferred = 0;
    // --- arrays (arrays.cpp) ---
    Value parse_array_declaration(const Token& kw);
    void parse_array_initializer(ArrayValue& array, std::size_t dim, std::size_t offset, const Token& kw);
    /// Reads `[i][j]...` after an array identifier and returns the flat element index.
    std::size_t parse_array_index(const ArrayValue& array, const Token& id);
    /// When an array element `A[i]...` comes next, consumes it and returns a copy of its value.
    std::optional<Value> take_array_element();
    bool is_array_element_next();
    void declare(const std::string& name, Value v, bool local);
    std::vector<std::string> known_names() const;

    // --- diagnostics (parse.cpp) ---
    Diagnostic make_diagnostic(Severity s, const Token& at, std::string message) const;
    void report(Diagnostic d);
    [[noreturn]] void fail(const Token& at, std::string message);
    void warn(const Token& at, std::string message);
    void warn_unsupported(const Token& at, const std::string& feature);
    [[noreturn]] void fail_undeclared(const Token& at);

    // --- expressions (expression.cpp) ---
    Value parse_rvalue();
    Numeric parse_numeric();
    double parse_float();
    Vec3 parse_vector();
    std::string parse_string();
    bool parse_bool_optional();
    /// `?:` and below; `allow_less` is false outside parentheses, where '<' starts the next vector.
    Numeric parse_conditional(bool allow_less = true);
    Numeric parse_logical(bool allow_less);
    Numeric parse_relational(bool allow_less);
    /// The additive level; `first`, when given, is an operand already read (an array element).
    Numeric parse_additive(std::optional<Numeric> first = std::nullopt);
    Numeric parse_multiplicative(std::optional<Numeric> first = std::nullopt);
    Numeric parse_unary(std::optional<Numeric> first = std::nullopt);
    Numeric parse_postfix(std::optional<Numeric> first = std::nullopt);
    Numeric parse_primary();
    Numeric parse_function(const Token& name);
    std::optional<Numeric> builtin_constant(const Token& t);
    /// trace(), inside(), min_extent(), max_extent() through ParseOptions::query (functions.cpp).
    Numeric parse_geometry_query(const Token& name);

    // --- user functions (function_compiler.cpp) ---
    /// Reads `[(params)] { body }` after the keyword `function` and compiles it.
    std::shared_ptr<const UserFunction> parse_user_function(const Token& kw);
    /// A warning shown once per parse for each distinct message.
    void warn_once(const Token& at, const std::string& message);
    /// Reads the argument list of a call of `f` and evaluates it at parse time.
    Numeric call_user_function(const Token& name, const UserFunction& f);
    friend class FunctionCompiler;
    bool starts_string(const Token& t);

    // --- splines (splines.cpp) ---
    /// Reads `{ [S] [type] T, value ... }` after the keyword `spline`.
    Spline parse_spline_body(const Token& kw);
    /// Reads `(t [, type])` after a spline identifier and evaluates the spline.
    Numeric call_spline(const Token& name, const Spline& spline);
    /// Warns (once per message) when `type` has too few of the spline's points to interpolate as its name says.
    void warn_few_spline_points(const Token& at, const Spline& spline, Spline::Type type);

    // --- appearance (appearance.cpp) ---
    Color parse_color();
    bool is_color_keyword(const Token& t) const;
    Pigment parse_pigment_body(const Token& kw);
    Finish parse_finish_body(const Token& kw);
    Texture parse_texture_body(const Token& kw);
    void parse_finish_item(Finish& f, const Token& item);
    /// Reads texture items up to `close` ('}' of a texture block or ']' of a texture_map entry).
    void parse_texture_items(Texture& tx, const Token& kw, const char* close);
    Interior parse_interior_body(const Token& kw);
    SkySphere parse_sky_sphere(const Token& kw);
    Fog parse_fog(const Token& kw);
    /// Reads `reflection { ... }` into the finish.
    void parse_reflection_block(Finish& f);

    // --- patterns (patterns.cpp) ---
    /// True when `t` can start a float, vector or colour expression.
    bool starts_value(const Token& t);
    /// Consumes tokens up to and including `close` at brace depth `depth`.
    void skip_to_close(const Token& kw, const char* close, std::size_t depth);
    /// Reads a pattern keyword and its own parameters into `pat`: -1 when `t` is not one, else the length of the
    /// list of colours/pigments/textures that may follow it (2 for checker and brick, 3 for hexagon, 0 for others).
    int parse_pattern_keyword(const Token& t, Pattern& pat);
    /// Reads one pattern modifier (turbulence, frequency, wave type, transform, ...); false when `t` is none.
    bool parse_pattern_modifier(const Token& t, Pattern& pat);
    std::vector<ColorMapEntry> parse_color_map(const Token& kw);
    std::vector<PigmentMapEntry> parse_pigment_map(const Token& kw);
    /// Takes a leading pigment identifier or array element, when one comes next.
    bool parse_pigment_start(Pigment& p);
    void parse_pigment_list(Pigment& p, int count);
    /// Reads pigment items up to `close` ('}' of a pigment block or ']' of a pigment_map entry).
    void parse_pigment_items(Pigment& p, const Token& kw, const char* close);
    Normal parse_normal_body(const Token& kw);
    void parse_normal_items(Normal& n, const Token& kw, const char* close);
    void skip_block(const Token& kw);
    void skip_optional_block(const Token& kw);

    // --- statements (statements.cpp) ---
    void parse_statement();
    bool is_object_keyword(const Token& t) const;
    ObjectValue parse_object(const Token& kw);
    void parse_object_modifiers(ObjectValue& ov, bool compound);
    bool parse_transform_item(const Token& t, Transform& out);
    Transform parse_transform_body(const Token& kw);
    void apply_transform(ObjectValue& ov, const Transform& tr);
    Light parse_light_body(const Token& kw);
    CameraSpec parse_camera_body(const Token& kw);
    void parse_global_settings(const Token& kw);
    void parse_radiosity(const Token& kw, RadiositySettings& rad);
    void place_object(ObjectValue ov);
    Texture& texture_to_modify(ObjectValue& ov);
    /// An object statement's value as one Object: a union node when it holds several parts (or a union).
    std::optional<Object> as_single_object(ObjectValue& ov);
    /// Turns a flattened union into one union node (for inverse, clipped_by).
    void make_union_node(ObjectValue& ov);
    /// Reads `{ object ... }` (clipped_by, bounded_by) into Objects.
    std::vector<Object> parse_object_list(const Token& kw, const std::vector<Object>* bounded_by);

    // --- shapes (shapes.cpp) ---
    /// Reads a primitive's parameters after its '{' (the modifiers follow) with the keyword's reader.
    Shape parse_shape_parameters(const Token& kw);
    /// One reader per keyword of WARDRAY_SHAPES (scene/shapes.h): `Sphere read_sphere(const Token& kw)`, ...
#define WARDRAY_SHAPE_READER(keyword, Type) Type read_##keyword(const Token& kw);
    WARDRAY_SHAPES(WARDRAY_SHAPE_READER)
#undef WARDRAY_SHAPE_READER
    void parse_triangle(Mesh& mesh, bool smooth);
    /// Reads `ttf "font" "string" thickness, offset` and lays the glyphs out (the font through the library path).
    Text parse_text_parameters(const Token& kw);
    Lathe parse_lathe_parameters(const Token& kw);
    Sor parse_sor_parameters(const Token& kw);
    Mesh parse_mesh_body(const Token& kw);
    Mesh parse_mesh2_body(const Token& kw);
    template <typename F>
    void parse_counted_list(const Token& kw, F read_item);

    /// The deepest nesting of blocks and expressions the descent follows.
    static constexpr std::size_t k_max_nesting = 400;
    /// The most stack the descent may use: frames are larger in sanitizer and debug builds, where 400 levels
    /// can exceed the default 8 MiB stack, so the guard also measures the stack itself.
    static constexpr std::ptrdiff_t k_max_stack_bytes = std::ptrdiff_t{4} << 20;
    /// Bounds the recursion of the descent so deeply nested input ends in an error, not a stack overflow.
    class NestingGuard {
    public:
        NestingGuard(Parser& parser, const Token& at) : NestingGuard(parser, at, parser.m_nesting) {}
        /// Counts in `depth` instead of the descent's own counter.
        NestingGuard(Parser& parser, const Token& at, std::size_t& depth);
        ~NestingGuard() { --m_depth; }
        NestingGuard(const NestingGuard&) = delete;
        NestingGuard& operator=(const NestingGuard&) = delete;

    private:
        Parser& m_parser;
        std::size_t& m_depth;
    };
    friend class NestingGuard;
    std::size_t m_nesting = 0;
    /// POV-Ray compat: while a directive reads its operands (a #declare's value included) and while a float,
    /// vector or colour value reads its operators, the brace depth they started at; a directive met at that depth
    /// ends what is being read. Blocks opened inside (objects, pigments, ...) and the inside of an operand ('(',
    /// '<', a call: k_directives_run) run directives as they come.
    static constexpr std::size_t k_directives_run = static_cast<std::size_t>(-1);
    std::size_t m_directive_ends_value_at = k_directives_run;
    /// Sets a variable for a scope and puts its old value back at the end, or earlier through restore().
    class ScopedSetting {
    public:
        ScopedSetting(std::size_t& setting, std::size_t value) : m_setting(setting), m_old(setting) {
            setting = value;
        }
        ~ScopedSetting() { restore(); }
        ScopedSetting(const ScopedSetting&) = delete;
        ScopedSetting& operator=(const ScopedSetting&) = delete;
        void restore() { m_setting = m_old; }

    private:
        std::size_t& m_setting;
        std::size_t m_old;
    };
    std::size_t m_directive_nesting = 0;  ///< directives running inside another directive's operands
    const char* m_stack_base = nullptr;   ///< the stack address where this parser was made

    const ParseOptions& m_options;
    std::vector<std::unique_ptr<SourceFile>> m_files;
    std::map<std::string, std::uint32_t> m_file_index;  ///< resolved path -> index, so re-includes do not re-lex
    std::uint32_t m_file = 0;
    std::size_t m_pos = 0;
    std::size_t m_brace_depth = 0;  ///< '{' minus '}' consumed so far, for error recovery
    std::vector<Token> m_open_braces;  ///< the '{' tokens not closed yet, innermost last
    /// Files written while writing is off (FileWrites::Discard): kept here so the scene can read them back.
    std::map<std::string, std::string> m_memory_files;
    std::vector<Frame> m_frames;
    std::vector<Cond> m_conds;
    std::vector<std::unordered_map<std::string, Value>> m_scopes;
    std::unordered_map<std::string, Macro> m_macros;
    std::vector<Diagnostic> m_diagnostics;
    std::size_t m_errors = 0;
    /// Identifiers whose #declare failed: their uses are not errors again.
    std::set<std::string> m_failed_declarations;
    std::set<std::string> m_warned_features;
    /// Unsupported-feature warnings met while declaring an identifier: shown only when the identifier is used,
    /// so unused declarations of include files cost nothing.
    std::unordered_map<std::string, std::vector<Diagnostic>> m_deferred_warnings;
    std::vector<std::vector<Diagnostic>> m_declaring;  ///< warnings collected by the declarations being parsed
    void emit_feature_warning(Diagnostic d);
    std::uint64_t m_loop_iterations = 0;
    std::vector<std::uint32_t> m_rand_streams;  ///< states of the streams seed() created
    double m_version = 3.7;
    bool m_version_given = false;  ///< a #version was read (in any file): POV-Ray then stops assuming 3.62
    bool m_charset_utf8 = false;  ///< global_settings { charset utf8 }: text strings are decoded as UTF-8
    /// Fonts read so far, by resolved path; POV-Ray keeps each font's glyph cache for the whole scene.
    std::map<std::string, std::shared_ptr<TrueTypeFont>> m_fonts;
    Pigment m_default_pigment;
    Finish m_default_finish;
    /// A texture made of the current #default pigment and finish.
    Texture default_texture() const {
        Texture t;
        t.pigment = m_default_pigment;
        t.finish = m_default_finish;
        return t;
    }
    unsigned m_finish_albedo = 0;  ///< finish items given with `albedo` in the block being read (bits: diffuse, phong, specular)
    Scene m_scene;
};

}  // namespace wardray::parser
