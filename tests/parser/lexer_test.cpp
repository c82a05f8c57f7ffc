// Tests of the lexer: token kinds, numbers, strings, comments and source locations.
#include <gtest/gtest.h>

#include "parser/lexer.h"

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
