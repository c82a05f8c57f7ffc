// TokenStore: one file's tokens, lexed a chunk at a time as the parse reaches them, with old chunks released.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "parser/lexer.h"

namespace wardray::parser {

/// The tokens of a file (or of a stretch of one), numbered from 0, as the parse reads them. They are lexed a chunk
/// of k_chunk_tokens at a time when first asked for, so a scene file of megabytes of mesh data never holds all its
/// tokens at once (32 bytes each, about seven times its text): of the chunks read, only the last k_live_chunks
/// are kept, besides those holding macro bodies (pinned). A loop or a rewind that goes back to a released chunk
/// has it lexed again from where it began. A reference to a token stays valid while the tokens read after it fill
/// fewer than k_live_chunks - 1 chunks.
class TokenStore {
public:
    /// Tokens in a chunk: a power of two, so a position splits into chunk and index by shifts.
    static constexpr std::size_t k_chunk_shift = 12;
    static constexpr std::size_t k_chunk_tokens = std::size_t{1} << k_chunk_shift;
    /// Chunks kept besides the pinned ones: a loop body of up to about this many chunks is lexed once.
    static constexpr std::size_t k_live_chunks = 8;

    /// Receives the lexical errors and warnings of text lexed for the first time.
    using ErrorSink = std::function<void(std::vector<Diagnostic>&)>;

    /// Reads `text` (which must outlive the store, as must `path` and `decoded`) from `start` up to byte `end`;
    /// tokens carry `file`. Lexical diagnostics go to `sink` the first time their stretch of text is lexed
    /// (never after a reset, never when `sink` is empty). Pins are dropped.
    void reset(std::string_view text, LexStart start, std::size_t end, std::uint32_t file, const std::string& path,
               DecodedStrings& decoded, ErrorSink sink);
    /// Tokens given whole (a copy of macro bodies): never released, never lexed.
    void assign(std::vector<Token> tokens);
    /// Releases every token; reading again needs a reset.
    void clear();
    /// True before a reset or assign, and after clear.
    bool cleared() const { return m_text == nullptr && m_chunks.empty(); }

    /// The token at `pos`; past the end, the EndOfFile token. Lexes (or lexes again) its chunk when needed.
    const Token& operator[](std::size_t pos) const {
        // The parse reads on within one chunk far more often than it moves to another: that chunk is at hand.
        const std::size_t i = pos - m_hot_first;
        if (i < m_hot_count) return m_hot[i];
        return slow_at(pos);
    }
    /// The token at `pos` when its chunk is in memory, without lexing anything; null otherwise.
    const Token* if_present(std::size_t pos) const;
    /// The last token, the EndOfFile (lexing the rest of the text when needed).
    const Token& last() const;

    /// Keeps the chunks holding positions `begin` and after in memory (a macro body, its end not known yet);
    /// returns the pin, to be narrowed by pin_end.
    std::size_t pin(std::size_t begin);
    /// Narrows pin `index` to end at position `end` (inclusive).
    void pin_end(std::size_t index, std::size_t end);

    /// Chunks whose tokens are in memory (what the store costs, for tests).
    std::size_t chunks_in_memory() const;

private:
    const Token& slow_at(std::size_t pos) const;
    /// Lexes chunk `c` (the next new one, or a released one again), then releases the oldest beyond the live ones.
    void lex_chunk(std::size_t c) const;
    /// True when a pin keeps chunk `c`.
    bool pinned(std::size_t c) const;

    const char* m_text = nullptr;
    std::size_t m_text_size = 0;
    std::size_t m_end = 0;
    std::uint32_t m_file = 0;
    const std::string* m_path = nullptr;
    DecodedStrings* m_decoded = nullptr;
    ErrorSink m_sink;
    /// Text lexed so far in any reading of this store: diagnostics before it were delivered already.
    mutable std::size_t m_reported_to = 0;

    mutable std::vector<std::vector<Token>> m_chunks;  ///< empty when released (or not lexed yet)
    mutable std::vector<LexStart> m_starts;            ///< where chunk c begins; one more once the next is known
    mutable bool m_ended = false;                      ///< the chunk with the EndOfFile is known
    mutable Token m_eof;                               ///< a copy of the EndOfFile, once known
    mutable std::vector<std::size_t> m_live;           ///< unpinned chunks in memory, in the order they were lexed
    /// The chunk read last (never released while it is): its first position, tokens and count.
    mutable std::size_t m_hot_first = 0;
    mutable const Token* m_hot = nullptr;
    mutable std::size_t m_hot_count = 0;
    std::vector<std::pair<std::size_t, std::size_t>> m_pins;  ///< position ranges kept in memory, inclusive
};

}  // namespace wardray::parser
