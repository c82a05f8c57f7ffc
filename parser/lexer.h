// Lexer: turns POV-Ray scene text into a flat token vector that the directive layer can re-read.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "parser/diagnostics.h"

namespace wardray::parser {

/// What a token is; keywords are identifiers and are told apart by the parser.
enum class TokenKind { Identifier, Number, String, Punct, Directive, EndOfFile };

/// One token with its place in its file (file is an index into the parser's file table).
struct Token {
    TokenKind kind = TokenKind::EndOfFile;
    std::string text;     ///< identifier, punctuation, directive name (without '#'), or decoded string contents
    double number = 0.0;  ///< value of a Number token
    std::uint32_t file = 0;
    std::uint32_t line = 0;
    std::uint32_t column = 0;
    std::uint32_t length = 1;  ///< characters the token spans in the source (for the caret)
};

/// The text of line `line` (from 1) of `text`, without its line ending; empty when out of range.
std::string source_line(std::string_view text, std::uint32_t line);

/// Tokenises `text`; lexical errors and warnings go to `errors` (with `path` and source line) and the scan goes on.
/// The result always ends with one EndOfFile token.
std::vector<Token> lex(std::string_view text, std::uint32_t file, const std::string& path,
                       std::vector<Diagnostic>& errors);

}  // namespace wardray::parser
