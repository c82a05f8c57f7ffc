// KeywordTable: a static table from keyword to handler, which the readers dispatch through.
#pragma once

#include <initializer_list>
#include <string_view>
#include <unordered_map>
#include <utility>

namespace wardray::parser {

/// Keyword -> handler, built once (a function-local static); find() costs one hash of the word.
template <typename Handler>
class KeywordTable {
public:
    /// A table of the given keywords and their handlers.
    KeywordTable(std::initializer_list<std::pair<const std::string_view, Handler>> entries) : m_entries(entries) {}

    /// The handler of `word`, or nullptr when `word` is no keyword of this table.
    const Handler* find(std::string_view word) const {
        const auto found = m_entries.find(word);
        return found == m_entries.end() ? nullptr : &found->second;
    }

private:
    std::unordered_map<std::string_view, Handler> m_entries;
};

}  // namespace wardray::parser
