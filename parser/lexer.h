// Lexer: turns POV-Ray scene text into a flat token vector that the directive layer can re-read.
#pragma once

#include <cstdint>
#include <deque>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "core/diagnostics.h"

namespace wardray::parser {

/// What a token is; keywords are identifiers and are told apart by the parser.
enum class TokenKind : std::uint8_t { Identifier, Number, String, Punct, Directive, EndOfFile };

/// A token's text: a view of its file's text, or of a string literal the lexer decoded. It converts to
/// std::string and std::string_view where those are wanted; what it views lives as long as the parse's files.
class TokenText {
public:
    TokenText() = default;
    TokenText(std::string_view s) : m_data(s.data()), m_size(static_cast<std::uint32_t>(s.size())) {}  // NOLINT
    std::string_view view() const { return {m_data, m_size}; }
    operator std::string_view() const { return view(); }                // NOLINT: reads as a string
    operator std::string() const { return std::string(view()); }       // NOLINT
    const char* data() const { return m_data; }
    std::size_t size() const { return m_size; }
    bool empty() const { return m_size == 0; }
    char operator[](std::size_t i) const { return m_data[i]; }
    const char* begin() const { return m_data; }
    const char* end() const { return m_data + m_size; }

    // The first characters decide most comparisons of a word with a keyword: check them before memcmp.
    friend bool operator==(const TokenText& a, std::string_view b) {
        return a.m_size == b.size() && (b.empty() || (a.m_data[0] == b[0] && a.view() == b));
    }
    friend std::string operator+(std::string a, const TokenText& b) { return a.append(b.view()); }
    friend std::string operator+(const char* a, const TokenText& b) { return std::string(a).append(b.view()); }
    friend std::string operator+(const TokenText& a, const char* b) { return std::string(a.view()).append(b); }
    friend std::string operator+(const TokenText& a, const std::string& b) {
        return std::string(a.view()).append(b);
    }
    friend std::ostream& operator<<(std::ostream& out, const TokenText& t) { return out << t.view(); }

private:
    const char* m_data = "";
    std::uint32_t m_size = 0;
};

/// String literals with escapes, decoded; tokens view them, so they live as long as the tokens.
using DecodedStrings = std::deque<std::string>;

/// One token with its place in its file (file is an index into the parser's file table). A scene's include
/// files make tens of thousands of tokens: the fields pack into 32 bytes.
struct Token {
    [[no_unique_address]] TokenText text;  ///< identifier, punctuation, directive name (without '#'), number as
                                           ///< written, or decoded string contents
    std::uint32_t file = 0;
    std::uint32_t line = 0;
    std::uint32_t column = 0;
    std::uint32_t length = 1;  ///< characters the token spans in the source (for the caret)
    TokenKind kind = TokenKind::EndOfFile;

    /// The value of a Number token, read from its text as the lexer reads it.
    double number() const;
};

/// Where a scan starts inside a file's text: its byte offset, line and column (from 1).
struct LexStart {
    std::size_t offset = 0;
    std::uint32_t line = 1;
    std::uint32_t column = 1;
};

/// The text of line `line` (from 1) of `text`, without its line ending; empty when out of range.
std::string source_line(std::string_view text, std::uint32_t line);

/// Tokenises `text`; lexical errors and warnings go to `errors` (with `path` and source line) and the scan goes on.
/// The result always ends with one EndOfFile token.
/// The tokens view `text` and `decoded`, which must outlive them.
std::vector<Token> lex(std::string_view text, std::uint32_t file, const std::string& path,
                       std::vector<Diagnostic>& errors, DecodedStrings& decoded);

/// Tokenises the part of `text` from `start` up to byte `end`, with the lines and columns the tokens have in the
/// whole text (to read a stretch of a file again).
std::vector<Token> lex(std::string_view text, LexStart start, std::size_t end, std::uint32_t file,
                       const std::string& path, std::vector<Diagnostic>& errors, DecodedStrings& decoded);

/// Appends to `tokens` at most `max_tokens` tokens of `text` from `start` up to byte `end` (to read a file a batch
/// at a time). True when the text ended, after the EndOfFile token; false when the batch filled, with `stop`
/// just past its last token, where the next batch starts.
bool lex_some(std::string_view text, LexStart start, std::size_t end, std::size_t max_tokens, std::uint32_t file,
              const std::string& path, std::vector<Diagnostic>& errors, DecodedStrings& decoded,
              std::vector<Token>& tokens, LexStart& stop);

}  // namespace wardray::parser
