// Tests of the lexer: token kinds, numbers, strings, comments and source locations.
#include <gtest/gtest.h>

#include <bit>
#include <charconv>
#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include "parser/lexer.h"
#include "parser/source_stream.h"

namespace wardray::parser {
namespace {

// Tokens view their text: `text` is a literal, and decoded strings are kept for the whole run.
std::vector<Token> lex_ok(std::string_view text) {
    static DecodedStrings decoded;
    std::vector<Diagnostic> errors;
    auto tokens = lex(text, 0, "t.pov", errors, decoded);
    EXPECT_TRUE(errors.empty()) << (errors.empty() ? "" : format_diagnostic(errors.front()));
    return tokens;
}

TEST(Lexer, KindsAndText) {
    const auto t = lex_ok("sphere { <1, 2.5, .5>, 1e2 } #declare \"a\\tb\\\"c\" <= != >=");
    ASSERT_EQ(t.size(), 18u);
    EXPECT_EQ(t[0].kind, TokenKind::Identifier);
    EXPECT_EQ(t[0].text, "sphere");
    EXPECT_EQ(t[1].kind, TokenKind::Punct);
    EXPECT_EQ(t[3].kind, TokenKind::Number);
    EXPECT_DOUBLE_EQ(t[3].number(), 1.0);
    EXPECT_DOUBLE_EQ(t[5].number(), 2.5);
    EXPECT_DOUBLE_EQ(t[7].number(), 0.5);
    EXPECT_DOUBLE_EQ(t[10].number(), 100.0);
    EXPECT_EQ(t[12].kind, TokenKind::Directive);
    EXPECT_EQ(t[12].text, "declare");
    EXPECT_EQ(t[13].kind, TokenKind::String);
    EXPECT_EQ(t[13].text, "a\tb\"c");
    EXPECT_EQ(t[14].text, "<=");
    EXPECT_EQ(t[15].text, "!=");
    EXPECT_EQ(t[16].text, ">=");
    EXPECT_EQ(t.back().kind, TokenKind::EndOfFile);
}

TEST(Lexer, NumbersLikePovRay) {
    const auto t = lex_ok("2. 3e-2 1.5E+1 007 nan");
    EXPECT_DOUBLE_EQ(t[0].number(), 2.0);
    EXPECT_DOUBLE_EQ(t[1].number(), 0.03);
    EXPECT_DOUBLE_EQ(t[2].number(), 15.0);
    EXPECT_DOUBLE_EQ(t[3].number(), 7.0);
    EXPECT_EQ(t[4].kind, TokenKind::Identifier);  // never a floating-point NaN literal
}

// Token::number() reads short decimals without from_chars (digits over a power of ten); the value must be
// from_chars's, bit for bit, at every length and point position, and beyond the short form too.
TEST(Lexer, NumbersReadExactlyAsFromChars) {
    std::uint64_t state = 12345;
    const auto draw = [&](std::uint64_t n) {
        state = state * 6364136223846793005ULL + 1442695040888963407ULL;
        return (state >> 33) % n;
    };
    std::vector<std::string> texts = {"0", "0.", ".0", "1", "0.1", "0.3", "2.675", "999999999999999",
                                      "999999999999999.", "9999999999999999", "123456789012345.6", "0.000000000000001",
                                      ".000000000000001", "00000000000001.5", "4503599627370497", "1e5", "2.5E-3"};
    for (int i = 0; i < 20000; ++i) {
        const std::uint64_t digits = 1 + draw(18);
        std::string text;
        for (std::uint64_t k = 0; k < digits; ++k) text += static_cast<char>('0' + draw(10));
        const std::uint64_t point = draw(digits + 2);  // digits + 1: none
        if (point <= digits) text = text.substr(0, point) + "." + text.substr(point);
        texts.push_back(text);
    }
    for (const std::string& text : texts) {
        Token t;
        t.kind = TokenKind::Number;
        t.text = std::string_view(text);
        double expected = 0.0;
        ASSERT_EQ(std::from_chars(text.data(), text.data() + text.size(), expected).ec, std::errc{}) << text;
        EXPECT_EQ(std::bit_cast<std::uint64_t>(t.number()), std::bit_cast<std::uint64_t>(expected)) << text;
    }
}

// Identifier tables hash names with name_hash (short names by overlapping loads): every form of a name finds
// the same entry, at every length, and names that differ in one character rarely share a hash.
TEST(Lexer, IdentifierTablesFindEveryFormOfAName) {
    NameMap<int> table;
    std::vector<std::string> names;
    for (std::size_t length = 0; length <= 40; ++length)
        for (char c = 'a'; c <= 'z'; ++c) {
            std::string name(length, 'x');
            if (length > 0) name[(static_cast<std::size_t>(c) * 7) % length] = c;
            if (table.emplace(name, static_cast<int>(names.size())).second) names.push_back(name);
        }
    std::set<std::size_t> hashes;
    for (std::size_t i = 0; i < names.size(); ++i) {
        const std::string copy = names[i];
        const TokenText text(copy);
        ASSERT_TRUE(table.count(copy)) << names[i];
        EXPECT_EQ(table.find(text)->second, static_cast<int>(i));
        EXPECT_EQ(table.find(hashed(copy))->second, static_cast<int>(i));
        EXPECT_EQ(name_hash(copy), NameHash{}(text));
        hashes.insert(name_hash(copy));
    }
    EXPECT_EQ(hashes.size(), names.size());
    EXPECT_EQ(table.find(std::string_view("xxxxq")), table.end());
}

TEST(Lexer, DotItemAfterVectorIsPunctuation) {
    const auto t = lex_ok("V.x <1,2,3>.y");
    EXPECT_EQ(t[0].text, "V");
    EXPECT_EQ(t[1].text, ".");
    EXPECT_EQ(t[2].text, "x");
    EXPECT_EQ(t[10].text, ".");
}

TEST(Lexer, CommentsNestAndAreSkipped) {
    const auto t = lex_ok("a // line comment\n/* outer /* inner */ still comment */ b");
    ASSERT_EQ(t.size(), 3u);
    EXPECT_EQ(t[0].text, "a");
    EXPECT_EQ(t[1].text, "b");
    EXPECT_EQ(t[1].line, 2u);
}

TEST(Lexer, LocationsCountFromOne) {
    const auto t = lex_ok("a\n  bb  #  declare\n\t\"s\"");
    EXPECT_EQ(t[0].line, 1u);
    EXPECT_EQ(t[0].column, 1u);
    EXPECT_EQ(t[1].line, 2u);
    EXPECT_EQ(t[1].column, 3u);
    EXPECT_EQ(t[1].length, 2u);
    EXPECT_EQ(t[2].kind, TokenKind::Directive);
    EXPECT_EQ(t[2].text, "declare");
    EXPECT_EQ(t[2].column, 7u);
    EXPECT_EQ(t[2].length, 10u);
    EXPECT_EQ(t[3].line, 3u);
    EXPECT_EQ(t[3].column, 2u);
    EXPECT_EQ(t[3].length, 3u);
}

TEST(Lexer, UnterminatedCommentIsAnErrorAtItsStart) {
    std::vector<Diagnostic> errors;
    DecodedStrings decoded;
    const auto t = lex("a\n  /* open /* nested */ never closed", 0, "t.pov", errors, decoded);
    ASSERT_EQ(errors.size(), 1u);
    EXPECT_EQ(errors[0].message, "unterminated comment");
    EXPECT_EQ(errors[0].loc.line, 2u);
    EXPECT_EQ(errors[0].loc.column, 3u);
    EXPECT_EQ(t.back().kind, TokenKind::EndOfFile);
}

TEST(Lexer, UnterminatedStringIsAnErrorAtItsStart) {
    std::vector<Diagnostic> errors;
    DecodedStrings decoded;
    lex("#include \"colors.inc", 0, "t.pov", errors, decoded);
    ASSERT_EQ(errors.size(), 1u);
    EXPECT_EQ(errors[0].message, "unterminated string");
    EXPECT_EQ(errors[0].loc.column, 10u);
}

TEST(Lexer, StrayCharacterIsAnError) {
    std::vector<Diagnostic> errors;
    DecodedStrings decoded;
    const auto t = lex("a \x01 b", 0, "t.pov", errors, decoded);
    EXPECT_EQ(errors.size(), 1u);
    EXPECT_EQ(t.size(), 3u);
}

TEST(Lexer, SourceLine) {
    EXPECT_EQ(source_line("one\r\ntwo\nthree", 2), "two");
    EXPECT_EQ(source_line("one\r\ntwo\nthree", 1), "one");
    EXPECT_EQ(source_line("one", 5), "");
}

}  // namespace
}  // namespace wardray::parser
