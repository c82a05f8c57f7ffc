// Tests of TokenStore (tokens lexed a chunk at a time, old chunks released) and of parses that cross many chunks.
#include <string>

#include "parser/token_store.h"
#include "tests/parser/test_util.h"

namespace wardray::parser {
namespace {

constexpr std::size_t K = TokenStore::k_chunk_tokens;

// "a0 a1 a2 ..." over lines of ten words: `n` tokens whose text says their position.
std::string numbered_words(std::size_t n) {
    std::string s;
    for (std::size_t i = 0; i < n; ++i) s += "a" + std::to_string(i) + (i % 10 == 9 ? "\n" : " ");
    return s;
}

struct Store {
    std::string text;
    std::string path = "t.pov";
    DecodedStrings decoded;
    std::vector<Diagnostic> delivered;
    TokenStore tokens;
    explicit Store(std::string t) : text(std::move(t)) { reset(); }
    void reset() {
        tokens.reset(text, LexStart{}, text.size(), 7, path, decoded,
                     [this](std::vector<Diagnostic>& d) { delivered.insert(delivered.end(), d.begin(), d.end()); });
    }
};

TEST(TokenStore, ReadingForwardKeepsOnlyTheLastChunks) {
    const std::size_t n = 20 * K + 5;
    Store s(numbered_words(n));
    std::vector<Diagnostic> errors;
    DecodedStrings decoded;
    const std::vector<Token> whole = lex(s.text, 7, s.path, errors, decoded);
    ASSERT_EQ(whole.size(), n + 1);
    for (std::size_t i = 0; i <= n; ++i) {
        const Token& t = s.tokens[i];
        ASSERT_EQ(t.text, whole[i].text.view()) << i;
        ASSERT_EQ(t.line, whole[i].line) << i;
        ASSERT_EQ(t.column, whole[i].column) << i;
        ASSERT_EQ(t.kind, whole[i].kind) << i;
        ASSERT_EQ(t.file, 7u);
        ASSERT_LE(s.tokens.chunks_in_memory(), TokenStore::k_live_chunks) << i;
    }
    EXPECT_EQ(s.tokens[n].kind, TokenKind::EndOfFile);
    EXPECT_EQ(s.tokens[n + 1000].kind, TokenKind::EndOfFile);  // past the end
    EXPECT_EQ(s.tokens.last().line, whole.back().line);
    EXPECT_TRUE(s.delivered.empty());
}

TEST(TokenStore, GoingBackLexesAReleasedChunkAgain) {
    Store s(numbered_words(12 * K));
    for (std::size_t i = 0; i < 12 * K; i += 97) (void)s.tokens[i];
    EXPECT_EQ(s.tokens.if_present(5), nullptr);  // the first chunk was released
    const Token& again = s.tokens[K + 3];
    EXPECT_EQ(again.text, "a" + std::to_string(K + 3));
    EXPECT_EQ(again.line, (K + 3) / 10 + 1);
    EXPECT_EQ(again.column, s.tokens[K + 3].column);
    EXPECT_LE(s.tokens.chunks_in_memory(), TokenStore::k_live_chunks);
}

TEST(TokenStore, PinnedTokensStayInMemory) {
    Store s(numbered_words(30 * K));
    (void)s.tokens[K + 10];
    const std::size_t pin = s.tokens.pin(K + 10);
    for (std::size_t i = K + 10; i < 3 * K; ++i) (void)s.tokens[i];
    s.tokens.pin_end(pin, 3 * K - 1);
    for (std::size_t i = 3 * K; i < 30 * K; ++i) (void)s.tokens[i];
    ASSERT_NE(s.tokens.if_present(K + 10), nullptr);
    ASSERT_NE(s.tokens.if_present(3 * K - 1), nullptr);
    EXPECT_EQ(s.tokens.if_present(K + 10)->text, "a" + std::to_string(K + 10));
    EXPECT_EQ(s.tokens.if_present(0), nullptr);
    EXPECT_LE(s.tokens.chunks_in_memory(), TokenStore::k_live_chunks + 2);
}

TEST(TokenStore, LexicalErrorsAreDeliveredOnceWhereTheyAre) {
    // A stray byte in the fifth chunk, and a chunk that holds exactly K tokens before the end.
    std::string text = numbered_words(4 * K + 2);
    text += "\x01 " + numbered_words(2 * K - 2);
    Store s(text);
    for (std::size_t i = 0; i < 4 * K; ++i) (void)s.tokens[i];
    EXPECT_TRUE(s.delivered.empty()) << "an error delivered before its chunk was read";
    for (std::size_t i = 4 * K; i <= 6 * K; ++i) (void)s.tokens[i];
    ASSERT_EQ(s.delivered.size(), 1u);
    EXPECT_EQ(s.delivered[0].message, "unexpected character '\x01'");
    EXPECT_EQ(s.delivered[0].loc.line, (4 * K + 2) / 10 + 1);
    EXPECT_EQ(s.tokens[6 * K].kind, TokenKind::EndOfFile);
    // Read again after a release, and after the store is cleared and reset (a file included again).
    for (std::size_t i = 0; i <= 6 * K; i += 50) (void)s.tokens[i];
    s.tokens.clear();
    EXPECT_TRUE(s.tokens.cleared());
    s.reset();
    for (std::size_t i = 0; i <= 6 * K; i += 50) (void)s.tokens[i];
    EXPECT_EQ(s.delivered.size(), 1u);
}

TEST(TokenStore, GivenTokensAreKeptWhole) {
    Store s(numbered_words(3 * K));
    std::vector<Token> copy;
    for (std::size_t i = 0; i <= 3 * K; ++i) copy.push_back(s.tokens[i]);
    TokenStore given;
    given.assign(copy);
    EXPECT_EQ(given[2 * K + 1].text, "a" + std::to_string(2 * K + 1));
    EXPECT_EQ(given[3 * K + 5].kind, TokenKind::EndOfFile);
    EXPECT_EQ(given.chunks_in_memory(), 4u);
}

// Scenes longer than the live chunks: `n` spheres of 14 tokens each, the i-th of radius i + 1.
std::string spheres(int first, int n) {
    std::string s;
    for (int i = first; i < first + n; ++i) s += "sphere { <0, 0, 0>, " + std::to_string(i + 1) + " }\n";
    return s;
}

double radius(const Scene& scene, std::size_t i) {
    return std::get<Sphere>(scene.objects.at(i).shape).radius;
}

TEST(TokenStore, MacrosAndLoopsReadAgainAcrossReleasedChunks) {
    // A macro defined before and a loop whose body spans more chunks than are kept, then a call at the end.
    const int n = static_cast<int>(12 * K / 10);
    const std::string text = "#macro Last(R) sphere { 0, R } #end\n#declare I = 0;\n#while (I < 3)\n" +
                             spheres(0, n) + "#declare I = I + 1;\n#end\nLast(7)\n";
    const Scene scene = test::parse_ok(text);
    ASSERT_EQ(scene.objects.size(), 3u * n + 1);
    EXPECT_EQ(radius(scene, 0), 1);
    EXPECT_EQ(radius(scene, n - 1), n);
    EXPECT_EQ(radius(scene, 2 * n + 5), 6);
    EXPECT_EQ(radius(scene, 3 * n), 7);
}

TEST(TokenStore, ErrorsFarIntoAFileKeepTheirPlace) {
    const int n = static_cast<int>(10 * K / 10);
    // Line 1 is the test's global_settings; the spheres take one line each.
    const ParseResult r = test::parse_fail("global_settings { assumed_gamma 1 }\n" + spheres(0, n) +
                                           "sphere { 0, Undeclared_Radius }\n" + spheres(n, 10) + "  \x01\n");
    const std::string all = test::all_diagnostics(r);
    EXPECT_NE(all.find("test.pov:" + std::to_string(n + 2) + ":13: error: undeclared identifier 'Undeclared_Radius'"),
              std::string::npos)
        << all;
    EXPECT_NE(all.find("test.pov:" + std::to_string(n + 13) + ":3: error: unexpected character"), std::string::npos)
        << all;
}

}  // namespace
}  // namespace wardray::parser
