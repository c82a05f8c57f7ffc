// SourceStream: the files a parse reads, the position in their tokens, and the diagnostics it reports.
#pragma once

#include <algorithm>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "core/large_stack.h"
#include "parser/lexer.h"
#include "parser/parse.h"
#include "parser/read_access.h"
#include "parser/token_store.h"
#include "parser/value.h"

namespace wardray::parser {

/// An identifier with its hash, computed once for a lookup that searches several tables (the scopes).
struct HashedName {
    std::string_view name;
    std::size_t hash;
};

/// The hash of an identifier, inline: a few multiplications over at most two overlapping loads for the short names
/// scenes use (a lookup hashes every identifier the parse reads, and libstdc++'s string hash is an out-of-line call
/// several times as long). Not a stable value: only the tables' bucket order depends on it.
inline std::size_t name_hash(std::string_view s) {
    const auto* p = reinterpret_cast<const unsigned char*>(s.data());
    const std::size_t n = s.size();
    const auto load8 = [](const unsigned char* q) {
        std::uint64_t w;
        std::memcpy(&w, q, sizeof w);
        return w;
    };
    const auto load4 = [](const unsigned char* q) {
        std::uint32_t w;
        std::memcpy(&w, q, sizeof w);
        return std::uint64_t{w};
    };
    const auto mix = [](std::uint64_t h, std::uint64_t w) {
        h = (h ^ w) * 0x9E3779B97F4A7C15ULL;
        return h ^ (h >> 32);
    };
    // The length is mixed in first, spread over every bit: names that differ in length and first byte alone would
    // otherwise cancel out.
    std::uint64_t h = mix(0xD6E8FEB86659FD93ULL, n);
    if (n >= 8) {
        // Whole words, then the last eight bytes (overlapping the previous word when n is not a multiple of 8).
        std::size_t i = 0;
        for (; i + 8 < n; i += 8) h = mix(h, load8(p + i));
        h = mix(h, load8(p + n - 8));
    } else if (n >= 4) {
        h = mix(h, load4(p) << 32 | load4(p + n - 4));
    } else if (n > 0) {
        h = mix(h, std::uint64_t{p[0]} << 16 | std::uint64_t{p[n / 2]} << 8 | p[n - 1]);
    }
    h *= 0xBF58476D1CE4E5B9ULL;
    return static_cast<std::size_t>(h ^ (h >> 31));
}

/// Hash and equality of identifier tables that also take a HashedName (heterogeneous lookup).
struct NameHash {
    using is_transparent = void;
    template <typename S>
        requires std::convertible_to<const S&, std::string_view>
    std::size_t operator()(const S& s) const { return name_hash(std::string_view(s)); }
    std::size_t operator()(const HashedName& n) const { return n.hash; }
};
struct NameEqual {
    using is_transparent = void;
    static std::string_view view(const HashedName& n) { return n.name; }
    template <typename S>
        requires std::convertible_to<const S&, std::string_view>
    static std::string_view view(const S& s) { return std::string_view(s); }
    template <typename A, typename B>
    bool operator()(const A& a, const B& b) const { return view(a) == view(b); }
};

/// A table keyed by identifier.
template <typename T>
using NameMap = std::unordered_map<std::string, T, NameHash, NameEqual>;

inline HashedName hashed(std::string_view name) { return {name, NameHash{}(name)}; }


/// One source file read by the parse, with its tokens (lexed as they are read; macros and loops re-read them).
struct SourceFile {
    SharedString path;  ///< as shown in diagnostics (every location in the file shares it)
    std::string text;
    TokenStore tokens;
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

/// Thrown inside the parser to abandon the current statement after an error was reported. Constructing one clears
/// AddressSanitizer's stale stack poison (core/large_stack.h), since it is thrown from deep in the parser's stack.
struct StatementError {
    StatementError() noexcept { unpoison_stack_above_here(); }
};
/// Thrown inside the parser to end the whole parse (error limit, #error, runaway recursion).
struct FatalError {
    FatalError() noexcept { unpoison_stack_above_here(); }
};

/// How a token reads in a message: 'word', string "text", '#directive' or end of file.
std::string describe_token(const Token& t);
/// "a pigment", "an object", ... for messages about identifiers of the wrong kind.
const char* value_kind_name(const Value& v);

/// The bottom layer of the parser: source files and their tokens, the include/macro frames, diagnostics with
/// their include and macro notes, and the guards on nesting. The layers above read tokens through it.
class SourceStream {
public:
    SourceStream(const SourceStream&) = delete;
    SourceStream& operator=(const SourceStream&) = delete;

protected:
    /// A stream reading with `options` (library paths, declares, image size, error limit).
    explicit SourceStream(const ParseOptions& options);
    virtual ~SourceStream() = default;

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

    /// The current token, before directives and macro ends are handled.
    const Token& raw() const { return m_files[m_file]->tokens[m_pos]; }
    // Inline, taking views: most callers pass literals, whose length is then known where they are compared.
    /// True when `t` is the punctuation `p`.
    bool is_punct(const Token& t, std::string_view p) const { return t.kind == TokenKind::Punct && t.text == p; }
    /// True when `t` is the identifier or keyword `w`.
    bool is_word(const Token& t, std::string_view w) const { return t.kind == TokenKind::Identifier && t.text == w; }

    /// Starts reading a file's tokens from its text (lexed as they are read); its lexical errors are reported the
    /// first time their stretch of text is lexed.
    void lex_file(std::uint32_t index);
    /// Reads and lexes a file once (a second #include of it reuses the tokens); `library` marks a file found
    /// through the library paths.
    std::optional<std::uint32_t> load_file(const std::filesystem::path& path, bool library, std::string& error);
    /// One place a file named in the scene may be: its path, whether it counts as a library file, and whether only
    /// wardray looks there (POV-Ray would not find it).
    struct SearchCandidate {
        std::filesystem::path path;
        bool library = false;
        bool beyond_povray = false;
    };
    /// Where a file named in the scene is looked for, in POV-Ray's order: the current folder, the scene's folder,
    /// the library paths; then the reading file's folder. A name without extension is then tried with
    /// `extension` in the same places.
    std::vector<SearchCandidate> search_candidates(const std::filesystem::path& requested,
                                                   const char* extension) const;
    /// Fails at `at` when `file` lies outside the folders the scene may read (parser/read_access.h), naming the
    /// switch that allows it; `what` says what the file is for ("include file", "font", ...).
    void require_readable(const Token& at, const std::filesystem::path& file, std::string_view what);
    /// The first of search_candidates(requested, extension) that exists, checked by require_readable; nothing
    /// when none exists. The way every file a scene names (images, height fields, density files) is found.
    std::optional<std::filesystem::path> find_readable(const Token& at, const std::filesystem::path& requested,
                                                       const char* extension, std::string_view what);

    /// A diagnostic at `at` with the source line and the include/macro notes.
    Diagnostic make_diagnostic(Severity s, const Token& at, std::string message) const;
    /// Records a diagnostic; ends the parse at the error limit.
    void report(Diagnostic d);
    /// Reports an error at `at` and abandons the statement.
    [[noreturn]] void fail(const Token& at, std::string message);
    /// Reports a warning at `at`.
    void warn(const Token& at, std::string message);
    /// Warns that `feature` is not rendered yet, once per parse, deferred while a declaration is read.
    void warn_unsupported(const Token& at, const std::string& feature);
    /// A warning shown once per parse for each distinct message.
    void warn_once(const Token& at, const std::string& message);
    /// Reports an unsupported-feature warning unless the same one was shown already.
    void emit_feature_warning(Diagnostic d);

    /// Counts `n` objects created at `at`; past ParseOptions::max_objects an error there ends the parse.
    void count_objects(const Token& at, std::size_t n);
    /// Gives back `n` objects counted as copies whose value is freed (a declared object redeclared).
    void uncount_objects(std::size_t n) { m_objects_created -= std::min(n, m_objects_created); }
    /// Counts `n` objects copied at `at` (and created, see count_objects); past ten times
    /// ParseOptions::max_objects copied in all, an error there ends the parse (a growing object copied in a loop).
    void count_copies(const Token& at, std::size_t n);
    /// Past ParseOptions::max_memory_bytes of growth since the parse began, an error at `at` ends the parse.
    /// Reads the resident size, so callers ask every few thousand tokens, or before a large allocation:
    /// `about_to_take` bytes are counted as if already taken, so a single huge request fails before it is made.
    void check_memory(const Token& at, std::size_t about_to_take = 0);

    /// The deepest nesting of blocks and expressions the descent follows.
    static constexpr std::size_t k_max_nesting = 400;
    /// The most stack the descent may use: frames are larger in sanitizer and debug builds, where 400 levels
    /// can exceed the default 8 MiB stack, so the guard also measures the stack itself.
    static constexpr std::ptrdiff_t k_max_stack_bytes = std::ptrdiff_t{4} << 20;
    /// The deepest nesting of object statements (`union { union { ... } }`): POV-Ray reads 20,000 levels and
    /// more; the parse runs on a thread with a large stack (Parser::run), and the stack guard still applies.
    static constexpr std::size_t k_max_object_nesting = 1'000'000;
public:
    /// Bounds the recursion of the descent so deeply nested input ends in an error, not a stack overflow.
    /// Public so the function compiler (a friend of a derived class, which clang does not let through) can use it.
    class NestingGuard {
    public:
        /// Counts one level of the descent's own nesting at `at`.
        NestingGuard(SourceStream& stream, const Token& at) : NestingGuard(stream, at, stream.m_nesting) {}
        /// Counts in `depth` instead of the descent's own counter. Inline: every operand of an expression passes
        /// one, and the check is two comparisons.
        NestingGuard(SourceStream& stream, const Token& at, std::size_t& depth, std::size_t limit = k_max_nesting)
            : m_stream(stream), m_depth(depth) {
            // The stack grows down on every platform we build for: the distance from where the parser began is its
            // use.
            const char* here = static_cast<const char*>(__builtin_frame_address(0));
            const bool stack_full = m_stream.m_stack_base - here > m_stream.m_max_stack_bytes;
            if (++m_depth <= limit && !stack_full) return;
            --m_depth;
            fail(at, limit, stack_full);
        }
        ~NestingGuard() { --m_depth; }
        NestingGuard(const NestingGuard&) = delete;
        NestingGuard& operator=(const NestingGuard&) = delete;

    private:
        /// Reports the nesting as too deep at `at` and stops the parse.
        [[noreturn]] void fail(const Token& at, std::size_t limit, bool stack_full);

        SourceStream& m_stream;
        std::size_t& m_depth;
    };

protected:
    /// POV-Ray compat: while a directive reads its operands (a #declare's value included) and while a float,
    /// vector or colour value reads its operators, the brace depth they started at; a directive met at that depth
    /// ends what is being read. Blocks opened inside (objects, pigments, ...) and the inside of an operand ('(',
    /// '<', a call: k_directives_run) run directives as they come.
    static constexpr std::size_t k_directives_run = static_cast<std::size_t>(-1);
    /// Sets a variable for a scope and puts its old value back at the end, or earlier through restore().
    class ScopedSetting {
    public:
        /// Sets `setting` to `value` until the end of the scope.
        ScopedSetting(std::size_t& setting, std::size_t value) : m_setting(setting), m_old(setting) {
            setting = value;
        }
        ~ScopedSetting() { restore(); }
        ScopedSetting(const ScopedSetting&) = delete;
        ScopedSetting& operator=(const ScopedSetting&) = delete;
        /// Puts the old value back now.
        void restore() { m_setting = m_old; }

    private:
        std::size_t& m_setting;
        std::size_t m_old;
    };

    std::size_t m_nesting = 0;
    std::size_t m_directive_ends_value_at = k_directives_run;
    std::size_t m_directive_nesting = 0;  ///< directives running inside another directive's operands
    const char* m_stack_base = nullptr;   ///< the stack address where this parser was made (or its parse began)
    std::ptrdiff_t m_max_stack_bytes = k_max_stack_bytes;  ///< how much of the stack below it the descent may use
    std::size_t m_object_nesting = 0;     ///< object statements being read, one inside the other

    const ParseOptions& m_options;
    std::vector<ReadRoot> m_read_roots;  ///< the folders the scene may read, made on first use
    std::size_t m_objects_created = 0;
    std::size_t m_objects_copied = 0;  ///< every object copied, never given back: bounds quadratic copying
    std::size_t m_resident_at_start = 0;  ///< the process's resident bytes when the parse began
    std::vector<std::unique_ptr<SourceFile>> m_files;
    std::map<std::string, std::uint32_t> m_file_index;  ///< resolved path -> index, so re-includes do not re-lex
    std::uint32_t m_file = 0;
    std::size_t m_pos = 0;
    std::size_t m_brace_depth = 0;  ///< '{' minus '}' consumed so far, for error recovery
    std::vector<Token> m_open_braces;  ///< the '{' tokens not closed yet, innermost last
    std::vector<Frame> m_frames;
    double m_version = 3.7;
    bool m_version_given = false;  ///< a #version was read (in any file): POV-Ray then stops assuming 3.62

    std::vector<Diagnostic> m_diagnostics;
    std::vector<Diagnostic> m_warnings;  ///< the warnings among them, which the scene keeps
    std::size_t m_errors = 0;
    std::set<std::string> m_warned_features;
    /// Unsupported-feature warnings met while declaring an identifier: shown only when the identifier is used,
    /// so unused declarations of include files cost nothing.
    NameMap<std::vector<Diagnostic>> m_deferred_warnings;
    std::vector<std::vector<Diagnostic>> m_declaring;  ///< warnings collected by the declarations being parsed
};

}  // namespace wardray::parser
