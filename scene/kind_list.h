// Kind lists: the helpers that turn scene/'s X-macro lists (shapes, patterns, lights, cameras) into types and tables.
#pragma once

#include <cstddef>
#include <optional>
#include <string_view>
#include <type_traits>
#include <variant>

namespace wardray::scene {

/// A compile-time list of types.
template <typename... Ts>
struct TypeList {};

namespace detail {

template <typename List, typename... Ts>
struct Unique {
    using type = List;
};
template <typename... Seen, typename T, typename... Ts>
struct Unique<TypeList<Seen...>, T, Ts...>
    : Unique<std::conditional_t<(std::is_same_v<T, Seen> || ...), TypeList<Seen...>, TypeList<Seen..., T>>, Ts...> {};

template <typename List>
struct AsVariant;
template <typename... Ts>
struct AsVariant<TypeList<Ts...>> {
    using type = std::variant<Ts...>;
};

}  // namespace detail

/// std::variant of the distinct types among Ts..., in the order they first appear (a list may name a type twice).
template <typename... Ts>
using UniqueVariant = typename detail::AsVariant<typename detail::Unique<TypeList<>, Ts...>::type>::type;

/// One entry of a kind's keyword table: the keyword and the enumerator it names.
template <typename E>
struct KindKeyword {
    std::string_view keyword;
    E value;
};

/// The enumerator `word` names in `table`, or nothing when it names none.
template <typename E, std::size_t N>
constexpr std::optional<E> find_kind(const KindKeyword<E> (&table)[N], std::string_view word) {
    for (const KindKeyword<E>& k : table)
        if (k.keyword == word) return k.value;
    return std::nullopt;
}

/// The keyword of `value` in `table` (empty when the table has none for it).
template <typename E, std::size_t N>
constexpr std::string_view kind_keyword(const KindKeyword<E> (&table)[N], E value) {
    for (const KindKeyword<E>& k : table)
        if (k.value == value) return k.keyword;
    return {};
}

}  // namespace wardray::scene
