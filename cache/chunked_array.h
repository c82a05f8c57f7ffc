// ChunkedArray: an append-only array in fixed-size chunks, so that growing it never copies it or doubles its size.
#pragma once

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

namespace wardray::cache {

/// Read-only forward iteration over `Container` by index: `*it` is `container[i]` (a reference or a value, as the
/// container's const operator[] gives it).
template <typename Container>
class IndexIterator {
public:
    using reference = decltype(std::declval<const Container&>()[std::size_t{}]);
    using value_type = std::remove_cvref_t<reference>;
    using iterator_category = std::conditional_t<std::is_reference_v<reference>, std::forward_iterator_tag,
                                                 std::input_iterator_tag>;
    using difference_type = std::ptrdiff_t;
    using pointer = void;
    IndexIterator(const Container* container, std::size_t i) : m_container(container), m_i(i) {}
    reference operator*() const { return (*m_container)[m_i]; }
    IndexIterator& operator++() {
        ++m_i;
        return *this;
    }
    bool operator==(const IndexIterator& o) const { return m_i == o.m_i; }
    bool operator!=(const IndexIterator& o) const { return m_i != o.m_i; }

private:
    const Container* m_container;
    std::size_t m_i;
};

/// Elements in chunks of 2^kShift, addressed by index with one more load than a std::vector (the chunk's address);
/// unlike a std::vector, growing never holds the old and the new copy at once, and at most one chunk is unused.
/// The first chunk starts small and doubles up to the full chunk size, so that a small array stays small.
/// Addresses of elements stay valid as it grows (except those in the first chunk while it is still growing).
template <typename T, unsigned kShift = 10>
class ChunkedArray {
public:
    static constexpr std::size_t kChunk = std::size_t{1} << kShift;

    ChunkedArray() = default;
    ChunkedArray(ChunkedArray&&) noexcept = default;
    ChunkedArray& operator=(ChunkedArray&&) noexcept = default;
    ChunkedArray(const ChunkedArray& other)
        requires std::is_copy_assignable_v<T>
    {
        for (const T& v : other) push_back(v);
    }
    ChunkedArray& operator=(const ChunkedArray& other)
        requires std::is_copy_assignable_v<T>
    {
        if (this != &other) *this = ChunkedArray(other);
        return *this;
    }

    std::size_t size() const { return m_size; }
    bool empty() const { return m_size == 0; }
    /// Elements allocated for, used or not.
    std::size_t capacity() const { return m_capacity; }
    /// What the array has allocated, chunk table included.
    std::size_t memory_bytes() const {
        return m_capacity * sizeof(T) + m_chunks.capacity() * sizeof(std::unique_ptr<T[]>);
    }

    T& operator[](std::size_t i) { return m_chunks[i >> kShift][i & (kChunk - 1)]; }
    const T& operator[](std::size_t i) const { return m_chunks[i >> kShift][i & (kChunk - 1)]; }
    const T& back() const { return (*this)[m_size - 1]; }
    T& back() { return (*this)[m_size - 1]; }

    void push_back(const T& value) {
        if (m_size == m_capacity) grow();
        (*this)[m_size++] = value;
    }
    void push_back(T&& value) {
        if (m_size == m_capacity) grow();
        (*this)[m_size++] = std::move(value);
    }
    void clear() {
        m_chunks.clear();
        m_chunks.shrink_to_fit();
        m_size = m_capacity = 0;
    }

    /// Read-only iteration in index order.
    using const_iterator = IndexIterator<ChunkedArray>;
    const_iterator begin() const { return {this, 0}; }
    const_iterator end() const { return {this, m_size}; }

private:
    void grow() {
        if (m_capacity < kChunk) {
            // The first chunk doubles (from 16) until it is full size: a copy of at most one chunk.
            const std::size_t capacity = std::min(kChunk, std::max<std::size_t>(16, 2 * m_capacity));
            std::unique_ptr<T[]> bigger(new T[capacity]);
            if (!m_chunks.empty()) std::move(m_chunks[0].get(), m_chunks[0].get() + m_size, bigger.get());
            m_chunks.clear();
            m_chunks.push_back(std::move(bigger));
            m_capacity = capacity;
            return;
        }
        m_chunks.emplace_back(new T[kChunk]);
        m_capacity += kChunk;
    }

    std::vector<std::unique_ptr<T[]>> m_chunks;
    std::size_t m_size = 0;
    std::size_t m_capacity = 0;
};

}  // namespace wardray::cache
