// TokenStore: a file's tokens lexed a chunk at a time on demand; the oldest unpinned chunks are released.
#include "parser/token_store.h"

#include <algorithm>
#include <limits>

namespace wardray::parser {

void TokenStore::reset(std::string_view text, LexStart start, std::size_t end, std::uint32_t file,
                       const std::string& path, DecodedStrings& decoded, ErrorSink sink) {
    m_text = text.data();
    m_text_size = text.size();
    m_end = std::min(end, text.size());
    m_file = file;
    m_path = &path;
    m_decoded = &decoded;
    m_sink = std::move(sink);
    m_chunks.clear();
    m_starts.assign(1, start);
    m_ended = false;
    m_eof = Token{};
    m_live.clear();
    m_pins.clear();
    m_hot_count = 0;
}

void TokenStore::assign(std::vector<Token> tokens) {
    clear();
    m_eof = tokens.empty() ? Token{} : tokens.back();
    for (std::size_t i = 0; i < tokens.size(); i += k_chunk_tokens) {
        const auto from = tokens.begin() + static_cast<std::ptrdiff_t>(i);
        const auto to = tokens.begin() + static_cast<std::ptrdiff_t>(std::min(tokens.size(), i + k_chunk_tokens));
        m_chunks.emplace_back(from, to);
    }
    m_ended = true;
}

void TokenStore::clear() {
    m_text = nullptr;
    m_text_size = 0;
    std::vector<std::vector<Token>>().swap(m_chunks);
    m_starts.clear();
    m_ended = false;
    m_live.clear();
    m_pins.clear();
    m_hot_count = 0;
}

const Token* TokenStore::if_present(std::size_t pos) const {
    const std::size_t c = pos >> k_chunk_shift;
    const std::size_t i = pos & (k_chunk_tokens - 1);
    if (c < m_chunks.size() && i < m_chunks[c].size()) return &m_chunks[c][i];
    if (m_ended && !m_chunks.empty() && (c >= m_chunks.size() || !m_chunks[c].empty() || c + 1 == m_chunks.size()))
        return &m_eof;
    return nullptr;
}

const Token& TokenStore::last() const {
    while (m_text != nullptr && !m_ended) lex_chunk(m_chunks.size());
    return m_eof;
}

const Token& TokenStore::slow_at(std::size_t pos) const {
    const std::size_t c = pos >> k_chunk_shift;
    if (m_text != nullptr) {
        // Lex forward to the chunk (or lex a released one again).
        while (!m_ended && m_chunks.size() < c) lex_chunk(m_chunks.size());
        if (c < m_chunks.size() ? m_chunks[c].empty() : !m_ended) lex_chunk(c);
    }
    const std::size_t i = pos & (k_chunk_tokens - 1);
    if (c >= m_chunks.size() || i >= m_chunks[c].size()) return m_eof;  // past the end, or cleared
    m_hot_first = c << k_chunk_shift;
    m_hot = m_chunks[c].data();
    m_hot_count = m_chunks[c].size();
    return m_hot[i];
}

void TokenStore::lex_chunk(std::size_t c) const {
    std::vector<Token> tokens;
    tokens.reserve(k_chunk_tokens);
    std::vector<Diagnostic> diagnostics;
    LexStart stop;
    const bool ended = lex_some(std::string_view(m_text, m_text_size), m_starts[c], m_end, k_chunk_tokens, m_file,
                                *m_path, diagnostics, *m_decoded, tokens, stop);
    if (c == m_chunks.size()) m_chunks.emplace_back();
    m_chunks[c] = std::move(tokens);
    if (ended) {
        m_ended = true;
        m_eof = m_chunks[c].back();
    } else if (c + 1 == m_starts.size()) {
        m_starts.push_back(stop);
    }
    if (!pinned(c)) m_live.push_back(c);
    // Of the live chunks, release the oldest beyond k_live_chunks, never this one, the one before it or the one
    // read last (where the reader is when a look-ahead needs this chunk).
    const std::size_t hot = m_hot_count > 0 ? m_hot_first >> k_chunk_shift : c;
    for (std::size_t k = 0; m_live.size() > k_live_chunks && k < m_live.size();) {
        const std::size_t old = m_live[k];
        if (old == c || old + 1 == c || old == hot) {
            ++k;
            continue;
        }
        if (!pinned(old)) std::vector<Token>().swap(m_chunks[old]);
        m_live.erase(m_live.begin() + static_cast<std::ptrdiff_t>(k));
    }
    // Diagnostics are delivered once, the first time their text is lexed, when the store is consistent (the sink
    // may end the parse).
    const std::size_t to = ended ? m_end : stop.offset;
    if (m_starts[c].offset >= m_reported_to && to > m_reported_to) {
        m_reported_to = to;
        if (m_sink && !diagnostics.empty()) m_sink(diagnostics);
    }
}

std::size_t TokenStore::chunks_in_memory() const {
    return static_cast<std::size_t>(
        std::count_if(m_chunks.begin(), m_chunks.end(), [](const std::vector<Token>& c) { return !c.empty(); }));
}

bool TokenStore::pinned(std::size_t c) const {
    const std::size_t first = c << k_chunk_shift;
    const std::size_t last = first + k_chunk_tokens - 1;
    return std::any_of(m_pins.begin(), m_pins.end(),
                       [&](const auto& pin) { return pin.first <= last && pin.second >= first; });
}

std::size_t TokenStore::pin(std::size_t begin) {
    m_pins.emplace_back(begin, std::numeric_limits<std::size_t>::max());
    return m_pins.size() - 1;
}

void TokenStore::pin_end(std::size_t index, std::size_t end) {
    if (index < m_pins.size()) m_pins[index].second = end;
}

}  // namespace wardray::parser
