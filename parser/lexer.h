// Lexer: turns POV-Ray scene text into a flat token vector that the directive layer can re-read.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "parser/diagnostics.h"

namespace wardray::parser {

/// What a token is; keywords are identifiers and are told apart by the parser.
enum class TokenKind : std::uint8_t { Identifier, Number, String, Punct, Directive, EndOfFile };

/// One token with its place in its file (file is an index into the parser's file table). The fields are ordered
/// so the token packs into 64 bytes: a scene's include files make tens of thousands of them.
struct Token {
    std::string text;     ///< identifier, punctuation, directive name (without '#'), or decoded string contents
    double number = 0.0;  ///< value of a Number token
    std::uint32_t file = 0;
    std::uint32_t line = 0;
    std::uint32_t column = 0;
    std::uint32_t length = 1;  ///< characters the token spans in the source (for the caret)
    std::uint32_t offset = 0;  ///< byte offset of its first character in its file
    TokenKind kind = TokenKind::EndOfFile;
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
std::vector<Token> lex(std::string_view text, std::uint32_t file, const std::string& path,
                       std::vector<Diagnostic>& errors);

/// Tokenises the part of `text` from `start` up to byte `end`, with the lines, columns and offsets the tokens have
/// in the whole text (to read a stretch of a file again).
std::vector<Token> lex(std::string_view text, LexStart start, std::size_t end, std::uint32_t file,
                       const std::string& path, std::vector<Diagnostic>& errors);

}  // namespace wardray::parser
