// KeywordTable: a static table from keyword to handler, which the readers dispatch through.
#pragma once

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <string_view>
#include <utility>
#include <vector>

namespace wardray::parser {

/// Keyword -> handler, built once (a function-local static). find() hashes the word inline (FNV-1a) into an
/// open-addressed table of a power-of-two size, so a lookup costs about what two or three string comparisons of
/// the if-chain it replaces did.
template <typename Handler>
class KeywordTable {
public:
    /// A table of the given keywords and their handlers (each keyword once).
    KeywordTable(std::initializer_list<std::pair<std::string_view, Handler>> entries) {
        std::size_t size = 8;
        while (size < 2 * entries.size()) size *= 2;
        m_slots.resize(size);
        m_mask = size - 1;
        for (const auto& [word, handler] : entries) {
            std::size_t i = hash(word) & m_mask;
            while (m_slots[i].used) i = (i + 1) & m_mask;
            m_slots[i] = Slot{word, handler, true};
        }
    }

    /// The handler of `word`, or nullptr when `word` is no keyword of this table.
    const Handler* find(std::string_view word) const {
        for (std::size_t i = hash(word) & m_mask;; i = (i + 1) & m_mask) {
            const Slot& slot = m_slots[i];
            if (!slot.used) return nullptr;
            if (slot.word == word) return &slot.handler;
        }
    }

private:
    struct Slot {
        std::string_view word;
        Handler handler{};
        bool used = false;
    };
    static std::size_t hash(std::string_view word) {
        std::uint64_t h = 14695981039346656037ull;
        for (const char c : word) h = (h ^ static_cast<unsigned char>(c)) * 1099511628211ull;
        return static_cast<std::size_t>(h ^ (h >> 32));
    }
    std::vector<Slot> m_slots;
    std::size_t m_mask = 0;
};

}  // namespace wardray::parser
