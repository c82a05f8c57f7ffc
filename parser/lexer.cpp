// Lexer: Spirit X3 token rules over a hand-written loop that skips whitespace and (nested) comments.
#include "parser/lexer.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>

#include <boost/spirit/home/x3.hpp>

namespace wardray::parser {

namespace x3 = boost::spirit::x3;

namespace {

// Unsigned reals as POV-Ray writes them ("1", "1.5", ".5", "2.", "1e-3"), never "nan" or "inf". The lexer only
// finds where a number ends; Token::number() reads its value when the parser asks.
const auto digits = +x3::char_('0', '9');
const auto number_rule = (digits >> -('.' >> *x3::char_('0', '9')) | '.' >> digits) >>
                         -(x3::char_("eE") >> -x3::char_("+-") >> digits);
// ASCII letters, digits and '_', as POV-Ray reads identifiers (character sets are table lookups).
const auto identifier_rule = x3::char_("a-zA-Z_") >> *x3::char_("a-zA-Z0-9_");

bool starts_identifier(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }
const auto two_char_punct = x3::string("<=") | x3::string(">=") | x3::string("!=");
// Single-character punctuation; '-' comes last so the character set does not read it as a range.
const auto one_char_punct = x3::char_("{}()[]<>,;+*/=!&|?:.%^@$'`~\\-");

// Tracks line and column while the scanner moves forward byte by byte.
class Cursor {
public:
    Cursor(std::string_view text, LexStart start)
        : m_text(text), m_pos(start.offset), m_line(start.line), m_column(start.column) {}
    bool done() const { return m_pos >= m_text.size(); }
    char peek(std::size_t ahead = 0) const {
        return m_pos + ahead < m_text.size() ? m_text[m_pos + ahead] : '\0';
    }
    void advance(std::size_t n = 1) {
        for (std::size_t i = 0; i < n && m_pos < m_text.size(); ++i, ++m_pos) {
            if (m_text[m_pos] == '\n') {
                ++m_line;
                m_column = 1;
            } else {
                ++m_column;
            }
        }
    }
    std::size_t pos() const { return m_pos; }
    std::uint32_t line() const { return m_line; }
    std::uint32_t column() const { return m_column; }

private:
    std::string_view m_text;
    std::size_t m_pos = 0;
    std::uint32_t m_line = 1;
    std::uint32_t m_column = 1;
};

char decode_escape(char c) {
    switch (c) {
        case 'n': return '\n';
        case 't': return '\t';
        case 'r': return '\r';
        case 'a': return '\a';
        case 'b': return '\b';
        case 'f': return '\f';
        case 'v': return '\v';
        default: return c;  // \\ \" \' and anything else stand for themselves
    }
}

}  // namespace

std::string source_line(std::string_view text, std::uint32_t line) {
    if (line == 0) return {};
    std::size_t start = 0;
    for (std::uint32_t l = 1; l < line; ++l) {
        const std::size_t nl = text.find('\n', start);
        if (nl == std::string_view::npos) return {};
        start = nl + 1;
    }
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    if (end > start && text[end - 1] == '\r') --end;
    return std::string(text.substr(start, end - start));
}

double Token::number() const {
    // Most numbers in scenes are short decimals (`3`, `0.25`): up to 15 digits and no exponent, the digits as an
    // integer m and the point k places from the end give exactly m / 10^k, both exact doubles (m < 2^53,
    // k ≤ 15 < 23), so one correctly rounded division: from_chars's value (also correctly rounded), read faster.
    static constexpr double kPowersOfTen[16] = {1e0, 1e1, 1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                                1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15};
    if (text.size() <= 16) {
        std::uint64_t digits = 0;
        int count = 0, after_point = -1;
        bool plain = !text.empty();
        for (const char c : text) {
            if (c >= '0' && c <= '9') {
                digits = digits * 10 + static_cast<std::uint64_t>(c - '0');
                ++count;
                if (after_point >= 0) ++after_point;
            } else if (c == '.' && after_point < 0) {
                after_point = 0;
            } else {
                plain = false;
                break;
            }
        }
        if (plain && count > 0 && count <= 15)
            return static_cast<double>(digits) / kPowersOfTen[after_point < 0 ? 0 : after_point];
    }
    double value = 0.0;
    if (std::from_chars(text.begin(), text.end(), value).ec == std::errc{}) return value;
    // Out of double's range: strtod's reading underflows to 0 (an overflow is a lexical error).
    value = std::strtod(std::string(text.view()).c_str(), nullptr);
    return std::isfinite(value) ? value : 0.0;
}

std::vector<Token> lex(std::string_view text, std::uint32_t file, const std::string& path,
                       std::vector<Diagnostic>& errors, DecodedStrings& decoded) {
    return lex(text, LexStart{}, text.size(), file, path, errors, decoded);
}

std::vector<Token> lex(std::string_view whole, LexStart start, std::size_t end_offset, std::uint32_t file,
                       const std::string& path, std::vector<Diagnostic>& errors, DecodedStrings& decoded) {
    std::vector<Token> tokens;
    // Scene files average about five bytes per token: reserving up front avoids re-copying the vector as it grows
    // (untouched reserved memory costs nothing).
    tokens.reserve((std::min(end_offset, whole.size()) - std::min(start.offset, whole.size())) / 3 + 16);
    LexStart stop;
    lex_some(whole, start, end_offset, static_cast<std::size_t>(-1), file, path, errors, decoded, tokens, stop);
    return tokens;
}

bool lex_some(std::string_view whole, LexStart start, std::size_t end_offset, std::size_t max_tokens,
              std::uint32_t file, const std::string& path, std::vector<Diagnostic>& errors, DecodedStrings& decoded,
              std::vector<Token>& tokens, LexStart& stop) {
    // The scan sees the text up to `end_offset` only; diagnostics quote lines of the whole text.
    const std::string_view text = whole.substr(0, std::min(end_offset, whole.size()));
    Cursor cur(text, start);
    std::size_t taken = 0;
    auto error_at = [&](std::uint32_t line, std::uint32_t column, std::uint32_t span, std::string message) {
        Diagnostic d;
        d.severity = Severity::Error;
        d.loc = SourceLoc{path, line, column};
        d.message = std::move(message);
        d.source_line = source_line(whole, line);
        d.span = span;
        errors.push_back(std::move(d));
    };

    while (true) {
        // A full batch stops right after its last token, where the next batch starts.
        if (taken == max_tokens) {
            stop = LexStart{cur.pos(), cur.line(), cur.column()};
            return false;
        }
        // Whitespace and comments between tokens.
        const char c = cur.peek();
        if (cur.done()) break;
        if (c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v') {
            cur.advance();
            continue;
        }
        if (c == '/' && cur.peek(1) == '/') {
            while (!cur.done() && cur.peek() != '\n') cur.advance();
            continue;
        }
        if (c == '/' && cur.peek(1) == '*') {
            // POV-Ray compat: block comments nest.
            const std::uint32_t line = cur.line();
            const std::uint32_t column = cur.column();
            int depth = 0;
            while (!cur.done()) {
                if (cur.peek() == '/' && cur.peek(1) == '*') {
                    ++depth;
                    cur.advance(2);
                } else if (cur.peek() == '*' && cur.peek(1) == '/') {
                    --depth;
                    cur.advance(2);
                    if (depth == 0) break;
                } else {
                    cur.advance();
                }
            }
            if (depth != 0) error_at(line, column, 2, "unterminated comment");
            continue;
        }

        Token tok;
        tok.file = file;
        tok.line = cur.line();
        tok.column = cur.column();
        const char* const begin = text.data() + cur.pos();
        const char* const end = text.data() + text.size();
        const char* it = begin;

        if (c == '"') {
            // String literal with backslash escapes; it may not run past the end of the file.
            ++it;
            const char* const contents = it;
            bool escapes = false;
            bool closed = false;
            while (it != end) {
                if (*it == '"') {
                    closed = true;
                    break;
                }
                if (*it == '\\' && it + 1 != end) {
                    escapes = true;
                    ++it;
                }
                ++it;
            }
            if (!closed) {
                error_at(tok.line, tok.column, 1, "unterminated string");
                cur.advance(static_cast<std::size_t>(it - begin));
                break;
            }
            tok.kind = TokenKind::String;
            tok.text = std::string_view(contents, static_cast<std::size_t>(it - contents));
            if (escapes) {
                // Only a literal with escapes needs text of its own.
                std::string& value = decoded.emplace_back();
                for (const char* p = contents; p != it; ++p) value += (*p == '\\') ? decode_escape(*++p) : *p;
                tok.text = std::string_view(value);
            }
            ++it;  // the closing quote
        } else if (c == '#') {
            // A directive: '#' then optional blanks then its name.
            ++it;
            while (it != end && (*it == ' ' || *it == '\t')) ++it;
            const char* const name = it;
            if (x3::parse(it, end, identifier_rule)) {
                tok.kind = TokenKind::Directive;
                tok.text = std::string_view(name, static_cast<std::size_t>(it - name));
            } else {
                // POV-Ray compat: a stray '#' (language/image_size.pov has one before '}') is skipped with a warning.
                Diagnostic d;
                d.severity = Severity::Warning;
                d.loc = SourceLoc{path, tok.line, tok.column};
                d.message = "'#' without a directive name is ignored";
                d.source_line = source_line(whole, tok.line);
                errors.push_back(std::move(d));
                cur.advance(1);
                continue;
            }
        } else if (starts_identifier(c)) {
            x3::parse(it, end, identifier_rule);
            tok.kind = TokenKind::Identifier;
            tok.text = std::string_view(begin, static_cast<std::size_t>(it - begin));
        } else if (is_digit(c) || (c == '.' && is_digit(cur.peek(1)))) {
            x3::parse(it, end, number_rule);
            tok.kind = TokenKind::Number;
            tok.text = std::string_view(begin, static_cast<std::size_t>(it - begin));
            // Only an exponent or a few hundred digits reach beyond double's range; strtod's reading underflows
            // to 0 and overflows to infinity, which is an error.
            const bool may_overflow = tok.text.view().find_first_of("eE") != std::string_view::npos ||
                                      tok.text.size() > 300;
            if (may_overflow && !std::isfinite(std::strtod(std::string(tok.text.view()).c_str(), nullptr)))
                error_at(tok.line, tok.column, static_cast<std::uint32_t>(tok.text.size()),
                         "number '" + tok.text + "' is too large for a double");
        } else {
            if (!x3::parse(it, end, two_char_punct) && !x3::parse(it, end, one_char_punct)) {
                error_at(tok.line, tok.column, 1, std::string("unexpected character '") + c + "'");
                cur.advance(1);
                continue;
            }
            tok.kind = TokenKind::Punct;
            tok.text = std::string_view(begin, static_cast<std::size_t>(it - begin));
        }
        const auto consumed = static_cast<std::size_t>(it - begin);
        tok.length = static_cast<std::uint32_t>(consumed > 0 ? consumed : 1);
        // A token that spans lines (a string) is underlined only to the end of its first line.
        for (std::size_t i = 0; i < consumed; ++i) {
            if (begin[i] == '\n') {
                tok.length = static_cast<std::uint32_t>(i > 0 ? i : 1);
                break;
            }
        }
        cur.advance(consumed);
        tokens.push_back(std::move(tok));
        ++taken;
    }

    Token eof;
    eof.kind = TokenKind::EndOfFile;
    eof.file = file;
    eof.line = cur.line();
    eof.column = cur.column();
    eof.text = std::string_view(text.data() + cur.pos(), 0);
    tokens.push_back(std::move(eof));
    stop = LexStart{cur.pos(), cur.line(), cur.column()};
    return true;
}

}  // namespace wardray::parser
